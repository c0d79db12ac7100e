#include "pm/robot/ArmPassPlan.h"

#include <algorithm>
#include <cstdio>

#include "pm/core/Error.h"
#include "pm/robot/InverseKinematics.h"

namespace pm::robot {

std::vector<ArmPassView> planArmPass(const ArmModel &arm, const vpColVector &q0, const vpHomogeneousMatrix &eMh,
                                     const model::PassPlan &plan, double distanceMm, std::vector<model::PassDirection> *leftOut)
{
  arm.requireJoints(q0, "rest joint values");
  const std::vector<model::PassDirection> dirs = model::passDirections(plan);
  const vpHomogeneousMatrix fMh0 = arm.fMe(q0) * eMh, hMe = eMh.inverse();
  const auto flangeGoal = [&](const model::PassDirection &d) { return fMh0 * model::passPose(d, distanceMm) * hMe; };
  const double innermost = *std::min_element(plan.ringsDeg.begin(), plan.ringsDeg.end());
  std::vector<ArmPassView> out;
  vpColVector q = q0;
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "view %02zu", k);
    // From the rest joints first (the arm stays near its rest shape), else from the last view's.
    model::PassDirection d = dirs[k];
    IkResult ik;
    for (double roll : {0, 30, -30, 60, -60, 90, -90}) {
      d.rollDeg = roll;
      for (d.tiltDeg = dirs[k].tiltDeg; d.tiltDeg >= 0.5 * dirs[k].tiltDeg - 1e-9; d.tiltDeg -= 5) {
        ik = inverseKinematics(arm, flangeGoal(d), q0);
        if (!ik.reached)
          ik = inverseKinematics(arm, flangeGoal(d), q);
        if (ik.reached)
          break;
      }
      if (ik.reached)
        break;
    }
    if (!ik.reached && dirs[k].tiltDeg > innermost) { // an outer ring's view: left out, said
      if (leftOut)
        leftOut->push_back(dirs[k]);
      continue;
    }
    if (!ik.reached) {
      ik = inverseKinematics(arm, flangeGoal(dirs[k]), q); // to name the joint in the way
      throw core::Error(std::string(name) + " of the pass (" + std::to_string(static_cast<int>(dirs[k].tiltDeg)) + " deg toward " +
                  std::to_string(static_cast<int>(dirs[k].azimuthDeg)) + " deg) is out of the " + arm.title() +
                  "'s reach within its joint limits, also turned and tilted down to half" +
                  (ik.blockingJoint >= 0 ? ": " + arm.describeJoint(static_cast<unsigned>(ik.blockingJoint), ik.q) + " is in the way"
                                         : std::string(" (too far)")));
    }
    q = ik.q;
    out.push_back({name, d, q});
  }
  return out;
}

std::string describeLeftOut(const model::PassDirection &d, const std::string &armTitle)
{
  char s[160];
  std::snprintf(s, sizeof s, "view at %.0f deg toward %.0f deg: out of the %s's reach, left out of the pass", d.tiltDeg, d.azimuthDeg,
                armTitle.c_str());
  return s;
}

} // namespace pm::robot
