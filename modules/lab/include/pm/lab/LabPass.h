#pragma once
/*!
  \file LabPass.h
  The lab's pass around the target: the simulated PA-10 carries the rig through the poses of a
  PassPlan (each reached by inverse kinematics from the last, within the joint limits), and at
  each the rig takes a pair with the toy in place and one with it removed; the hand's pose is the
  robot's forward kinematics at the joints it reached (the base frame is the world frame f). The
  views are what a user's rig writes into a views folder (pm::io::saveViewsFolder), so the lab and
  a user's files go through one builder.

      const pm::lab::LabPass pass = pm::lab::runLabPass(scene, rig, pm::PassPlan(), pm::lab::LoopParams::startJoints());
      const pm::AllAroundBuild b = pm::buildAllAroundModel(rig, pass.views);
      const vpHomogeneousMatrix oMm = pass.fMo.inverse() * b.fMm;   // ground truth of the model frame
*/
#include <vector>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/StereoRig.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PassPlanner.h"
#include "pm/model/PassView.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"

namespace pm::lab {

//! What runLabPass() gives: the views and, for ground truth, the robot's side of the pass.
struct LabPass
{
  std::vector<PassView> views;     //!< the views, named "view 00", "view 01", ... (hand pose fMh, the pairs with and without the toy)
  std::vector<vpColVector> joints; //!< the PA-10's joints at each view
  std::vector<PassDirection> directions; //!< each view's direction as reached (tilted less where the plan's was out of reach)
  vpHomogeneousMatrix fMo;         //!< the toy in the base frame during the pass (ground truth, metres)
  vpHomogeneousMatrix fMh0;        //!< the hand at rest, in the base frame (forward kinematics at q0)
};

/*!
  Runs the pass of \e plan with the PA-10 starting at \e q0 and the toy at \e h0Mo in the hand frame
  at rest (the plan's pivot is put on the toy's origin). Without \e backgrounds the second pass (the
  toy removed) is not made (a plain backdrop). Throws pm::Error naming the first view the
  PA-10 cannot reach within its joint limits.
*/
LabPass runLabPass(const sim::Scene &scene, const StereoRig &rig, const PassPlan &plan, const vpColVector &q0,
                   const vpHomogeneousMatrix &h0Mo = vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), bool backgrounds = true);

/*!
  The lab's all-around model of \e scene's toy: the pass of \e plan from \e q0 with the toy at
  (0, 0, \e distanceMm) in the hand frame at rest, then buildAllAroundModel(); with the model frame
  in the toy's frame (oMm) for ground truth. \e build (when given) receives the whole build.
*/
sim::SimulatedPhotoModel makeSimulatedAllAroundModel(const sim::Scene &scene, const StereoRig &rig, const PassPlan &plan,
                                                     const vpColVector &q0, double distanceMm = 500,
                                                     const AllAroundParams &params = AllAroundParams(),
                                                     AllAroundBuild *build = nullptr);

} // namespace pm::lab
