#pragma once
/*!
  \file Viper850Model.h
  The Adept Viper s850 (6 revolute joints) as ViSP models it (vpViper850: its kinematics and
  joint limits), for the pass and the servo loop.
*/
#include <visp3/robot/vpViper850.h>

#include "pm/robot/ViSPArmModel.h"

namespace pm::robot {

/*!
  ViSP's Viper850 (vpViper850's forward kinematics, Jacobian and joint limits; its hand-eye eMc
  is not used: the rig is mounted on the flange by the lab's own eMh). Rest joints (0, -85,
  200, 0, -65, 0) deg: the flange 0.65 m ahead of the base's axis and 0.73 m up, looking ahead
  and 40 deg up, the wrist 65 deg from its singularity (q5 = 0; with q5 = -45 the main job
  crossed it during Table 2's rotations and the hand lagged 65 mm), joint 3 15 deg from the
  simulator's 215 deg limit (at 210 deg the main job on R2 sat on it: a 6-joint arm has no
  redundancy for the servo's joint-limit avoidance). Within the simulator's narrow limits
  (jointMin()) 6 of the lab pass's 16 views are out of reach as planned (joint 2 at its -40 deg)
  and are made tilted less, as the pass does for any arm.
  Speed limits, our choice: 2, 2, 2, 3, 3, 5 rad/s (under the s850's catalogue joint speeds of
  250-600 deg/s); accelerations 5 times those (full speed in 0.2 s, as for the PA-10).
  \code
    pm::robot::Viper850Model viper;
    const vpHomogeneousMatrix fMe = viper.fMe(viper.restJoints());
  \endcode
*/
class Viper850Model : public ViSPArmModel<vpViper850>
{
public:
  std::string name() const override { return "viper850"; }
  std::string title() const override { return "Viper850"; }
  /*!
    vpViper850's limits narrowed to the software limits of ViSP's threaded simulator
    (vpSimulatorViper850: joint 1 +-50, 2 -135..-40, 3 -40..215, 4 +-190, 5 +-110, 6 +-184 deg),
    so that a pass and a servo planned here run there too.
  */
  vpColVector jointMin() const override;
  vpColVector jointMax() const override; //!< see jointMin()
  vpColVector speedLimits() const override;
  vpColVector restJoints() const override;
};

} // namespace pm::robot
