// The usage examples of pm::hand's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/hand/GraspApproach.h"
#include "pm/hand/GuardedServo.h"
#include "pm/hand/HandLoop.h"
#include "pm/hand/HandPass.h"

#include <iostream>
#include "pm/capture/VideoCaptureSource.h"
#include "pm/io/ViewsFolder.h"
#include "pm/robot/ArmCatalog.h"
#include "pm/robot/ViSPRobotArm.h"
namespace pm_examples {

// GraspApproach.h
void exampleGraspApproach(pm::hand::GuardedServo &guard, const pm::hand::GuardedCommand &c)
{
  pm::hand::GraspApproach approach(pm::hand::GraspApproachParams(), vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0));
  // each frame, after the command (guard: a pm::hand::GuardedServo, c: its GuardedCommand):
  approach.advance(c.servoing, 1.0 / 30);
  guard.moveDesired(approach.hdMo());
}

// GuardedServo.h
void exampleGuardedServo(const pm::servo::ServoParams &servoParams, pm::tracker::PhotoModelTracker &tracker, pm::robot::Arm &arm,
                         const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right)
{
  pm::hand::GuardedServo guard(servoParams, pm::hand::GuardParams(), tracker, arm.model());
  const pm::tracker::TrackResult r = tracker.track(left, right);
  const vpColVector q = arm.q();
  const pm::hand::GuardedCommand c = guard.step(r, false, q, arm.fMh(q), arm.hJe(q), 1.0 / 30);
  arm.setJointVelocity(c.qdot);
}

// HandLoop.h
void exampleHandLoop(vpRobot &myRobot, const vpHomogeneousMatrix &eMh, const pm::core::StereoRig &rig, const pm::core::PhotoModel &model)
{
  pm::robot::ViSPRobotArm arm(myRobot, pm::robot::makeArmModel("viper850"), eMh);
  pm::capture::VideoCaptureSource cameras("0", "1");
  pm::servo::ServoParams sp;
  sp.hdMo = vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0); // keep the target 500 mm ahead
  pm::hand::HandLoop loop(rig, model, pm::tracker::TrackerParams(), sp, pm::hand::GuardParams(), cameras, arm);
  pm::hand::HandFrame f;
  while (loop.step(f))
    std::cout << f.index << (f.command.servoing ? " servoing" : " held") << std::endl;
}

// HandPass.h
void exampleHandPass(vpRobot &myRobot, const vpHomogeneousMatrix &eMh)
{
  pm::robot::ViSPRobotArm arm(myRobot, pm::robot::makeArmModel("viper850"), eMh);
  pm::capture::VideoCaptureSource cameras("0", "1");
  pm::model::PassPlan plan;
  plan.distanceMm = 500;   // the target this far ahead of the hand, on its z axis
  pm::hand::PassRecording rec;
  rec.ask = [](const std::string &what) { std::cout << what << std::endl; std::cin.get(); };
  pm::io::saveViewsFolder(pm::hand::recordPass(arm, cameras, plan, rec), "views");
}

} // namespace pm_examples
