#pragma once
//! pm-bench's shared set-up: the C12 crab at the true pose, its photo-models and its stereo pair, made once.
#include <cstddef>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/PhotoModel.h"
#include "pm/core/Pose.h"
#include "pm/core/StereoRig.h"
#include "pm/sim/Scene.h"

namespace pm::bench {

//! The C12 crab at the true pose, its photo-model and the stereo pair, made once.
struct Setup
{
  pm::core::StereoRig rig;
  pm::core::PhotoModel model, model1000, model1000Depth;
  pm::sim::StereoImages images;
  pm::core::Phi truth;        //!< the model's pose (what the tracker estimates) ...
  vpHomogeneousMatrix hMo; //!< ... of the toy at this pose

  Setup(); //!< builds everything (throws pm::core::Error)
};

//! The set-up, made on first use (pm-bench's main calls it before timing).
const Setup &setup();
//! Poses around the truth, as a GA population sees them.
std::vector<pm::core::Phi> poses(std::size_t n);

} // namespace pm::bench
