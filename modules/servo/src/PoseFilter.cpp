#include "pm/servo/PoseFilter.h"

#include "pm/core/Error.h"

namespace pm::servo {

void PoseFilterParams::validate() const
{
  for (double a : {alphaT, alphaR})
    if (!(a > 0 && a <= 1))
      throw core::Error("pose filter: alpha must lie in (0, 1]");
  for (double b : {betaT, betaR})
    if (!(b >= 0 && b < 2))
      throw core::Error("pose filter: beta must lie in [0, 2)");
}

PoseFilter::PoseFilter(const PoseFilterParams &p) : m_p(p) { p.validate(); }

const vpHomogeneousMatrix &PoseFilter::update(const vpHomogeneousMatrix &z, double dt)
{
  if (!m_init || !(dt > 0)) {
    m_pose = z;
    for (int i = 0; i < 3; ++i)
      m_v[i] = m_w[i] = 0;
    m_init = true;
    return m_pose;
  }
  // Predict with the current twist.
  vpTranslationVector t = m_pose.getTranslationVector();
  for (unsigned i = 0; i < 3; ++i)
    t[i] += m_v[i] * dt;
  const vpRotationMatrix Rp = vpRotationMatrix(vpThetaUVector(m_w[0] * dt, m_w[1] * dt, m_w[2] * dt)) * m_pose.getRotationMatrix();
  // Correct.
  const vpTranslationVector zt = z.getTranslationVector();
  const vpThetaUVector rr(z.getRotationMatrix() * Rp.t()); // rotation residual, fixed frame
  for (unsigned i = 0; i < 3; ++i) {
    const double r = zt[i] - t[i];
    t[i] += m_p.alphaT * r;
    m_v[i] += m_p.betaT / dt * r;
    m_w[i] += m_p.betaR / dt * rr[i];
  }
  const vpRotationMatrix R = vpRotationMatrix(vpThetaUVector(m_p.alphaR * rr[0], m_p.alphaR * rr[1], m_p.alphaR * rr[2])) * Rp;
  m_pose.buildFrom(t, R);
  return m_pose;
}

vpColVector PoseFilter::twist() const
{
  vpColVector v(6);
  for (unsigned i = 0; i < 3; ++i) {
    v[i] = m_v[i];
    v[3 + i] = m_w[i];
  }
  return v;
}

} // namespace pm::servo
