#pragma once
/*!
  \file FitnessMapOutputs.h
  The fitness-distribution experiment's outputs (the paper's Sec. 5, Figs. 10, 11; pm-fitness-map):
  the stereo fitness on 2-D grids around a pose, each written as map_<grid>.csv and a heat map
  map_<grid>.png with the truth and the peak marked, the model drawn at the truth on both images
  (truth_overlay.png) and summary.json; all or nothing (io::StagedFiles).
*/
#include <functional>
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/CameraImages.h"
#include "pm/core/FitnessMap.h"
#include "pm/core/StereoFitness.h"

namespace pm::report {

//! One grid's result.
struct GridResult
{
  std::string name;        //!< the grid's variables, e.g. "xy", "e1e2"
  double peakA = 0;        //!< the peak's first variable (mm, or unitless for an eps)
  double peakB = 0;        //!< its second
  double errorA = 0;       //!< peak minus truth, first variable
  double errorB = 0;       //!< peak minus truth, second variable
  double reprojectionPx = 0; //!< rms image distance of the model's points at the peak and at the truth (px)
  double maxFitness = 0;   //!< F at the peak
  double seconds = 0;      //!< the grid's computing time (s)
};

//! The experiment's results.
struct FitnessMapsResult
{
  std::vector<GridResult> grids; //!< in the order of the specs
  double fitnessAtTruth = 0;     //!< F at the truth
  std::size_t modelPoints = 0;   //!< the model's points (S_in and S_out)
  double seconds = 0;            //!< all grids' computing time (s)
  std::string summaryJson;       //!< summary.json as written
  std::string text;              //!< one line per grid, as pm-fitness-map prints it
  //! The grid named \e name (throws pm::core::Error if there is none).
  const GridResult &grid(const std::string &name) const;
};

/*!
  Computes \e specs' maps of \e fitness (its images set: \e images, one per camera of its rig)
  around \e truth (the variables off a grid held at the truth) and writes them into \e dir; \e
  source names the images in summary.json, \e onMap is called after each grid. Throws
  pm::core::Error; on an error nothing is left in \e dir.

  \code
    pm::core::StereoFitness fit(rig, model);
    const pm::core::CameraImages images(left, right); // a pair; CameraImages(image) for one camera
    fit.setImages(images.data());
    const pm::report::FitnessMapsResult r =
        pm::report::writeFitnessMaps("maps", fit, model.size(), truth, pm::core::paperFitnessMaps(), "my pair", images);
    std::cout << r.text;
  \endcode
*/
FitnessMapsResult writeFitnessMaps(const std::string &dir, const core::StereoFitness &fitness, std::size_t modelPoints, const core::Phi &truth,
                                   const std::vector<core::FitnessMapSpec> &specs, const std::string &source,
                                   const core::CameraImages &images, const std::function<void()> &onMap = {});

} // namespace pm::report
