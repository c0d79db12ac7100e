#pragma once
/*!
  \file SurfaceTruth.h
  The lab's check of an all-around model against the toy it was made of (the renderer's ground
  truth): where its surface lies, and where its outlines fall, as the precise stage reads them.
  - The surface: cameras at the pass's distance looking at the model from the rest direction and
    turned by 20 and 40 deg about the model's x axis; in each, the model's depth (its mesh,
    HullMesh::depthMap) against the toy's (the rasterizer's) over the pixels both cover: the median
    and 90th percentile of the absolute difference (mm), and the pixels only the model covers.
  - The outlines: every \e stride-th viewpoint's contour points, projected from that viewpoint, against
    the toy's outline there (where the rasterizer's coverage crosses one half along the point's normal,
    within 8 px): the mean (signed: positive outside the toy) and rms distance (px), by the viewpoint's
    angle from the rest direction (0-15, 15-30, 30-45, 45-75 deg), and the share of points farther than 8 px.

  \code
      const pm::lab::SurfaceTruth t = pm::lab::checkSurface(scene, build, oMm, rig.left.cam, 10);
      std::cout << "depth error median " << t.views[0].medianMm << " mm\n";
  \endcode
*/
#include <array>
#include <string>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/model/AllAroundModelBuilder.h"
#include "pm/sim/Scene.h"

namespace pm::lab {

//! One camera's depth comparison (see SurfaceTruth.h).
struct DepthCheck
{
  double turnDeg = 0;      //!< the camera's turn from the rest direction (deg)
  double medianMm = 0;     //!< median |model - toy| depth over the pixels both cover (mm)
  double p90Mm = 0;        //!< its 90th percentile (mm)
  long modelOnlyPx = 0;    //!< pixels the model covers and the toy does not
  long pixels = 0;         //!< pixels both cover
};

//! The outlines of the viewpoints within one band of angles from the rest direction (see SurfaceTruth.h).
struct OutlineCheck
{
  double fromDeg = 0;      //!< the band's start (deg)
  double toDeg = 0;        //!< its end (deg)
  double meanPx = 0;       //!< mean signed distance from the toy's outline (px; positive: the model outside)
  double rmsPx = 0;        //!< its rms (px)
  double farShare = 0;     //!< share of the points farther than 8 px (or without the toy's outline near)
  long points = 0;         //!< points measured
};

//! What checkSurface() found.
struct SurfaceTruth
{
  std::array<DepthCheck, 3> views{};     //!< at 0, 20 and 40 deg
  std::array<OutlineCheck, 4> outlines{}; //!< 0-15, 15-30, 30-45, 45-75 deg
  double volumeCm3 = 0;                  //!< the model's surface volume (AllAroundBuild::surfaceVolumeCm3)
  std::string text;                      //!< a few lines for the terminal
};

/*!
  Checks \e build (an all-around model of \e scene's toy; \e oMm its model frame in the toy's frame,
  metres) against the toy, seen through \e cam at 640 x 480 (see SurfaceTruth.h); the outlines of every
  \e stride-th viewpoint. Throws pm::core::Error when the build has no mesh.
*/
SurfaceTruth checkSurface(const sim::Scene &scene, const model::AllAroundBuild &build, const vpHomogeneousMatrix &oMm, const vpCameraParameters &cam,
                          int stride = 6);

//! \e t as JSON (an object: "depth" per camera turn, "outlines" per band, "surface_volume_cm3").
std::string surfaceTruthJson(const SurfaceTruth &t);

} // namespace pm::lab
