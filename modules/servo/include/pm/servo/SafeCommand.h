#pragma once
/*!
  \file SafeCommand.h
  The last gate between a controller and the joints: every cycle the wanted joint velocity (zero
  to stop) is scaled down as a whole to the speed limits, and the command moves toward it by at
  most the acceleration limits times the cycle time (the change scaled as a whole, so that it
  keeps its direction). So a stop is a ramp, a restart too, and no command jumps. A wanted
  velocity that is not finite or of the wrong size is taken as a stop.
*/
#include <visp3/core/vpColVector.h>

namespace pm::servo {

/*!
  Speed and acceleration limiter of a joint velocity command (see SafeCommand.h). It holds the
  last command, zero at first; call next() or stop() once per control cycle.

  \code
    pm::sim::RobotPA10 robot;
    robot.setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
    pm::servo::SafeCommand safe(robot.speedLimits(), robot.accelerationLimits());
    // every cycle of dt seconds: toward the servo's command when the estimate is usable, else toward zero
    robot.setVelocity(vpRobot::JOINT_STATE, usable ? safe.next(qdotWanted, dt) : safe.stop(dt));
  \endcode
*/
class SafeCommand
{
public:
  /*!
    \e speedLimits (rad/s) and \e accelerationLimits (rad/s^2), one per joint (at least one),
    positive and finite. Throws pm::core::Error otherwise. The first command is zero.
  */
  SafeCommand(const vpColVector &speedLimits, const vpColVector &accelerationLimits);

  //! The command for a cycle of \e dt seconds toward \e wanted. Throws pm::core::Error if dt <= 0.
  const vpColVector &next(const vpColVector &wanted, double dt);
  //! next() toward zero.
  const vpColVector &stop(double dt);

  //! The last command (rad/s, one per joint).
  const vpColVector &last() const { return m_cmd; }
  bool stopped() const; //!< the last command is exactly zero

private:
  vpColVector m_vmax, m_amax, m_cmd;
};

} // namespace pm::servo
