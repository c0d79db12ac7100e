#include "pm/sim/RobotPA10.h"

#include <algorithm>
#include <cmath>

#include <visp3/core/vpThetaUVector.h>
#include <visp3/core/vpVelocityTwistMatrix.h>

#include "pm/core/Error.h"

namespace pm::sim {

namespace {
constexpr double kD[7] = {0.317, 0, 0.450, 0, 0.480, 0, 0.070};
constexpr double kAlphaDeg[7] = {-90, 90, -90, 90, -90, 90, 0};
constexpr double kLimitDeg[7] = {177, 94, 174, 137, 255, 165, 255};
constexpr double kSpeed[7] = {1, 1, 2, 2, 2 * M_PI, 2 * M_PI, 2 * M_PI};

//! Standard DH link transform: Rz(theta) Tz(d) Tx(a = 0) Rx(alpha).
vpHomogeneousMatrix dh(double theta, double d, double alpha)
{
  const double ct = std::cos(theta), st = std::sin(theta), ca = std::cos(alpha), sa = std::sin(alpha);
  vpHomogeneousMatrix T;
  T[0][0] = ct, T[0][1] = -st * ca, T[0][2] = st * sa, T[0][3] = 0;
  T[1][0] = st, T[1][1] = ct * ca, T[1][2] = -ct * sa, T[1][3] = 0;
  T[2][0] = 0, T[2][1] = sa, T[2][2] = ca, T[2][3] = d;
  return T;
}
} // namespace

RobotPA10::RobotPA10() : m_q(kDof, 0.0), m_qdot(kDof, 0.0), m_prevQ(kDof, 0.0)
{
  nDof = kDof;
  eJeAvailable = true;
  fJeAvailable = true;
  areJointLimitsAvailable = true;
  qmin = new double[kDof];
  qmax = new double[kDof];
  for (int i = 0; i < kDof; ++i) {
    qmin[i] = -kLimitDeg[i] * M_PI / 180;
    qmax[i] = kLimitDeg[i] * M_PI / 180;
  }
  setSamplingTime(0.002); // the PA-10's servo cycle
  init();
}

void RobotPA10::init()
{
  m_q = 0;
  m_qdot = 0;
  m_prevQ = 0;
  m_limitHits = 0;
}

vpHomogeneousMatrix RobotPA10::forward(const vpColVector &q)
{
  if (q.size() != kDof)
    throw Error("PA-10: 7 joint values expected, got " + std::to_string(q.size()));
  vpHomogeneousMatrix T;
  for (unsigned i = 0; i < kDof; ++i)
    T = T * dh(q[i], kD[i], kAlphaDeg[i] * M_PI / 180);
  return T;
}

bool RobotPA10::inverse(const vpHomogeneousMatrix &fMe, const vpColVector &seed, vpColVector &q, double marginDeg)
{
  if (seed.size() != kDof)
    throw Error("PA-10: 7 joint values expected for the seed");
  q = seed;
  double lo[kDof], hi[kDof];
  for (int i = 0; i < kDof; ++i) {
    hi[i] = (kLimitDeg[i] - marginDeg) * M_PI / 180;
    lo[i] = -hi[i];
    q[i] = std::min(hi[i], std::max(lo[i], q[i]));
  }
  const vpTranslationVector td = fMe.getTranslationVector();
  const vpRotationMatrix Rd = fMe.getRotationMatrix();
  for (int it = 0; it < 400; ++it) {
    const vpHomogeneousMatrix T = forward(q);
    // The error as a base-frame twist: translation, and the rotation Rd R^T as theta-u.
    const vpTranslationVector dt = td - T.getTranslationVector();
    const vpThetaUVector dr(Rd * T.getRotationMatrix().t());
    const double ep = std::sqrt(dt.sumSquare()), er = std::sqrt(dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2]);
    if (ep < 1e-4 && er < 1e-2 * M_PI / 180)
      return true;
    vpColVector e(6);
    const double maxStep = 0.05; // m and rad per iteration
    const double s = std::min(1.0, maxStep / std::max(ep, er));
    for (int k = 0; k < 3; ++k) {
      e[k] = s * dt[k];
      e[3 + k] = s * dr[k];
    }
    const vpMatrix J = jacobianBase(q);
    // dq = J^T (J J^T + lambda^2 I)^-1 e
    vpMatrix A = J * J.t();
    const double lambda2 = 1e-4;
    for (unsigned k = 0; k < 6; ++k)
      A[k][k] += lambda2;
    const vpMatrix Jp = J.t() * A.inverseByLU();
    vpColVector dq = Jp * e;
    // The redundancy: toward the seed in the null space of J, so that the arm stays near where it started.
    vpColVector toSeed(kDof);
    for (int i = 0; i < kDof; ++i)
      toSeed[i] = ep > 1e-3 ? 0.1 * (seed[i] - q[i]) : 0.0; // near the goal: the goal alone
    dq += toSeed - Jp * (J * toSeed);
    for (int i = 0; i < kDof; ++i)
      q[i] = std::min(hi[i], std::max(lo[i], q[i] + dq[i]));
  }
  return false;
}

