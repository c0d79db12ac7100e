#pragma once
/*!
  \file PassRig.h
  The pair a pass takes at each view, for a rig of any number of cameras. The all-around builder
  measures depth from two images of each view (its stereo stages); the tracker then runs on the
  rig itself.
  - A stereo rig: its two cameras, as they are.
  - One camera: the camera, then the same camera after a side step of the hand: moved as the
    lab's stereo rig's right camera sits beside its left one (kSideStepM to its right, the two
    turned toward each other to meet kSideStepMeetM ahead). The arm takes the second image from
    there; the builder sees a stereo rig whose right camera is where the camera stood the second
    time.
  - Three or more: the first two cameras (the others are the tracker's alone).
  The side step is a rigid motion the arm makes at every view; its pose comes from the arm's
  kinematics as every pass view's does.

  \code
  const pm::core::CameraRig mono = pm::io::loadCameraRig("data/rig/pa10_mono.json");
  const pm::core::StereoRig pair = pm::model::passRig(mono);  // the camera and its side step
  const vpHomogeneousMatrix step = pm::model::sideStep(mono); // the hand's motion to the second image
  std::cout << pair.right.hMc.getTranslationVector().t() << "\n" << step << "\n";
  \endcode
*/
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/CameraImages.h"
#include "pm/core/CameraRig.h"
#include "pm/core/StereoRig.h"
#include "pm/model/PassView.h"

namespace pm::model {

//! The side step of a one-camera pass (m): the lab's stereo baseline ...
constexpr double kSideStepM = 0.323;
//! ... and the distance ahead at which the camera's two places look at one point (m), the lab's rig's.
constexpr double kSideStepMeetM = 0.5;

/*!
  The stereo rig a pass of \e rig is taken with (see PassRig.h). Throws pm::core::Error for an
  invalid rig.
*/
core::StereoRig passRig(const core::CameraRig &rig);

/*!
  For a one-camera \e rig: the hand frame after the side step in the hand frame before it
  (h1Mh2): the hand at fMh takes the second image from fMh * sideStep(). The identity for a rig of
  two cameras or more (no step: the second camera is there).
*/
vpHomogeneousMatrix sideStep(const core::CameraRig &rig);

/*!
  What a tracker on a rig of \e cameras sees of pass view \e v: one image per camera. One camera:
  the view's first image; two: both. Throws pm::core::Error for more cameras than the view holds
  (a pass keeps two images a view).
*/
core::CameraImages viewImages(const PassView &v, std::size_t cameras);

} // namespace pm::model
