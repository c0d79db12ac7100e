#pragma once
/*!
  \file InverseKinematics.h
  Joints that put an arm's flange at a pose, for any ArmModel: damped least squares on its
  base-frame Jacobian, each step held inside the joint limits less a margin, the redundancy of
  an arm with more than 6 joints spent on staying near the seed.
*/
#include <string>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/robot/ArmModel.h"

namespace pm::robot {

//! What inverseKinematics() found.
struct IkResult
{
  bool reached = false; //!< the flange within 0.1 mm and 0.01 deg of the goal
  vpColVector q;        //!< the joints reached (or the last iterate)
  /*!
    When not reached: the joint (from 0) held on its limit (less the margin) at the last iterate
    that the motion toward the goal pushed against, or -1 (none: the goal is out of reach).
  */
  int blockingJoint = -1;
};

/*!
  Joints of \e arm that put its flange at \e fMe, from \e seed (the nearest solution to it), each
  step held inside the joint limits less \e marginDeg (revolute joints) or \e marginMm (prismatic
  ones). Throws pm::core::Error for a seed of the wrong size.
  \code
    pm::robot::Viper850Model viper;
    const vpHomogeneousMatrix goal = viper.fMe(viper.restJoints()) * vpHomogeneousMatrix(0, 0.05, 0, 0, 0, 0);
    const pm::robot::IkResult ik = pm::robot::inverseKinematics(viper, goal, viper.restJoints());
    if (!ik.reached && ik.blockingJoint >= 0)
      std::cerr << viper.describeJoint(ik.blockingJoint, ik.q) << " is in the way" << std::endl;
  \endcode
*/
IkResult inverseKinematics(const ArmModel &arm, const vpHomogeneousMatrix &fMe, const vpColVector &seed, double marginDeg = 2.0,
                           double marginMm = 2.0);

} // namespace pm::robot
