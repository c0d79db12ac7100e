#pragma once
/*!
  \file ArmPassPlan.h
  The pass of the hand around the target (a pm::model::PassPlan) made concrete for one arm: the joints
  of each view, found by inverse kinematics from the rest joints or the last view's, within the
  joint limits. A view out of reach is tilted less, 5 deg at a time down to half its ring's
  angle; still out of reach, it is turned about the hand's axis (a wrist's last joint may not
  turn far enough; the view sees the target the same) and tilted less again. A view of an outer
  ring still out of reach is left out (the pass covers those tilts where the arm reaches them);
  the rest view and the innermost ring's must be reached. The lab's pass and a real arm's both
  move through these joints.
*/
#include <string>
#include <vector>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/model/PassPlanner.h"
#include "pm/robot/ArmModel.h"

namespace pm::robot {

//! One view of an ArmPassPlan.
struct ArmPassView
{
  std::string name;        //!< "view 00", "view 01", ...
  model::PassDirection direction; //!< the direction as reached (tilted less or turned where the plan's was out of reach)
  vpColVector q;           //!< the arm's joints there
};

/*!
  The views of \e plan for \e arm from joints \e q0, the rig mounted at \e eMh on the flange and
  the plan's pivot \e distanceMm ahead of the hand at q0. Views of the outer rings out of reach are
  left out (their directions appended to \e leftOut when given; the views keep the plan's numbers).
  Throws pm::core::Error naming the first view of the innermost ring (or the rest view) out of
  reach and the joint in the way.
  \code
    const auto arm = pm::robot::makeArmModel("viper850");
    const std::vector<pm::robot::ArmPassView> views =
        pm::robot::planArmPass(*arm, arm->restJoints(), vpHomogeneousMatrix(), pm::model::PassPlan(), 500);
  \endcode
*/
std::vector<ArmPassView> planArmPass(const ArmModel &arm, const vpColVector &q0, const vpHomogeneousMatrix &eMh,
                                     const model::PassPlan &plan, double distanceMm,
                                     std::vector<model::PassDirection> *leftOut = nullptr);

//! "view at 55 deg toward 65 deg: out of the PA-10's reach, left out of the pass" for a direction planArmPass() left out.
std::string describeLeftOut(const model::PassDirection &d, const std::string &armTitle);

} // namespace pm::robot
