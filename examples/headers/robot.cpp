// The usage examples of pm::robot's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/robot/Afma6Model.h"
#include "pm/robot/Arm.h"
#include "pm/robot/ArmCatalog.h"
#include "pm/robot/ArmModel.h"
#include "pm/robot/ArmPassPlan.h"
#include "pm/robot/InverseKinematics.h"
#include "pm/robot/Pa10Model.h"
#include "pm/robot/SteppedArm.h"
#include "pm/robot/ViSPRobotArm.h"
#include "pm/robot/ViSPSimulatedArm.h"
#include "pm/robot/Viper850Model.h"

#include <visp3/robot/vpSimulatorViper850.h>
namespace pm_examples {

// Afma6Model.h
void exampleAfma6Model()
{
  pm::robot::Afma6Model afma6;
  const vpHomogeneousMatrix fMe = afma6.fMe(afma6.restJoints());
}

// Arm.h
void exampleArm()
{
  pm::robot::SteppedArm arm(pm::robot::makeArmModel("viper850"));    // at its rest joints
  vpColVector qdot(arm.model().dof(), 0.0);
  qdot[0] = 0.1;
  arm.setJointVelocity(qdot);
  arm.advance(1.0 / 30);                                            // one camera frame
  const vpHomogeneousMatrix fMh = arm.fMh();                        // the rig's pose now
}

// ArmCatalog.h
void exampleArmCatalog()
{
  const std::unique_ptr<pm::robot::ArmModel> arm = pm::robot::makeArmModel("afma6");
}

// ArmModel.h
void exampleArmModel()
{
  const std::unique_ptr<pm::robot::ArmModel> arm = pm::robot::makeArmModel("viper850");
  const vpColVector q = arm->restJoints();
  const vpHomogeneousMatrix fMe = arm->fMe(q);   // the flange in the base frame
  const vpMatrix eJe = arm->eJe(q);              // 6 x dof, the flange's twist in its own frame
}

// ArmPassPlan.h
void exampleArmPassPlan()
{
  const auto arm = pm::robot::makeArmModel("viper850");
  const std::vector<pm::robot::ArmPassView> views =
      pm::robot::planArmPass(*arm, arm->restJoints(), vpHomogeneousMatrix(), pm::model::PassPlan(), 500);
}

// InverseKinematics.h
void exampleInverseKinematics()
{
  pm::robot::Viper850Model viper;
  const vpHomogeneousMatrix goal = viper.fMe(viper.restJoints()) * vpHomogeneousMatrix(0, 0.05, 0, 0, 0, 0);
  const pm::robot::IkResult ik = pm::robot::inverseKinematics(viper, goal, viper.restJoints());
  if (!ik.reached && ik.blockingJoint >= 0)
    std::cerr << viper.describeJoint(ik.blockingJoint, ik.q) << " is in the way" << std::endl;
}

// Pa10Model.h
void examplePa10Model()
{
  pm::robot::Pa10Model pa10;
  const vpHomogeneousMatrix fMe = pa10.fMe(pa10.restJoints()); // the flange 0.78 m ahead, looking along x
}

// SteppedArm.h
void exampleSteppedArm()
{
  pm::robot::SteppedArm arm(pm::robot::makeArmModel("afma6"));
  arm.setJointVelocity(vpColVector(6, 0.01));
  for (int k = 0; k < 30; ++k)
    arm.advance(1.0 / 30);                 // one second
}

// ViSPRobotArm.h
void exampleViSPRobotArm()
{
  vpSimulatorViper850 sim(false);                       // headless, its own thread
  sim.init(vpViper850::TOOL_PTGREY_FLEA2_CAMERA, vpCameraParameters::perspectiveProjWithoutDistortion);
  pm::robot::ViSPRobotArm arm(sim, pm::robot::makeArmModel("viper850"));
  arm.moveTo(arm.model().restJoints());                 // position control, blocking
  vpColVector qdot(6, 0.0);
  qdot[0] = 0.1;
  arm.setJointVelocity(qdot);                           // velocity control
  arm.advance(1.0 / 30);                                // waits until 1/30 s after the last advance()
  arm.stop();
}

// ViSPSimulatedArm.h
void exampleViSPSimulatedArm()
{
  pm::robot::ViSPSimulatedArm arm("afma6");      // at rest, in real time
  arm.setJointVelocity(vpColVector(6, 0.0));
  arm.advance(1.0 / 30);
}

// Viper850Model.h
void exampleViper850Model()
{
  pm::robot::Viper850Model viper;
  const vpHomogeneousMatrix fMe = viper.fMe(viper.restJoints());
}

} // namespace pm_examples
