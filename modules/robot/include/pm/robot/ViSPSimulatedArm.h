#pragma once
/*!
  \file ViSPSimulatedArm.h
  ViSP's own threaded simulators of its arms, vpSimulatorViper850 and vpSimulatorAfma6, headless,
  driven through ViSPRobotArm exactly as a real vpRobot would be: in real time (a run takes the
  motion's real duration), by the simulator's thread, so not repeatable frame for frame. The lab's
  repeatable runs step the same kinematic models in our own loop instead (SteppedArm).
*/
#include <memory>
#include <string>

#include <visp3/robot/vpRobot.h>

#include "pm/robot/ViSPRobotArm.h"

namespace pm::robot {

namespace detail {
//! Owns the simulator, built before the ViSPRobotArm that drives it.
struct SimulatorHolder
{
  std::unique_ptr<vpRobot> simulator; //!< vpSimulatorViper850 or vpSimulatorAfma6, headless
};
} // namespace detail

/*!
  A headless ViSP simulator of the arm called \e name ("viper850" or "afma6"; the PA-10 has none)
  at its model's rest joints, driven through ViSPRobotArm. The simulator's velocity saturation is
  set to the model's speed limits; it moves to a position through joint velocities (ViSPRobotArmParams::moveByVelocity).
  \code
    pm::robot::ViSPSimulatedArm arm("afma6");      // at rest, in real time
    arm.setJointVelocity(vpColVector(6, 0.0));
    arm.advance(1.0 / 30);
  \endcode
*/
class ViSPSimulatedArm : private detail::SimulatorHolder, public ViSPRobotArm
{
public:
  //! Throws pm::core::Error for a name without a ViSP simulator.
  explicit ViSPSimulatedArm(const std::string &name, const vpHomogeneousMatrix &eMh = vpHomogeneousMatrix());
  ~ViSPSimulatedArm() override;
  std::string describe() const override;
};

} // namespace pm::robot
