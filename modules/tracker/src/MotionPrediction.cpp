#include "pm/tracker/MotionPrediction.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::tracker {

void MotionPredictionParams::validate() const
{
  if (!(gain >= 0 && gain <= 1.5) || !(maxStepMm > 0) || !(maxStepDeg > 0))
    throw core::Error("motion prediction: the gain must lie in [0, 1.5] and the largest step and turn be positive");
}

MotionPrediction::MotionPrediction(const MotionPredictionParams &params) : m_params(params) { params.validate(); }

bool MotionPrediction::step(const core::Phi &prev, const core::Phi &last, double dtMm[3], core::Quaternion &dR) const
{
  const double d[3] = {last.x - prev.x, last.y - prev.y, last.z - prev.z};
  const core::Quaternion turn = core::quaternionOf(last) * core::quaternionOf(prev).conjugate(); // hRlast hRprev^T
  const double stepMm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const double turnDeg = turn.angle() * 180.0 / M_PI;
  if (!(stepMm <= m_params.maxStepMm) || !(turnDeg <= m_params.maxStepDeg))
    return false;
  for (int k = 0; k < 3; ++k)
    dtMm[k] = m_params.gain * d[k];
  double v[3];
  turn.rotationVector(v);
  dR = core::Quaternion::fromRotationVector(m_params.gain * v[0], m_params.gain * v[1], m_params.gain * v[2]);
  return true;
}

bool MotionPrediction::moving(const PoseHistory &history) const
{
  double dt[3];
  core::Quaternion dR;
  return history.preciseCount() >= 2 && m_params.enabled() && step(history.precisePrev(), history.preciseLast(), dt, dR);
}

core::Phi MotionPrediction::predict(const PoseHistory &history) const
{
  const core::Phi &last = history.last().phi;
  if (history.preciseCount() < 2 || !m_params.enabled())
    return last;
  // Only the latest precise pose moves on (another, e.g. one the lock verifier jumped to, stays).
  const core::Phi &latest = history.preciseLast();
  if (core::translationDistanceMm(last, latest) > 1e-3 || core::rotationDistanceDeg(last, latest) > 1e-3)
    return last;
  double dt[3];
  core::Quaternion dR;
  if (!step(history.precisePrev(), latest, dt, dR))
    return last;
  const core::Phi moved{latest.x + dt[0], latest.y + dt[1], latest.z + dt[2], 0, 0, 0};
  const core::Phi p = core::withRotation(moved, dR * core::quaternionOf(latest));
  return p.isValid() ? p : last;
}

} // namespace pm::tracker
