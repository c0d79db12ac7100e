#include "pm/tracker/TiltFilter.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::tracker {

void TiltFilterParams::validate() const
{
  if (!(alpha > 0 && alpha <= 1) || !(beta >= 0 && beta < 1) || !(gateDeg > 0 && std::isfinite(gateDeg)))
    throw core::Error("tilt filter: alpha must lie in (0, 1], beta in [0, 1) and the gate be a positive angle");
}

TiltFilter::TiltFilter(const TiltFilterParams &params) : m_p(params) { params.validate(); }

namespace {
//! The rotation vector (rad, hand frame) r with R(a) = exp(r) R(b).
void rotationFromTo(const core::Phi &b, const core::Phi &a, double r[3])
{
  // q = q_a (x) conj(q_b): its vector part and scalar part.
  const double wa = a.eta(), wb = b.eta();
  const double w = wa * wb + a.e1 * b.e1 + a.e2 * b.e2 + a.e3 * b.e3;
  const double v[3] = {wb * a.e1 - wa * b.e1 - (a.e2 * b.e3 - a.e3 * b.e2), wb * a.e2 - wa * b.e2 - (a.e3 * b.e1 - a.e1 * b.e3),
                       wb * a.e3 - wa * b.e3 - (a.e1 * b.e2 - a.e2 * b.e1)};
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  const double angle = n > 0 ? 2.0 * std::atan2(n, std::fabs(w)) * (w < 0 ? -1.0 : 1.0) : 0.0;
  for (int k = 0; k < 3; ++k)
    r[k] = n > 0 ? angle * v[k] / n : 0.0;
}
} // namespace

core::Phi TiltFilter::update(const core::Phi &measured)
{
  if (!measured.isValid())
    throw core::Error("tilt filter: invalid pose " + measured.toString());
  if (m_p.passesThrough())
    return measured;
  if (m_has) {
    const double turn[6] = {0, 0, 0, m_w[0], m_w[1], 0};
    const core::Phi predicted = core::applyTwist(m_pose, turn);
    double r[3];
    rotationFromTo(predicted, measured, r);
    if (std::sqrt(r[0] * r[0] + r[1] * r[1]) * 180.0 / M_PI <= m_p.gateDeg) { // the tilt's residual
      const double correction[6] = {0, 0, 0, m_p.alpha * r[0], m_p.alpha * r[1], r[2]};
      core::Phi out = core::applyTwist(predicted, correction);
      out.x = measured.x;
      out.y = measured.y;
      out.z = measured.z;
      m_w[0] += m_p.beta * r[0];
      m_w[1] += m_p.beta * r[1];
      m_pose = out;
      return out;
    }
  }
  m_has = true;
  m_w[0] = m_w[1] = 0;
  m_pose = measured;
  return measured;
}

void TiltFilter::transform(const vpHomogeneousMatrix &hNowMhPrev)
{
  if (!m_has)
    return;
  const core::Phi moved = core::fromHomogeneousMatrix(hNowMhPrev * core::toHomogeneousMatrix(m_pose));
  if (!moved.isValid()) {
    reset();
    return;
  }
  m_pose = moved;
  // The velocity is a rotation vector in the hand frame: turned with the hand.
  const vpRotationMatrix R = hNowMhPrev.getRotationMatrix();
  const double w0 = m_w[0], w1 = m_w[1];
  m_w[0] = R[0][0] * w0 + R[0][1] * w1;
  m_w[1] = R[1][0] * w0 + R[1][1] * w1;
}

} // namespace pm::tracker
