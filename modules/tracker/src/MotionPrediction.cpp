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

core::Phi MotionPrediction::predict(const core::Phi &last) const
{
  // Only the latest pose remembered moves on (another, e.g. one the lock verifier jumped to, stays).
  const core::Phi remembered = core::fromHomogeneousMatrix(m_last);
  if (!moving() || core::translationDistanceMm(last, remembered) > 1e-3 || core::rotationDistanceDeg(last, remembered) > 1e-3)
    return last;
  vpHomogeneousMatrix next;
  next.insert(vpRotationMatrix(m_dR * m_last.getRotationMatrix()));
  next.insert(vpTranslationVector(m_last.getTranslationVector() + m_dt));
  const core::Phi p = core::fromHomogeneousMatrix(next);
  return p.isValid() ? p : last;
}

void MotionPrediction::remember(const TrackResult &r)
{
  if (!r.precise || r.state != TrackState::Tracking) {
    m_count = 0;
    return;
  }
  m_prev = m_last;
  m_last = r.hMo;
  m_count = m_count >= 1 ? 2 : 1;
  updateStep();
}

void MotionPrediction::transform(const vpHomogeneousMatrix &hNowMhPrev)
{
  if (m_count == 0)
    return;
  m_prev = hNowMhPrev * m_prev;
  m_last = hNowMhPrev * m_last;
  updateStep();
}

void MotionPrediction::updateStep()
{
  m_stepOk = false;
  if (m_count < 2 || !m_params.enabled())
    return;
  const vpTranslationVector dt = m_last.getTranslationVector() - m_prev.getTranslationVector();
  const vpThetaUVector turn(vpRotationMatrix(m_last.getRotationMatrix() * m_prev.getRotationMatrix().t()));
  const double stepMm = 1000.0 * std::sqrt(dt.sumSquare());
  const double turnDeg = std::sqrt(turn.sumSquare()) * 180.0 / M_PI;
  if (!(stepMm <= m_params.maxStepMm) || !(turnDeg <= m_params.maxStepDeg))
    return;
  m_dt = dt * m_params.gain;
  vpThetaUVector scaled;
  for (unsigned int k = 0; k < 3; ++k)
    scaled[k] = m_params.gain * turn[k];
  m_dR.buildFrom(scaled);
  m_stepOk = true;
}

} // namespace pm::tracker
