#include "pm/sim/Trajectory.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::sim {

Trajectory::Trajectory(std::vector<core::Phi> waypoints, double holdS, double moveS)
    : m_points(std::move(waypoints)), m_hold(holdS), m_move(moveS)
{
  if (m_points.empty())
    throw core::Error("trajectory: no waypoint");
  if (!(holdS >= 0) || !(moveS > 0) || !std::isfinite(holdS) || !std::isfinite(moveS))
    throw core::Error("trajectory: the hold time must be >= 0 and the move time > 0 seconds");
  for (const auto &p : m_points)
    if (!p.isValid())
      throw core::Error("trajectory: invalid waypoint " + p.toString());
}

double Trajectory::duration() const { return static_cast<double>(m_points.size()) * m_hold + static_cast<double>(m_points.size() - 1) * m_move; }

int Trajectory::stepAt(double t) const
{
  const double period = m_hold + m_move;
  const int k = static_cast<int>(std::floor(std::max(0.0, t) / period));
  return std::min(k, static_cast<int>(m_points.size()) - 1);
}

bool Trajectory::moving(double t) const
{
  const int k = stepAt(t);
  const double local = t - k * (m_hold + m_move);
  return k + 1 < static_cast<int>(m_points.size()) && local > m_hold;
}

core::Phi Trajectory::at(double t) const
{
  const int k = stepAt(t);
  const double local = t - k * (m_hold + m_move);
  if (k + 1 >= static_cast<int>(m_points.size()) || local <= m_hold)
    return m_points[static_cast<std::size_t>(k)];
  const double tau = std::min(1.0, (local - m_hold) / m_move);
  const double s = tau * tau * tau * (10 - 15 * tau + 6 * tau * tau);
  const core::Phi &a = m_points[static_cast<std::size_t>(k)], &b = m_points[static_cast<std::size_t>(k + 1)];
  core::Phi p;
  for (std::size_t i = 0; i < 6; ++i)
    p[i] = a[i] + (b[i] - a[i]) * s;
  return p;
}

} // namespace pm::sim
