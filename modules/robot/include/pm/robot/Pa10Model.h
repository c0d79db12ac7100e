#pragma once
/*!
  \file Pa10Model.h
  The Mitsubishi PA-10-7C's kinematics: 7 revolute joints, standard DH (a = 0, d = 0.317, 0,
  0.450, 0, 0.480, 0, 0.070 m, alpha = -90, 90, -90, 90, -90, 90, 0 deg; q = 0 points the arm
  straight up, the flange at 1.317 m), joint ranges S1 +-177, S2 +-94, S3 +-174, E1 +-137,
  E2 +-255, W1 +-165, W2 +-255 deg, speed limits 1, 1, 2, 2, 2 pi, 2 pi, 2 pi rad/s.
*/
#include "pm/robot/ArmModel.h"

namespace pm::robot {

/*!
  The PA-10-7C (see Pa10Model.h): the arm of the paper's experiments, the lab's default.
  \code
    pm::robot::Pa10Model pa10;
    const vpHomogeneousMatrix fMe = pa10.fMe(pa10.restJoints()); // the flange 0.78 m ahead, looking along x
  \endcode
*/
class Pa10Model : public ArmModel
{
public:
  static constexpr unsigned kDof = 7; //!< number of joints
  std::string name() const override { return "pa10"; }
  std::string title() const override { return "PA-10"; }
  unsigned dof() const override { return kDof; }
  vpHomogeneousMatrix fMe(const vpColVector &q) const override;
  vpMatrix eJe(const vpColVector &q) const override;
  //! jacobianBase(q): straight from the DH chain.
  vpMatrix fJe(const vpColVector &q) const override { return jacobianBase(q); }
  //! The geometric Jacobian in the base frame, straight from the DH chain (6 x 7).
  static vpMatrix jacobianBase(const vpColVector &q);
  //! Forward kinematics (static: fMe() without an object).
  static vpHomogeneousMatrix forward(const vpColVector &q);
  vpColVector jointMin() const override;
  vpColVector jointMax() const override;
  vpColVector speedLimits() const override;
  /*!
    5, 5, 10, 10, 10 pi, 10 pi, 10 pi rad/s^2, i.e. each joint from rest to full speed in 0.2 s.
    Our choice (the PA-10's servo amplifiers' figures were not found; with 0.5 s the hand
    overshot the end of Table 2's moves by 20 mm).
  */
  vpColVector accelerationLimits() const override;
  //! (0, -35, 0, 80, 0, 45, -90) deg: looking horizontally along the base's x axis, elbow and wrist well bent.
  vpColVector restJoints() const override;
};

} // namespace pm::robot
