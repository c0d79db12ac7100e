#pragma once
/*!
  \file RobotPA10.h
  The Mitsubishi PA-10-7C as a ViSP robot (vpRobotSimulator): its kinematics and limits are
  pm::robot::Pa10Model's, its motion pm::robot::SteppedArm's (the lab's own loop drives the
  PA-10 through that Arm, as any other arm; this class lets ViSP code drive it as a vpRobot).

  Frames: f the base (reference), e the flange; the hand frame H of the stereo rig is the flange
  frame (z along the last joint axis, out of the flange), so eMh is the identity.

  Velocity control in joint space or in the end-effector frame (the redundancy resolved by the
  pseudo-inverse of eJe). The controller of the simulation calls step(dt): the commanded joint
  velocities, clamped to the speed limits, are integrated, and a joint that would cross its
  limit stops on it (the count of such events is kept; it must stay 0 under a sane controller).
  A command over a joint's speed limit is scaled down as a whole, so the motion keeps its direction.
*/
#include <memory>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpMatrix.h>
#include <visp3/robot/vpRobotSimulator.h>

#include "pm/robot/SteppedArm.h"

namespace pm::sim {

/*!
  The simulated PA-10-7C arm that carries the stereo rig (see RobotPA10.h for its geometry and
  limits). Its state is the joint vector q (rad) and the commanded joint velocities qdot
  (rad/s); time advances only when the caller calls step(). Not copyable.
  \code
  pm::sim::RobotPA10 robot;                          // q = 0: the arm straight up
  vpColVector q0(pm::sim::RobotPA10::kDof, 0.0);
  q0[1] = vpMath::rad(30);
  q0[3] = vpMath::rad(90);
  q0[5] = vpMath::rad(60);
  robot.setPosition(vpRobot::JOINT_STATE, q0);
  robot.setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
  vpColVector v(6, 0.0);                             // twist in the flange frame (m/s, rad/s)
  v[2] = 0.05;                                       // 5 cm/s along the flange's z axis
  robot.setVelocity(vpRobot::END_EFFECTOR_FRAME, v);
  for (int k = 0; k < 500; ++k)
    robot.step(0.002);                               // 1 s in steps of 2 ms
  const vpHomogeneousMatrix fMe = robot.fMe();       // the flange's pose in the base frame
  vpColVector q;
  if (pm::sim::RobotPA10::inverse(fMe, q0, q))       // back to it from q0
    robot.setPosition(vpRobot::JOINT_STATE, q);
  \endcode
*/
class RobotPA10 : public vpRobotSimulator
{
public:
  static constexpr int kDof = 7; //!< number of joints (degrees of freedom)
  //! The arm at q = 0, at rest, no limit hit; the joint limits set; a sampling time of 2 ms (the PA-10's servo cycle).
  RobotPA10();
  RobotPA10(const RobotPA10 &) = delete; // vpRobot's raw joint-limit arrays must not be shared
  RobotPA10 &operator=(const RobotPA10 &) = delete;

  //! Back to q = 0 at rest, and the count of limit hits to 0.
  void init() override;
  using vpRobot::getPosition;
  //! The Jacobian in the flange frame (6 x 7: vx vy vz wx wy wz of the flange in its own frame) at the current q.
  void get_eJe(vpMatrix &eJe) override;
  //! The Jacobian in the base frame (6 x 7) at the current q: jacobianBase(q()).
  void get_fJe(vpMatrix &fJe) override;
  //! JOINT_STATE: q (rad); any other frame: the flange pose fMe as (x, y, z in m, theta-u in rad).
  void getPosition(const vpRobot::vpControlFrameType frame, vpColVector &q) override;
  /*!
    JOINT_STATE only (the joint values are clamped into their limits); the arm is then at rest.
    Throws pm::core::Error for another frame, a size other than 7 or a value not finite.
  */
  void setPosition(const vpRobot::vpControlFrameType frame, const vpColVector &q) override;
  /*!
    JOINT_STATE (rad/s) or END_EFFECTOR_FRAME / CAMERA_FRAME (twist in the flange frame, m/s rad/s,
    turned into joint velocities by the pseudo-inverse of eJe; CAMERA_FRAME is taken as the flange
    frame too). Scaled down as a whole to the speed limits; applied by step(). Throws pm::core::Error
    for another frame, a wrong size or a value not finite.
  */
  void setVelocity(const vpRobot::vpControlFrameType frame, const vpColVector &vel) override;
  //! JOINT_STATE only: the joint displacement (rad) since the previous call (or setPosition()). Throws pm::core::Error otherwise.
  void getDisplacement(const vpRobot::vpControlFrameType frame, vpColVector &d) override;

  //! Integrates the commanded velocity over \e dt seconds.
  void step(double dt);

  //! Forward kinematics: the flange pose fMe in the base frame (metres) for joints \e q (rad; throws pm::core::Error unless 7).
  static vpHomogeneousMatrix forward(const vpColVector &q);
  //! The geometric Jacobian fJe in the base frame (6 x 7, rows vx vy vz wx wy wz) for joints \e q (rad).
  static vpMatrix jacobianBase(const vpColVector &q);
  /*!
    Inverse kinematics: joints that put the flange at \e fMe, by damped least squares on the
    base-frame Jacobian from \e seed (the nearest solution to it), each step held inside the joint
    limits with a margin of \e marginDeg. Returns false when no solution within 0.1 mm and
    0.01 deg was found (out of reach, or only past a joint limit); \e q holds the last iterate.
  */
  static bool inverse(const vpHomogeneousMatrix &fMe, const vpColVector &seed, vpColVector &q, double marginDeg = 2.0);
  vpHomogeneousMatrix fMe() const { return forward(q()); } //!< the flange (= hand) pose in the base frame now (metres)
  const vpColVector &q() const { return m_arm->joints(); } //!< the joint values now (rad)
  const vpColVector &qdot() const { return m_arm->qdot(); } //!< the joint velocities commanded, scaled to the speed limits; 0 for a joint stopped on its limit (rad/s)
  vpColVector jointMin() const;    //!< lower joint limits (rad)
  vpColVector jointMax() const;    //!< upper joint limits (rad)
  vpColVector speedLimits() const; //!< joint speed limits (rad/s)
  //! Acceleration limits (rad/s^2) for the commands (robot::Pa10Model::accelerationLimits()); pm::servo::SafeCommand holds the commands to them.
  vpColVector accelerationLimits() const;
  //! Times a joint reached its limit and was stopped there (should stay 0).
  int limitHits() const { return m_arm->limitHits(); }

private:
  std::unique_ptr<robot::SteppedArm> m_arm;
  vpColVector m_prevQ;
};

} // namespace pm::sim
