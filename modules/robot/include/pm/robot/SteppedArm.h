#pragma once
/*!
  \file SteppedArm.h
  The lab's drive of an arm: its model's joints integrated in our own loop (no thread, no clock),
  so a run repeats to the bit and goes as fast as the computer. The commanded joint velocity is
  scaled down as a whole to the speed limits (the motion keeps its direction), integrated in
  steps of at most the arm's servo cycle, and a joint that would cross its limit stops on it (the
  count of such events is kept; it must stay 0 under a sane controller).
*/
#include "pm/robot/Arm.h"

namespace pm::robot {

/*!
  An arm whose joints our loop integrates (see SteppedArm.h). Starts at its model's rest joints.
  \code
    pm::robot::SteppedArm arm(pm::robot::makeArmModel("afma6"));
    arm.setJointVelocity(vpColVector(6, 0.01));
    for (int k = 0; k < 30; ++k)
      arm.advance(1.0 / 30);                 // one second
  \endcode
*/
class SteppedArm : public Arm
{
public:
  /*!
    \e model with the rig at \e eMh, integrated in steps of at most \e cycle seconds (the arm's
    servo cycle; 2 ms, the PA-10's). Throws pm::core::Error for a null model or a cycle not positive.
  */
  explicit SteppedArm(std::unique_ptr<ArmModel> model, const vpHomogeneousMatrix &eMh = vpHomogeneousMatrix(), double cycle = 0.002);
  vpColVector q() override { return m_q; }
  const vpColVector &joints() const { return m_q; } //!< the joints now (without the virtual call)
  const vpColVector &qdot() const { return m_qdot; } //!< the command as scaled to the speed limits (0 for a joint stopped on its limit)
  vpColVector commanded() const override { return m_qdot; }
  void setJointVelocity(const vpColVector &qdot) override;
  void advance(double dt) override;
  //! Puts the arm at \e q at once (the lab's pass: the path between views is not simulated), at rest.
  void moveTo(const vpColVector &q) override;
  void stop() override { m_qdot = 0; }
  int limitHits() const override { return m_limitHits; }
  std::string describe() const override;

private:
  void integrate(double dt);
  vpColVector m_q, m_qdot, m_qmin, m_qmax, m_speed;
  double m_cycle;
  int m_limitHits = 0;
};

} // namespace pm::robot
