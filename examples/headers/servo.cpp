// The usage examples of pm::servo's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/servo/PbvsServo.h"
#include "pm/servo/PoseFilter.h"
#include "pm/servo/SafeCommand.h"

#include "pm/sim/RobotPA10.h"
namespace pm_examples {

// PbvsServo.h
void examplePbvsServo(const vpHomogeneousMatrix &hMo)
{
  pm::sim::RobotPA10 robot;
  robot.setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
  pm::servo::PbvsServo servo; // default ServoParams: the target held 0.5 m ahead of the hand
  const double dt = 1.0 / 30;
  vpMatrix eJe;
  robot.get_eJe(eJe);
  // hMo: the target's estimated pose in the hand frame (metres), e.g. a pm::tracker::TrackResult's.
  const vpColVector qdot = servo.computeJointVelocity(hMo, robot.fMe(), eJe, robot.q(), robot.jointMin(),
                                                      robot.jointMax(), dt);
  robot.setVelocity(vpRobot::JOINT_STATE, qdot);
  robot.step(dt);
}

// PoseFilter.h
void examplePoseFilter(pm::servo::PbvsServo &servo, const vpHomogeneousMatrix &fMh, const vpHomogeneousMatrix &hMo, const vpMatrix &eJe,
                       const vpColVector &q, const vpColVector &qmin, const vpColVector &qmax)
{
  pm::servo::PoseFilter filter; // default gains
  const double dt = 1.0 / 30;
  // fMh: the hand in the base frame; hMo: the estimated target in the hand frame.
  filter.update(fMh * hMo, dt);
  const vpColVector twist = filter.twist(); // v (m/s), w (rad/s), base frame
  const vpColVector qdot = servo.computeJointVelocity(fMh.inverse() * filter.pose(), fMh, eJe, q, qmin, qmax, dt, &twist);
}

// SafeCommand.h
void exampleSafeCommand(bool usable, const vpColVector &qdotWanted, double dt)
{
  pm::sim::RobotPA10 robot;
  robot.setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
  pm::servo::SafeCommand safe(robot.speedLimits(), robot.accelerationLimits());
  // every cycle of dt seconds: toward the servo's command when the estimate is usable, else toward zero
  robot.setVelocity(vpRobot::JOINT_STATE, usable ? safe.next(qdotWanted, dt) : safe.stop(dt));
}

} // namespace pm_examples
