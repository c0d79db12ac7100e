#pragma once
/*!
  \file StillPair.h
  One still frame to find a target in (pm-detect's Table 1, pm-fitness-map's maps), a stereo pair
  or one image per camera of any rig: a user's image files with a model file, or the simulator's
  images of a lab target at a pose, with its model (LabModel.h) and the model's true pose.

  \code
    const pm::lab::StillPair user = pm::lab::loadStillPair({"L.png", "R.png"}, "model.json");
    const pm::lab::StillPair lab = pm::lab::renderStillPair(pm::sim::makeTarget("C12"), {0, 0, 500, 0, 0, 0}, rig,
                                                            pm::sim::SceneParams(), pm::lab::LabModelChoice());
    std::cout << lab.source << ": the model at " << lab.truth.toString() << "\n";
  \endcode
*/
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/CameraImages.h"
#include "pm/core/CameraRig.h"
#include "pm/core/PhotoModel.h"
#include "pm/core/Pose.h"
#include "pm/core/StereoRig.h"
#include "pm/lab/LabModel.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetShape.h"

namespace pm::lab {

//! A still pair, its model and, where known, the model's true pose in the hand frame (see StillPair.h).
struct StillPair
{
  core::PhotoModel model;               //!< the photo-model to find
  std::vector<vpImage<vpRGBa>> images;  //!< one per camera, in the rig's order (a pair: left, right)
  bool haveTruth = false;               //!< the truth is known (always in the simulator)
  core::Phi truth;                      //!< the model's true pose (mm, quaternion vector)
  std::string source;                   //!< what the frame is, for the outputs
  //! The images as the tracker takes them (pointers into this frame).
  core::CameraImages view() const { return core::CameraImages::of(images); }
};

//! A user's images (one per camera) and model, read from files (no truth: the caller's, if it has one). Throws core::Error naming the file.
StillPair loadStillPair(const std::vector<std::string> &images, const std::string &modelPath);
//! Throws core::Error when the images (named by \e files) differ in size from the first.
void requireSameSize(const StillPair &pair, const std::vector<std::string> &files);
//! The simulator's images of \e shape at \e phi (the toy's pose in the hand frame) through every camera of \e rig, with the lab's model of it (\e choice) and its truth.
StillPair renderStillPair(const sim::TargetShape &shape, const core::Phi &phi, const core::CameraRig &rig, const sim::SceneParams &sp,
                          const LabModelChoice &choice);

} // namespace pm::lab
