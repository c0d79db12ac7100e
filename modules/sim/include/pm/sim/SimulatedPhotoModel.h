#pragma once
/*!
  \file SimulatedPhotoModel.h
  The photo-model of a simulated target, made as a user would make it: the scene's two photos
  (Fig. 4 (a), (b)) taken by one camera at a known distance, then buildPhotoModel().
  Also gives where the model frame sits in the toy's frame, for ground truth.
*/
#include "pm/core/PhotoModelBuilder.h"
#include "pm/core/Pose.h"
#include "pm/sim/Scene.h"

namespace pm::sim {

struct SimulatedPhotoModel
{
  PhotoModelBuild build;
  vpImage<vpRGBa> background, photo; //!< the two photos
  vpHomogeneousMatrix oMm;           //!< the model frame in the toy's frame (metres)

  /*!
    The model's true pose in the hand frame for a toy at \e hMo: hMm = hMo * oMm. The model
    frame's origin is the region's centroid in the photo, which sits off the toy's origin by
    ((cu - u0) d / px, (cv - v0) d / py, 0).
  */
  Phi truth(const vpHomogeneousMatrix &hMo) const { return fromHomogeneousMatrix(hMo * oMm); }
};

//! Photos by camera \e cam (w x h) at \e distanceMm, then the model. Throws pm::Error.
SimulatedPhotoModel makeSimulatedPhotoModel(const Scene &scene, const vpCameraParameters &cam, unsigned w, unsigned h,
                                            double distanceMm, const PhotoModelParams &params = PhotoModelParams());

} // namespace pm::sim
