#pragma once
/*!
  \file SurfaceDrawing.h
  The all-around model's surface drawn as a camera sees it, for pictures (pm-make-model's contact
  sheet and silhouettes, AllAroundOutputs.h).

  \code
      const vpImage<vpRGBa> seen = pm::report::drawSurface(build.surface, mMc, rig.left.cam, 640, 480);
  \endcode
*/
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/model/AllAroundModelBuilder.h"

namespace pm::report {

/*!
  The hull's surface drawn by a camera at \e mMc (its pose in the model frame, metres) with
  intrinsics \e cam, \e w x \e h: each surface point in its colour (nearest first), the rest black.
  \e mask (when given) gets 255 where the hull covers the image. For pictures.
*/
vpImage<vpRGBa> drawSurface(const std::vector<model::SurfacePoint> &surface, const vpHomogeneousMatrix &mMc,
                            const vpCameraParameters &cam, unsigned w, unsigned h, vpImage<unsigned char> *mask = nullptr);

} // namespace pm::report
