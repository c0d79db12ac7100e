#include "pm/robot/Pa10Model.h"

#include <array>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::robot {

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

//! v[i] * num / den per joint (in that order, as the PA-10's figures always were computed).
vpColVector perJoint(const double (&v)[7], double num, double den)
{
  vpColVector out(7);
  for (unsigned i = 0; i < 7; ++i)
    out[i] = v[i] * num / den;
  return out;
}
} // namespace

vpHomogeneousMatrix Pa10Model::forward(const vpColVector &q)
{
  if (q.size() != kDof)
    throw core::Error("PA-10: 7 joint values expected, got " + std::to_string(q.size()));
  vpHomogeneousMatrix T;
  for (unsigned i = 0; i < kDof; ++i)
    T = T * dh(q[i], kD[i], kAlphaDeg[i] * M_PI / 180);
  return T;
}

vpHomogeneousMatrix Pa10Model::fMe(const vpColVector &q) const { return forward(q); }

vpMatrix Pa10Model::jacobianBase(const vpColVector &q)
{
  if (q.size() != kDof)
    throw core::Error("PA-10: 7 joint values expected");
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

vpMatrix Pa10Model::eJe(const vpColVector &q) const
{
  return rotateJacobian(forward(q).getRotationMatrix().t(), jacobianBase(q)); // [eRf 0; 0 eRf] fJe
}

vpColVector Pa10Model::jointMin() const { return -perJoint(kLimitDeg, M_PI, 180); }
vpColVector Pa10Model::jointMax() const { return perJoint(kLimitDeg, M_PI, 180); }
vpColVector Pa10Model::speedLimits() const { return perJoint(kSpeed, 1, 1); }
vpColVector Pa10Model::accelerationLimits() const { return speedLimits() * 5.0; }

vpColVector Pa10Model::restJoints() const
{
  return degrees({0, -35, 0, 80, 0, 45, -90});
}

} // namespace pm::robot
