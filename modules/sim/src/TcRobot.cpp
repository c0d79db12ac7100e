#include "pm/sim/TcRobot.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::sim {

TcRobot::TcRobot(const vpHomogeneousMatrix &wMh0, const Trajectory &steps)
    : m_wMh0(wMh0), m_steps(std::make_unique<Trajectory>(steps))
{
}

TcRobot::TcRobot(const vpHomogeneousMatrix &wMh0, const core::Phi &phi0, int axis, double amplitude, double frequencyHz,
                 double maxVelocity, double maxAcceleration)
    : m_wMh0(wMh0), m_phi0(phi0), m_axis(axis), m_amp(amplitude), m_freq(frequencyHz)
{
  if (axis < 0 || axis > 5)
    throw core::Error("TC-robot: the axis must be one of x, y, z, e1, e2, e3");
  if (!(frequencyHz > 0) || !std::isfinite(amplitude) || !std::isfinite(frequencyHz))
    throw core::Error("TC-robot: the sinusoid needs a positive frequency and a finite amplitude");
  const double w = 2 * M_PI * frequencyHz;
  if (std::fabs(amplitude) * w > maxVelocity)
    throw core::Error("TC-robot: a sinusoid of amplitude " + std::to_string(amplitude) + " at " + std::to_string(frequencyHz) +
                " Hz needs a velocity of " + std::to_string(std::fabs(amplitude) * w) + ", over the limit " +
                std::to_string(maxVelocity));
  if (std::fabs(amplitude) * w * w > maxAcceleration)
    throw core::Error("TC-robot: a sinusoid of amplitude " + std::to_string(amplitude) + " at " + std::to_string(frequencyHz) +
                " Hz needs an acceleration of " + std::to_string(std::fabs(amplitude) * w * w) + ", over the limit " +
                std::to_string(maxAcceleration));
  core::Phi peak = phi0;
  peak[static_cast<std::size_t>(axis)] += std::fabs(amplitude);
  if (!peak.isValid())
    throw core::Error("TC-robot: the sinusoid leaves the valid poses (|eps| > 1)");
}

core::Phi TcRobot::phi(double t) const
{
  if (m_steps)
    return m_steps->at(t);
  core::Phi p = m_phi0;
  const double period = 1.0 / m_freq;
  const double fade = t >= period ? 1.0 : (t <= 0 ? 0.0 : 0.5 - 0.5 * std::cos(M_PI * t / period));
  p[static_cast<std::size_t>(m_axis)] += m_amp * fade * std::sin(2 * M_PI * m_freq * t);
  return p;
}

vpHomogeneousMatrix TcRobot::wMo(double t) const { return m_wMh0 * core::toHomogeneousMatrix(phi(t)); }

bool TcRobot::moving(double t) const { return m_steps ? m_steps->moving(t) : true; }

double TcRobot::duration() const { return m_steps ? m_steps->duration() : 0.0; }

} // namespace pm::sim
