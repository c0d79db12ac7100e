#pragma once
/*!
  \file SimulatedPhotoModel.h
  The photo-model of a simulated target, made as a user would make it: the scene's two photos
  (Fig. 4 (a), (b)) taken by one camera at a known distance, then buildPhotoModel().
  Also gives where the model frame sits in the toy's frame, for ground truth.

  The stereo model is made as a user of a rig would make it: the rig on the hand, the toy
  \e distanceMm ahead (its base, facing the hand), the backdrop pair then the photo pair, then
  buildStereoPhotoModel(). No distance is given to the builder: it measures it.

  \code
      const auto sm = pm::sim::makeSimulatedStereoPhotoModel(scene, rig);
      const pm::core::Phi truth = sm.truth(hMo);   // the model's true pose for a toy at hMo
  \endcode
*/
#include "pm/model/PhotoModelBuilder.h"
#include "pm/model/StereoPhotoModelBuilder.h"
#include "pm/core/Pose.h"
#include "pm/sim/Scene.h"

namespace pm::sim {

/*!
  A photo-model made from simulated photos, with the ground truth to judge it by (see
  SimulatedPhotoModel.h): made by makeSimulatedPhotoModel() or makeSimulatedStereoPhotoModel().
*/
struct SimulatedPhotoModel
{
  model::PhotoModelBuild build;             //!< the model and its region in the (left) photo
  //! The background photo, the backdrop alone (the left one for a stereo model).
  vpImage<vpRGBa> background, photo; //!< the photo with the toy (the left one for a stereo model)
  vpHomogeneousMatrix oMm;           //!< the model frame in the toy's frame (metres)
  // Stereo models only:
  bool stereo = false;               //!< true for a stereo model (the members below are filled)
  //! The right camera's background photo (stereo models).
  vpImage<vpRGBa> backgroundRight, photoRight; //!< the right camera's photo with the toy (stereo models)
  vpImage<float> depth;              //!< hand-frame z (mm) of the matched left region pixels, NaN elsewhere
  double backdropMm = 0;             //!< the backdrop's depth the builder measured (left camera, mm)
  int nOutFallback = 0;              //!< S_out points with no matched region pixel near them (the builder's count)
  std::vector<core::ModelPoint> dropped;   //!< S_in points without a reliable match
  vpHomogeneousMatrix photoHMo;      //!< the toy's pose in the hand frame when the photos were taken
  vpImage<float> trueDepth;          //!< ground truth: hand-frame z (mm) of the toy at each left photo pixel, NaN off it

  /*!
    Stereo models: for each S_in point, its hand-frame z in the model (at the photo pose) minus the
    toy's true z at its photo pixel (mm; NaN where the pixel is on the toy's edge). The accuracy
    of the matching.
  */
  std::vector<double> inDepthErrorsMm() const;

  /*!
    The model's true pose in the hand frame for a toy at \e hMo: hMm = hMo * oMm. The model
    frame's origin is the region's centroid in the photo, which sits off the toy's origin by
    ((cu - u0) d / px, (cv - v0) d / py, 0).
  */
  core::Phi truth(const vpHomogeneousMatrix &hMo) const { return core::fromHomogeneousMatrix(hMo * oMm); }
};

//! Photos by camera \e cam (w x h pixels) at \e distanceMm, then the model (the scene's look-alike left out). Throws pm::core::Error.
SimulatedPhotoModel makeSimulatedPhotoModel(const Scene &scene, const vpCameraParameters &cam, unsigned w, unsigned h,
                                            double distanceMm, const model::PhotoModelParams &params = model::PhotoModelParams());

/*!
  The stereo model of the toy at hMo = (0, 0, \e distanceMm) in the hand frame (facing the rig),
  from the rig's backdrop pair and photo pair. With \e viewTurnDeg > 0, four further pairs are taken
  with the hand moved around the scene by +-viewTurnDeg about its x and y axes (the toy's origin
  staying in place) and the model holds their views too (a multi-view model). The scene's
  look-alike is left out. Throws pm::core::Error unless \e distanceMm > 0 and \e viewTurnDeg is in
  [0, 45], and as buildStereoPhotoModel().
*/
SimulatedPhotoModel makeSimulatedStereoPhotoModel(const Scene &scene, const core::StereoRig &rig, double distanceMm = 500,
                                                  const model::StereoModelParams &params = model::StereoModelParams(),
                                                  double viewTurnDeg = 0);

} // namespace pm::sim
