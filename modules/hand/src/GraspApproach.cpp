#include "pm/hand/GraspApproach.h"

#include <algorithm>

#include "pm/core/Error.h"

namespace pm::hand {

void GraspApproachParams::validate() const
{
  if (!(toMm > 0 && toMm < fromMm && fromMm <= 5000))
    throw core::Error("grasp approach: the distances must satisfy 0 < to < from <= 5000 mm");
  if (!(mmPerS > 0 && mmPerS <= 1000 && settleS >= 0 && settleS <= 3600))
    throw core::Error("grasp approach: its speed must lie in (0, 1000] mm/s and its settling time in [0, 3600] s");
}

GraspApproach::GraspApproach(const GraspApproachParams &params, const vpHomogeneousMatrix &hdMo0)
    : m_params(params), m_hdMo(hdMo0), m_distanceMm(params.fromMm)
{
  params.validate();
  m_hdMo[2][3] = 1e-3 * m_distanceMm;
}

void GraspApproach::advance(bool servoed, double dt)
{
  if (!servoed)
    return; // held: it waits where it is
  if (m_settledS + 1e-9 < m_params.settleS) { // servoed at the start's distance first
    m_settledS += dt;
    return;
  }
  m_distanceMm = std::max(m_params.toMm, m_distanceMm - m_params.mmPerS * dt);
  m_hdMo[2][3] = 1e-3 * m_distanceMm;
}

} // namespace pm::hand
