#pragma once
/*!
  \file Arm.h
  One interface for the pass and the servo loop, whatever the arm: its model (kinematics and
  limits, ArmModel), how the stereo rig is mounted on its flange (eMh), and how it is driven:
  read the joints, command joint velocities, move to joints, let time pass. Two drives exist:
  SteppedArm (the lab's: the model's joints integrated in our own loop, repeatable and faster
  than real time) and ViSPRobotArm (any vpRobot, a real arm or ViSP's threaded simulators, in
  real time).

  Frames: f the arm's base, e its flange, h the hand frame of the stereo rig (StereoRig's frame).
*/
#include <memory>
#include <string>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpMatrix.h>

#include "pm/robot/ArmModel.h"

namespace pm::robot {

/*!
  An arm carrying the stereo rig (see Arm.h). Not copyable.
  \code
    pm::robot::SteppedArm arm(pm::robot::makeArmModel("viper850"));    // at its rest joints
    vpColVector qdot(arm.model().dof(), 0.0);
    qdot[0] = 0.1;
    arm.setJointVelocity(qdot);
    arm.advance(1.0 / 30);                                            // one camera frame
    const vpHomogeneousMatrix fMh = arm.fMh();                        // the rig's pose now
  \endcode
*/
class Arm
{
public:
  //! \e model (not null; throws pm::core::Error otherwise) with the rig at \e eMh on the flange.
  Arm(std::unique_ptr<ArmModel> model, const vpHomogeneousMatrix &eMh);
  virtual ~Arm() = default;
  Arm(const Arm &) = delete;
  Arm &operator=(const Arm &) = delete;

  const ArmModel &model() const { return *m_model; } //!< the arm's kinematics and limits
  const vpHomogeneousMatrix &eMh() const { return m_eMh; } //!< the rig's hand frame on the flange
  //! The joints now (rad or m). Throws pm::core::Error when the arm does not answer.
  virtual vpColVector q() = 0;
  //! The hand frame's pose in the base frame at joints \e q: model().fMe(q) eMh.
  vpHomogeneousMatrix fMh(const vpColVector &q) const { return m_model->fMe(q) * m_eMh; }
  //! The hand frame's pose in the base frame now.
  vpHomogeneousMatrix fMh() { return fMh(q()); }
  //! The Jacobian of the hand frame in its own frame at \e q (6 x dof): hVe eJe.
  vpMatrix hJe(const vpColVector &q) const;
  /*!
    Commands joint velocities \e qdot (rad/s or m/s; dof() values, finite), held until the next
    command. Throws pm::core::Error otherwise (the arm is then stopped).
  */
  virtual void setJointVelocity(const vpColVector &qdot) = 0;
  //! The joint velocity being commanded, after the arm's own clamps (rad/s or m/s).
  virtual vpColVector commanded() const = 0;
  //! Lets \e dt seconds pass under the last command (the lab integrates; a real arm waits until then).
  virtual void advance(double dt) = 0;
  //! Moves to joints \e q and returns there, at rest. Throws pm::core::Error (the joint named) for joints out of the limits.
  virtual void moveTo(const vpColVector &q) = 0;
  //! Commands zero velocity at once.
  virtual void stop() = 0;
  //! Times a joint reached its limit and was stopped there (0 under a sane controller; a real arm's own guards count elsewhere).
  virtual int limitHits() const { return 0; }
  //! "Viper850 (vpViper850), stepped in our loop", or similar: what drives the arm.
  virtual std::string describe() const = 0;

protected:
  std::unique_ptr<ArmModel> m_model; //!< the arm's kinematics and limits (never null)
  vpHomogeneousMatrix m_eMh;         //!< the rig's hand frame on the flange
};

} // namespace pm::robot
