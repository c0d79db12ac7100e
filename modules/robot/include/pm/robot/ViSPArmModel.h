#pragma once
/*!
  \file ViSPArmModel.h
  An ArmModel over one of ViSP's kinematic models of its robots (vpViper850, vpAfma6, ...: the
  classes its vpRobot drivers and simulators derive from): their get_fMe(), get_eJe() and joint
  limits. The hand-eye eMc they also hold is not used (the rig is mounted by the Arm's eMh).
*/
#include "pm/robot/ArmModel.h"

namespace pm::robot {

/*!
  ViSP's kinematic model \e Kinematics (with get_fMe(q, fMe), get_eJe(q, eJe), getJointMin(),
  getJointMax()) as an ArmModel; a derived class names the arm and gives its speed limits and
  rest joints. Instantiated for vpViper850 and vpAfma6 (Viper850Model, Afma6Model).
*/
template <class Kinematics>
class ViSPArmModel : public ArmModel
{
public:
  unsigned dof() const override { return Kinematics::njoint; } //!< ViSP's number of joints of the arm
  vpHomogeneousMatrix fMe(const vpColVector &q) const override; //!< ViSP's get_fMe(); throws pm::core::Error for a wrong size
  vpMatrix eJe(const vpColVector &q) const override;            //!< ViSP's get_eJe(); throws pm::core::Error for a wrong size
  vpColVector jointMin() const override { return m_kinematics.getJointMin(); } //!< ViSP's lower joint limits
  vpColVector jointMax() const override { return m_kinematics.getJointMax(); } //!< ViSP's upper joint limits
  vpColVector accelerationLimits() const override { return speedLimits() * 5.0; } //!< 5 times the speed limits: full speed in 0.2 s, as for the PA-10

protected:
  Kinematics m_kinematics; //!< ViSP's model (its hand-eye eMc unused)
};

} // namespace pm::robot
