#pragma once
/*!
  \file LabPass.h
  The lab's pass around the target: an arm (the PA-10, or ViSP's Viper850 or Afma6, any
  pm::robot::Arm) carries the rig through the views of a PassPlan made concrete for it
  (pm::robot::planArmPass(): joints by inverse kinematics within the limits, a view out of reach
  tilted less or turned; the arm is moved there with Arm::moveTo()), and at each the rig takes a pair with the toy in place and one with
  it removed; the hand's pose is the arm's forward kinematics at the joints it reached (the base
  frame is the world frame f). The views are what a user's rig writes into a views folder
  (pm::io::saveViewsFolder), so the lab and a user's files go through one builder.

  \code
      pm::robot::SteppedArm arm(pm::robot::makeArmModel("viper850"));
      const pm::lab::LabPass pass = pm::lab::runLabPass(scene, rig, pm::model::PassPlan(), arm);
      const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass.views);
      const vpHomogeneousMatrix oMm = pass.fMo.inverse() * b.fMm;   // ground truth of the model frame
  \endcode
*/
#include <vector>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/CameraRig.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PassPlanner.h"
#include "pm/model/PassView.h"
#include "pm/robot/Arm.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"

namespace pm::lab {

//! What runLabPass() gives: the views and, for ground truth, the robot's side of the pass.
struct LabPass
{
  std::vector<model::PassView> views;     //!< the views, named "view 00", "view 01", ... (hand pose fMh, the pairs with and without the toy)
  std::vector<vpColVector> joints; //!< the arm's joints at each view
  std::vector<model::PassDirection> directions; //!< each view's direction as reached (tilted less where the plan's was out of reach)
  std::vector<model::PassDirection> leftOut; //!< the plan's outer-ring directions the arm could not reach (no view there)
  vpHomogeneousMatrix fMo;         //!< the toy in the base frame during the pass (ground truth, metres)
  vpHomogeneousMatrix fMh0;        //!< the hand at rest, in the base frame (where the arm was when the pass began)
};

/*!
  Runs the pass of \e plan with \e arm from where it is (its rest) and the toy at \e h0Mo in the
  hand frame there (the plan's pivot is put on the toy's origin); the arm is left at the last
  view. Without \e backgrounds the second pass (the toy removed) is not made (a plain backdrop).
  Views of the plan's outer rings the arm cannot reach are left out (LabPass::leftOut). Each view's
  pair is taken by model::passRig(\e rig): a stereo rig's two cameras, or one camera and the same
  camera after the hand's side step (the lab takes the step as made exactly). Throws
  pm::core::Error naming the first view of the innermost ring the arm cannot reach within its joint
  limits, and the joint in the way.
*/
LabPass runLabPass(const sim::Scene &scene, const core::CameraRig &rig, const model::PassPlan &plan, robot::Arm &arm,
                   const vpHomogeneousMatrix &h0Mo = vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), bool backgrounds = true);

/*!
  The lab's all-around model of \e scene's toy: the pass of \e plan by \e arm (a pm::robot::makeArmModel()
  name, stepped in our loop from its rest joints, the rig on its flange) with the toy at
  (0, 0, \e distanceMm) in the hand frame at rest, then buildAllAroundModel(); with the model frame
  in the toy's frame (oMm) for ground truth. \e build (when given) receives the whole build. With
  \e calibrateTrust, the model's trust is calibrated from the pass as pm-make-model calibrates it
  (pm::trust::calibrateFromPass(), its default parameters), for a tracker on \e rig.
*/
sim::SimulatedPhotoModel makeSimulatedAllAroundModel(const sim::Scene &scene, const core::CameraRig &rig, const model::PassPlan &plan,
                                                     const std::string &arm = "pa10", double distanceMm = 500,
                                                     const model::AllAroundParams &params = model::AllAroundParams(),
                                                     model::AllAroundBuild *build = nullptr, bool calibrateTrust = false);

} // namespace pm::lab
