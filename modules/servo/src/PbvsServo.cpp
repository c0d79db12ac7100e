#include "pm/servo/PbvsServo.h"

#include <algorithm>
#include <cmath>

#include <visp3/core/vpVelocityTwistMatrix.h>
#include <visp3/vs/vpAdaptiveGain.h>

#include "pm/core/Error.h"

namespace pm::servo {

void ServoParams::validate() const
{
  if (!hdMo.isAnHomogeneousMatrix())
    throw core::Error("servo: the desired pose is not a rigid transformation");
  if (!(gainAtZero > 0 && gainAtInfinity > 0 && gainSlopeAtZero > 0) || gainAtInfinity > gainAtZero)
    throw core::Error("servo: the adaptive gain needs 0 < gain at infinity <= gain at zero and a positive slope");
  if (!(maxHandSpeed > 0 && maxHandRotation > 0))
    throw core::Error("servo: the hand's speed limits must be positive");
  if (!(feedForwardSmoothing >= 0 && feedForwardSmoothing < 1))
    throw core::Error("servo: the feed-forward smoothing must lie in [0, 1)");
}

PbvsServo::PbvsServo(const ServoParams &params) : m_params(params), m_vObj(6, 0.0)
{
  params.validate();
  m_task.setServo(vpServo::EYEINHAND_L_cVe_eJe);
  m_task.setInteractionMatrixType(vpServo::CURRENT);
  vpAdaptiveGain gain(params.gainAtZero, params.gainAtInfinity, params.gainSlopeAtZero);
  m_task.setLambda(gain);
  m_task.set_cVe(vpVelocityTwistMatrix()); // the hand frame is the flange frame
  m_task.addFeature(m_t);
  m_task.addFeature(m_tu);
}

void PbvsServo::setDesired(const vpHomogeneousMatrix &hdMo)
{
  ServoParams p = m_params;
  p.hdMo = hdMo;
  p.validate();
  m_params = p;
}

vpColVector PbvsServo::stop(unsigned dof)
{
  m_havePrev = false;
  m_vObj = 0;
  return vpColVector(dof, 0.0);
}

vpColVector PbvsServo::computeJointVelocity(const vpHomogeneousMatrix &hMo, const vpHomogeneousMatrix &fMe,
                                            const vpMatrix &eJe, const vpColVector &q, const vpColVector &qmin,
                                            const vpColVector &qmax, double dt, const vpColVector *targetTwist)
{
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 4; ++c)
      if (!std::isfinite(hMo[r][c]))
        throw core::Error("servo: the estimated pose is not finite");
  if (!hMo.isAnHomogeneousMatrix())
    throw core::Error("servo: the estimated pose is not a rigid transformation");
  const vpHomogeneousMatrix cdMc = m_params.hdMo * hMo.inverse();
  m_t.buildFrom(cdMc);
  m_tu.buildFrom(cdMc);
  m_tErr = cdMc.getTranslationVector().frobeniusNorm();
  m_rErr = cdMc.getThetaUVector().getTheta();
  m_task.set_eJe(eJe);
  vpColVector qdot = m_task.computeControlLaw();

  // Feed-forward: the target's twist in the base frame, moved to the hand (a rigid motion that keeps hMo).
  const vpHomogeneousMatrix fMo = fMe * hMo;
  if (m_params.feedForward && (targetTwist || (m_havePrev && dt > 0))) {
    // The target's twist in the base frame: given, or a finite difference of its pose.
    double lin[3], ang[3];
    if (targetTwist) {
      if (targetTwist->size() != 6)
        throw core::Error("servo: the target's twist needs 6 components");
      for (unsigned i = 0; i < 3; ++i) {
        lin[i] = (*targetTwist)[i];
        ang[i] = m_params.feedForwardRotation ? (*targetTwist)[3 + i] : 0.0;
      }
    } else {
      const vpThetaUVector tu = (fMo * m_prevFMo.inverse()).getThetaUVector();
      for (unsigned i = 0; i < 3; ++i) {
        lin[i] = (fMo[i][3] - m_prevFMo[i][3]) / dt;
        ang[i] = m_params.feedForwardRotation ? tu[i] / dt : 0.0;
      }
    }
    // The velocity of the point that will be the hand, moving rigidly with the target: v + w x (p_hand - p_obj).
    const double r[3] = {fMe[0][3] - fMo[0][3], fMe[1][3] - fMo[1][3], fMe[2][3] - fMo[2][3]};
    vpColVector v(6);
    v[0] = lin[0] + ang[1] * r[2] - ang[2] * r[1];
    v[1] = lin[1] + ang[2] * r[0] - ang[0] * r[2];
    v[2] = lin[2] + ang[0] * r[1] - ang[1] * r[0];
    for (unsigned i = 0; i < 3; ++i)
      v[3 + i] = ang[i];
    const double a = targetTwist ? 0.0 : m_params.feedForwardSmoothing;
    m_vObj = a * m_vObj + (1 - a) * v;
    // Base-frame twist of the flange -> flange-frame twist -> joints.
    const vpRotationMatrix eRf = fMe.getRotationMatrix().t();
    vpColVector ve(6);
    for (unsigned i = 0; i < 3; ++i) {
      ve[i] = 0;
      ve[3 + i] = 0;
      for (unsigned k = 0; k < 3; ++k) {
        ve[i] += eRf[i][k] * m_vObj[k];
        ve[3 + i] += eRf[i][k] * m_vObj[3 + k];
      }
    }
    qdot += eJe.pseudoInverse() * ve;
  }
  m_prevFMo = fMo;
  m_havePrev = true;
  if (m_params.jointLimitAvoidance)
    qdot += m_task.secondaryTaskJointLimitAvoidance(q, qdot, qmin, qmax);
  for (unsigned i = 0; i < qdot.size(); ++i)
    if (!std::isfinite(qdot[i]))
      throw core::Error("servo: the control law gave a non-finite velocity");
  // Safety: the hand's twist within its limits (the whole command scaled, so its direction is kept).
  const vpColVector v = eJe * qdot;
  const double lin = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  const double ang = std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
  const double k = std::min({1.0, m_params.maxHandSpeed / std::max(lin, 1e-12), m_params.maxHandRotation / std::max(ang, 1e-12)});
  return qdot * k;
}

} // namespace pm::servo
