#include "pm/servo/SafeCommand.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::servo {

SafeCommand::SafeCommand(const vpColVector &speedLimits, const vpColVector &accelerationLimits)
    : m_vmax(speedLimits), m_amax(accelerationLimits), m_cmd(speedLimits.size(), 0.0)
{
  if (speedLimits.size() == 0 || speedLimits.size() != accelerationLimits.size())
    throw core::Error("safe command: one speed and one acceleration limit per joint are needed");
  for (unsigned i = 0; i < speedLimits.size(); ++i)
    if (!(speedLimits[i] > 0 && std::isfinite(speedLimits[i]) && accelerationLimits[i] > 0 && std::isfinite(accelerationLimits[i])))
      throw core::Error("safe command: the speed and acceleration limits must be positive and finite");
}

const vpColVector &SafeCommand::next(const vpColVector &wanted, double dt)
{
  if (!(dt > 0) || !std::isfinite(dt))
    throw core::Error("safe command: the cycle time must be positive");
  const unsigned n = m_cmd.size();
  vpColVector target(n, 0.0);
  bool finite = wanted.size() == n;
  for (unsigned i = 0; finite && i < n; ++i)
    finite = std::isfinite(wanted[i]);
  if (finite) {
    double scale = 1;
    for (unsigned i = 0; i < n; ++i)
      scale = std::min(scale, m_vmax[i] / std::max(std::fabs(wanted[i]), 1e-300));
    target = wanted * scale;
  }
  double scale = 1;
  for (unsigned i = 0; i < n; ++i)
    scale = std::min(scale, m_amax[i] * dt * (1 + 1e-9) / std::max(std::fabs(target[i] - m_cmd[i]), 1e-300)); // (no leftover step)
  for (unsigned i = 0; i < n; ++i)
    m_cmd[i] += scale * (target[i] - m_cmd[i]);
  return m_cmd;
}

const vpColVector &SafeCommand::stop(double dt) { return next(vpColVector(m_cmd.size(), 0.0), dt); }

bool SafeCommand::stopped() const
{
  for (unsigned i = 0; i < m_cmd.size(); ++i)
    if (m_cmd[i] != 0)
      return false;
  return true;
}

} // namespace pm::servo
