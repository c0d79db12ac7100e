#include "pm/tracker/MotionPrediction.h"

#include <cmath>

#include <visp3/core/vpThetaUVector.h>

#include "pm/core/Error.h"

namespace pm::tracker {

void MotionPredictionParams::validate() const
{
  if (!(gain >= 0 && gain <= 1.5) || !(maxStepMm > 0) || !(maxStepDeg > 0))
    throw core::Error("motion prediction: the gain must lie in [0, 1.5] and the largest step and turn be positive");
}

MotionPrediction::MotionPrediction(const MotionPredictionParams &params) : m_params(params) { params.validate(); }

bool MotionPrediction::step(const vpHomogeneousMatrix &prev, const vpHomogeneousMatrix &last, vpTranslationVector &dt,
                            vpRotationMatrix &dR) const
{
  const vpTranslationVector d = last.getTranslationVector() - prev.getTranslationVector();
  const vpThetaUVector turn(vpRotationMatrix(last.getRotationMatrix() * prev.getRotationMatrix().t()));
  const double stepMm = 1000.0 * std::sqrt(d.sumSquare());
  const double turnDeg = std::sqrt(turn.sumSquare()) * 180.0 / M_PI;
  if (!(stepMm <= m_params.maxStepMm) || !(turnDeg <= m_params.maxStepDeg))
    return false;
  dt = d * m_params.gain;
  vpThetaUVector scaled;
  for (unsigned int k = 0; k < 3; ++k)
    scaled[k] = m_params.gain * turn[k];
  dR.buildFrom(scaled);
  return true;
}

bool MotionPrediction::moving(const PoseHistory &history) const
{
  vpTranslationVector dt;
  vpRotationMatrix dR;
  return history.preciseCount() >= 2 && m_params.enabled() && step(history.precisePrev(), history.preciseLast(), dt, dR);
}

core::Phi MotionPrediction::predict(const PoseHistory &history) const
{
  const core::Phi &last = history.last().phi;
  if (history.preciseCount() < 2 || !m_params.enabled())
    return last;
  // Only the latest precise pose moves on (another, e.g. one the lock verifier jumped to, stays).
  const vpHomogeneousMatrix &latest = history.preciseLast();
  const core::Phi remembered = core::fromHomogeneousMatrix(latest);
  if (core::translationDistanceMm(last, remembered) > 1e-3 || core::rotationDistanceDeg(last, remembered) > 1e-3)
    return last;
  vpTranslationVector dt;
  vpRotationMatrix dR;
  if (!step(history.precisePrev(), latest, dt, dR))
    return last;
  vpHomogeneousMatrix next;
  next.insert(vpRotationMatrix(dR * latest.getRotationMatrix()));
  next.insert(vpTranslationVector(latest.getTranslationVector() + dt));
  const core::Phi p = core::fromHomogeneousMatrix(next);
  return p.isValid() ? p : last;
}

} // namespace pm::tracker
