#pragma once
/*!
  \file HullGeometry.h
  The geometry the all-around model's stages share (AllAroundModelBuilder.h): one camera of one pass
  view as the hull sees it (its camera placed in the pass's world, core::PinholeCamera::Projection,
  its ideal photo and its silhouette's signed distance), the signed distance of a silhouette, and the
  hull's cells. The 3-vectors in millimetres are core's (core::Vec3).

  \code
      pm::model::hull::HullView v;
      v.cam = pm::core::PinholeCamera::Projection(wMc, rig.left.cam, 640, 480); // wMc in metres
      v.signedDist = pm::model::hull::signedDistance(mask);
      double u, z, w;
      if (v.cam.project({0, 0, 500}, u, w, z) && v.sd(u, w) > 0) std::cout << "inside the silhouette\n";
  \endcode
*/
#include <array>
#include <cmath>

#include <opencv2/core.hpp>
#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/PinholeCamera.h"
#include "pm/core/Rounding.h"

namespace pm::model::hull {

// The 3-vectors (mm) and the camera's projection are core's.
using core::add;
using core::add;
using core::cross;
using core::dot;
using core::scaled;
using core::sub;
using core::unit;
using core::Vec3;

/*!
  One camera of one pass view as the hull sees it: where it was, its ideal photo, and its
  silhouette's signed distance (px; positive inside, the outline midway between the last pixel in and
  the first out).
*/
struct HullView
{
  core::PinholeCamera::Projection cam; //!< in the world frame of the pass
  vpImage<vpRGBa> photo;  //!< the ideal (undistorted) photo
  cv::Mat signedDist;     //!< CV_32F, the silhouette's signed distance (px)
  int view = 0;           //!< the pass view it belongs to
  //! The signed distance at the pixel nearest (\e u, \e v); -1e6 off the image.
  double sd(double u, double v) const
  {
    const int ui = static_cast<int>(core::roundHalfAway(u)), vi = static_cast<int>(core::roundHalfAway(v));
    if (ui < 0 || vi < 0 || ui >= cam.w || vi >= cam.h)
      return -1e6;
    return signedDist.at<float>(vi, ui);
  }
  //! The signed distance interpolated bilinearly at (\e u, \e v); off the image, the border's minus the distance to it.
  double sdSmooth(double u, double v) const;
};

//! The signed distance (CV_32F, px, positive inside) of a binary \e mask (255 inside).
cv::Mat signedDistance(const vpImage<unsigned char> &mask);

} // namespace pm::model::hull
