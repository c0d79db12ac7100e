#pragma once
/*!
  \file ModelOutputs.h
  What pm-make-model writes for a flat or stereo photo-model: model.json, overlay.png (the region
  outline, S_in and S_out on the photo), model.png (the model alone), depth.png (a stereo model's
  relief), the photos it was made from, and summary.json; all or nothing (io::StagedFiles).
*/
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/PhotoModel.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PhotoModelBuilder.h"

namespace pm::report {

//! A flat or stereo model and what it was made from.
struct ModelOutputs
{
  std::string source;                 //!< where the photos came from (summary.json's "source")
  model::PhotoModelBuild build;              //!< the model and its region in the photo
  vpImage<vpRGBa> photo;              //!< the photo of the target (the overlays are drawn on it)
  vpImage<vpRGBa> background;         //!< the photo of the background alone
  bool writePhotos = true;            //!< also write them (photo_target.png, photo_background.png)
  vpImage<float> depth;               //!< a stereo model's depth per photo pixel (mm; empty for a flat model)
  std::vector<core::ModelPoint> dropped;    //!< a stereo model's S_in points without a reliable match
  double backdropMm = 0;              //!< a stereo model's backdrop distance (mm)
  double stepPx = 0;                  //!< the sampling step the model was made with (px)
};

//! The figures pm-make-model prints.
struct ModelFigures
{
  unsigned regionAreaPx = 0; //!< pixels of the target's region
};

/*!
  Writes \e m's files into \e dir (created if missing); \e seconds: the time the build took (s),
  for summary.json. Throws pm::core::Error; on an error nothing is left in \e dir.

  \code
    pm::report::ModelOutputs m;
    m.source = "photos bg.png + toy.png";
    m.build = pm::model::buildPhotoModel(bg, toy, cam, 500);
    m.photo = toy;
    m.background = bg;
    pm::report::writeModelOutputs("model", m, 0.5);
  \endcode
*/
ModelFigures writeModelOutputs(const std::string &dir, const ModelOutputs &m, double seconds);

//! What pm-make-model prints of a flat or stereo model written to \e dir in \e seconds (s).
std::string describeModel(const ModelOutputs &m, const ModelFigures &figures, const std::string &dir, double seconds);
//! What pm-make-model prints of an all-around model made from \e source, written to \e dir (with its views/ when \e withViews).
std::string describeAllAroundModel(const model::AllAroundBuild &b, const std::string &source, const std::string &dir, bool withViews);

} // namespace pm::report