vpMatrix RobotPA10::jacobianBase(const vpColVector &q)
{
  if (q.size() != kDof)
    throw Error("PA-10: 7 joint values expected");
  // Joint i turns about z_{i-1} through p_{i-1} (frames of the DH chain).
  std::array<vpHomogeneousMatrix, kDof + 1> T;
  for (unsigned i = 0; i < kDof; ++i)
    T[i + 1] = T[i] * dh(q[i], kD[i], kAlphaDeg[i] * M_PI / 180);
  const vpTranslationVector pe = T[kDof].getTranslationVector();
  vpMatrix J(6, kDof);
  for (unsigned i = 0; i < kDof; ++i) {
    const double z[3] = {T[i][0][2], T[i][1][2], T[i][2][2]};
    const double r[3] = {pe[0] - T[i][0][3], pe[1] - T[i][1][3], pe[2] - T[i][2][3]};
    J[0][i] = z[1] * r[2] - z[2] * r[1];
    J[1][i] = z[2] * r[0] - z[0] * r[2];
    J[2][i] = z[0] * r[1] - z[1] * r[0];
    J[3][i] = z[0];
    J[4][i] = z[1];
    J[5][i] = z[2];
  }
  return J;
}

void RobotPA10::get_fJe(vpMatrix &fJe_) { fJe_ = jacobianBase(m_q); }

void RobotPA10::get_eJe(vpMatrix &eJe_)
{
  // eJe = [eRf 0; 0 eRf] fJe
  const vpRotationMatrix eRf = fMe().getRotationMatrix().t();
  const vpMatrix J = jacobianBase(m_q);
  eJe_.resize(6, kDof);
  for (unsigned c = 0; c < kDof; ++c)
    for (unsigned blk = 0; blk < 2; ++blk)
      for (unsigned r = 0; r < 3; ++r) {
        double s = 0;
        for (unsigned k = 0; k < 3; ++k)
          s += eRf[r][k] * J[3 * blk + k][c];
        eJe_[3 * blk + r][c] = s;
      }
}

void RobotPA10::getPosition(const vpRobot::vpControlFrameType frame, vpColVector &q)
{
  if (frame == vpRobot::JOINT_STATE) {
    q = m_q;
    return;
  }
  const vpHomogeneousMatrix M = fMe();
  const vpTranslationVector t = M.getTranslationVector();
  const vpThetaUVector tu = M.getThetaUVector();
  q.resize(6);
  for (unsigned i = 0; i < 3; ++i) {
    q[i] = t[i];
    q[i + 3] = tu[i];
  }
}

void RobotPA10::setPosition(const vpRobot::vpControlFrameType frame, const vpColVector &q)
{
  if (frame != vpRobot::JOINT_STATE)
    throw Error("PA-10: setPosition takes joint values (JOINT_STATE)");
  if (q.size() != kDof)
    throw Error("PA-10: 7 joint values expected");
  for (unsigned i = 0; i < kDof; ++i) {
    if (!std::isfinite(q[i]))
      throw Error("PA-10: joint value not finite");
    m_q[i] = std::min(qmax[i], std::max(qmin[i], q[i]));
  }
  m_prevQ = m_q;
  m_qdot = 0;
}

void RobotPA10::setVelocity(const vpRobot::vpControlFrameType frame, const vpColVector &vel)
{
  vpColVector qd;
  if (frame == vpRobot::JOINT_STATE) {
    if (vel.size() != kDof)
      throw Error("PA-10: 7 joint velocities expected");
    qd = vel;
  } else if (frame == vpRobot::END_EFFECTOR_FRAME || frame == vpRobot::CAMERA_FRAME) {
    if (vel.size() != 6)
      throw Error("PA-10: a 6-component twist expected");
    vpMatrix J;
    get_eJe(J);
    qd = J.pseudoInverse() * vel;
  } else {
    throw Error("PA-10: velocity in joint space or in the end-effector frame only");
  }
  // Over a joint's speed limit, the whole command is scaled down: the motion keeps its direction.
  double scale = 1.0;
  for (unsigned i = 0; i < kDof; ++i) {
    if (!std::isfinite(qd[i]))
      throw Error("PA-10: a commanded joint velocity is not finite");
    scale = std::min(scale, kSpeed[i] / std::max(std::fabs(qd[i]), 1e-12));
  }
  m_qdot = qd * scale;
}

void RobotPA10::step(double dt)
{
  for (unsigned i = 0; i < kDof; ++i) {
    double q = m_q[i] + m_qdot[i] * dt;
    if (q > qmax[i] || q < qmin[i]) {
      q = std::min(qmax[i], std::max(qmin[i], q));
      m_qdot[i] = 0;
      ++m_limitHits;
    }
    m_q[i] = q;
  }
}

void RobotPA10::getDisplacement(const vpRobot::vpControlFrameType frame, vpColVector &d)
{
  if (frame != vpRobot::JOINT_STATE)
    throw Error("PA-10: displacement in joint space only");
  d = m_q - m_prevQ;
  m_prevQ = m_q;
}

vpColVector RobotPA10::jointMin() const
{
  vpColVector v(kDof);
  for (unsigned i = 0; i < kDof; ++i)
    v[i] = qmin[i];
  return v;
}

vpColVector RobotPA10::jointMax() const
{
  vpColVector v(kDof);
  for (unsigned i = 0; i < kDof; ++i)
    v[i] = qmax[i];
  return v;
}

vpColVector RobotPA10::speedLimits() const
{
  vpColVector v(kDof);
  for (unsigned i = 0; i < kDof; ++i)
    v[i] = kSpeed[i];
  return v;
}

vpColVector RobotPA10::accelerationLimits() const { return speedLimits() * 5.0; }

} // namespace pm::sim
