#pragma once
/*!
  \file ViSPRobotArm.h
  The drive of any ViSP robot (a vpRobot: a real arm's driver, or ViSP's threaded simulators
  vpSimulatorViper850 and vpSimulatorAfma6) behind pm::robot::Arm, in real time: joint
  velocities through vpRobot::setVelocity(JOINT_STATE), the joints read back with
  getPosition(JOINT_STATE), positions reached in position control. Its kinematics (for the
  pass's inverse kinematics and the servo's Jacobian) come from an ArmModel that matches it.

  Each velocity command is bounded near the joints' limits (ViSPRobotArmParams::limitHorizonS), so
  that a command that lasts longer than meant does not carry a joint onto its limit.

  A robot that does not answer (an exception, joints of the wrong size or not finite, or joints
  that do not move for ViSPRobotArmParams::stallS while a motion is commanded: the error names a
  joint on its limit when one is there) stops the arm and throws pm::core::Error: the loop that drives
  it ends with that error and the arm at rest.
*/
#include <visp3/robot/vpRobot.h>

#include "pm/robot/Arm.h"

namespace pm::robot {

//! Settings of ViSPRobotArm.
struct ViSPRobotArmParams
{
  double stallS = 1.0;           //!< a commanded motion that moves no joint for this long means the robot does not answer (s)
  double positionTolerance = 1e-3; //!< moveTo() fails when a joint ends farther than this from its goal (rad or m)
  /*!
    A joint's velocity toward its limit is at most its distance to that limit over this (s), as it
    reads when the command is sent. The command persists until the next one: a frame this late (the
    program descheduled on a loaded machine) still stops short of the limit, where ViSP's simulators
    would stop the arm (and their integrator can then read joints that are not finite).
  */
  double limitHorizonS = 0.5;
  /*!
    moveTo() through joint velocities in our own loop (each joint at most at its model's speed
    limit, slowing down proportionally near its goal) instead of the robot's vpRobot::setPosition().
    Always so for ViSP's threaded simulators (any vpRobotWireFrameSimulator), whose setPosition() in
    joint space races their own thread: on a loaded machine (or one core) it can wait for ever.
  */
  bool moveByVelocity = false;
};

/*!
  A vpRobot driven in real time through Arm (see ViSPRobotArm.h). The robot must outlive it.
  \code
    vpSimulatorViper850 sim(false);                       // headless, its own thread
    sim.init(vpViper850::TOOL_PTGREY_FLEA2_CAMERA, vpCameraParameters::perspectiveProjWithoutDistortion);
    pm::robot::ViSPRobotArm arm(sim, pm::robot::makeArmModel("viper850"));
    arm.moveTo(arm.model().restJoints());                 // position control, blocking
    vpColVector qdot(6, 0.0);
    qdot[0] = 0.1;
    arm.setJointVelocity(qdot);                           // velocity control
    arm.advance(1.0 / 30);                                // waits until 1/30 s after the last advance()
    arm.stop();
  \endcode
*/
class ViSPRobotArm : public Arm
{
public:
  //! \e robot with the kinematics of \e model and the rig at \e eMh on its flange. Throws pm::core::Error for a null model.
  ViSPRobotArm(vpRobot &robot, std::unique_ptr<ArmModel> model, const vpHomogeneousMatrix &eMh = vpHomogeneousMatrix(),
               const ViSPRobotArmParams &params = ViSPRobotArmParams());
  //! Stops the robot (a stop that fails is not reported from a destructor).
  ~ViSPRobotArm() override;
  vpColVector q() override;
  vpColVector commanded() const override { return m_command; }
  //! Sends \e qdot, each joint's velocity toward its limit bounded (ViSPRobotArmParams::limitHorizonS); commanded() is what was sent.
  void setJointVelocity(const vpColVector &qdot) override;
  //! Waits until \e dt seconds after the end of the last advance() (or the first command), then checks the robot moves.
  void advance(double dt) override;
  /*!
    Position control to \e q (within the model's limits; throws pm::core::Error naming a joint out of
    them), through the robot's own blocking vpRobot::setPosition() (or our velocity loop, see
    ViSPRobotArmParams::moveByVelocity); then at rest. Throws pm::core::Error when it stops short of \e q.
  */
  void moveTo(const vpColVector &q) override;
  void stop() override;
  std::string describe() const override;

private:
  [[noreturn]] void fail(const std::string &what);
  std::string stallReason(const vpColVector &q) const; //!< why the joints do not move: a joint on its limit, or no answer
  vpColVector boundedNearLimits(const vpColVector &qdot, const vpColVector &q) const; //!< \e qdot, its joints' velocities toward their limits bounded
  void setPosition(const vpColVector &goal);   //!< through vpRobot::setPosition()
  void driveTo(const vpColVector &goal);       //!< through joint velocities (moveByVelocity)
  vpRobot &m_robot;
  ViSPRobotArmParams m_params;
  vpColVector m_command, m_lastQ;
  vpColVector m_asked;     //!< the last velocity asked of setJointVelocity(), before boundedNearLimits(): a stall is judged on it
  double m_tickMs = -1;    //!< the end of the last advance() (vpTime ms; -1: none yet)
  double m_stillS = 0;     //!< how long the joints have not moved under a motion command (s)
};

} // namespace pm::robot
