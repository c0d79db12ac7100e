#pragma once
/*!
  \file Afma6Model.h
  Irisa's Afma6 gantry (3 prismatic joints x, y, z, then 3 revolute ones) as ViSP models it
  (vpAfma6: its kinematics and joint limits), for the pass and the servo loop.
*/
#include <visp3/robot/vpAfma6.h>

#include "pm/robot/ViSPArmModel.h"

namespace pm::robot {

/*!
  ViSP's Afma6 (vpAfma6's forward kinematics, Jacobian and joint limits; its hand-eye eMc is not
  used: the rig is mounted on the flange by the lab's own eMh). Rest joints (0, 0, -100 mm,
  0, 45 deg, 0): mid-way along the z slide, the wrist 45 deg from its singularity (q5 = 90 deg,
  where joints 4 and 6 turn about one axis: at rest there the main job hit the limits 85 times)
  and from q5's lower limit (-5.7 deg); every view of the lab's pass in reach.
  Speed limits, our choice: 0.25 m/s for the slides, 1 rad/s for the wrist; accelerations 5 times those.
  \code
    pm::robot::Afma6Model afma6;
    const vpHomogeneousMatrix fMe = afma6.fMe(afma6.restJoints());
  \endcode
*/
class Afma6Model : public ViSPArmModel<vpAfma6>
{
public:
  std::string name() const override { return "afma6"; }
  std::string title() const override { return "Afma6"; }
  bool prismatic(unsigned i) const override { return i < 3; }
  vpColVector speedLimits() const override;
  vpColVector restJoints() const override;
};

} // namespace pm::robot
