#pragma once
// The crab C12's flat model in the lab rig, rendered once at a known pose: the tracker's tests share it.
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/Pose.h"
#include "pm/core/StereoRig.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"

namespace pm::test {

//! C12 (relief halved) 520 mm ahead, slightly tilted and turned; its model made from photos at 500 mm.
struct C12Scene
{
  core::StereoRig rig;
  sim::Scene scene;
  sim::SimulatedPhotoModel sm;
  vpHomogeneousMatrix hMo;
  sim::StereoImages im;
  core::Phi truth; //!< the model's pose at hMo (its frame is not the toy's)
  C12Scene();
};

//! The scene, made on first use.
const C12Scene &c12();

} // namespace pm::test
