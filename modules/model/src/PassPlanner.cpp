#include "pm/model/PassPlanner.h"

#include <cmath>
#include <numeric>

#include <visp3/core/vpThetaUVector.h>

#include "pm/core/Error.h"

namespace pm::model {

void PassPlan::validate() const
{
  if (views < 2 || views > 200)
    throw core::Error("pass plan: views must lie in [2, 200]");
  if (ringsDeg.empty() || static_cast<int>(ringsDeg.size()) > views - 1)
    throw core::Error("pass plan: between 1 ring and one ring per view besides the rest view");
  for (double r : ringsDeg)
    if (!(r > 0 && r < 90))
      throw core::Error("pass plan: ring angles must lie in (0, 90) deg");
  if (!(distanceMm > 10 && distanceMm < 1e5))
    throw core::Error("pass plan: distance must lie in (10, 100000) mm");
}

std::vector<PassDirection> passDirections(const PassPlan &plan)
{
  plan.validate();
  std::vector<PassDirection> out{PassDirection()};
  // Views per ring in proportion to its angle (its circumference), at least one each.
  const double sum = std::accumulate(plan.ringsDeg.begin(), plan.ringsDeg.end(), 0.0);
  const int rest = plan.views - 1;
  int given = 0;
  for (std::size_t r = 0; r < plan.ringsDeg.size(); ++r) {
    const int n = r + 1 == plan.ringsDeg.size() ? rest - given
                                                : std::max(1, static_cast<int>(std::lround(rest * plan.ringsDeg[r] / sum)));
    given += n;
    for (int k = 0; k < n; ++k)
      out.push_back({plan.ringsDeg[r], 360.0 * (k + 0.5 * static_cast<double>(r)) / n});
  }
  return out;
}

vpHomogeneousMatrix passPose(const PassDirection &d, double distanceMm)
{
  const double a = d.tiltDeg * M_PI / 180, b = d.azimuthDeg * M_PI / 180;
  const vpHomogeneousMatrix toPivot(0, 0, distanceMm * 1e-3, 0, 0, 0);
  // Turned by a about the axis (-sin b, cos b, 0): the hand's z swings toward direction b.
  const vpHomogeneousMatrix turn(vpTranslationVector(0, 0, 0), vpThetaUVector(-a * std::sin(b), a * std::cos(b), 0));
  const vpHomogeneousMatrix roll(0, 0, 0, 0, 0, d.rollDeg * M_PI / 180); // about the axis through the pivot
  return toPivot * turn * toPivot.inverse() * roll;
}

std::vector<vpHomogeneousMatrix> planPass(const PassPlan &plan)
{
  std::vector<vpHomogeneousMatrix> out;
  for (const PassDirection &d : passDirections(plan))
    out.push_back(passPose(d, plan.distanceMm));
  return out;
}

} // namespace pm::model
