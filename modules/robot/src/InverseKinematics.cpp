#include "pm/robot/InverseKinematics.h"

#include <algorithm>
#include <cmath>

#include <visp3/core/vpThetaUVector.h>

namespace pm::robot {

IkResult inverseKinematics(const ArmModel &arm, const vpHomogeneousMatrix &fMe, const vpColVector &seed, double marginDeg,
                           double marginMm)
{
  arm.requireJoints(seed, "seed joint values");
  const unsigned n = arm.dof();
  const vpColVector qmin = arm.jointMin(), qmax = arm.jointMax();
  vpColVector lo(n), hi(n);
  IkResult out;
  out.q = seed;
  for (unsigned i = 0; i < n; ++i) {
    const double m = arm.prismatic(i) ? marginMm * 1e-3 : marginDeg * M_PI / 180;
    lo[i] = qmin[i] + m;
    hi[i] = qmax[i] - m;
    out.q[i] = std::min(hi[i], std::max(lo[i], out.q[i]));
  }
  vpColVector &q = out.q;
  const vpTranslationVector td = fMe.getTranslationVector();
  const vpRotationMatrix Rd = fMe.getRotationMatrix();
  vpColVector dq(n);
  for (int it = 0; it < 400; ++it) {
    const vpHomogeneousMatrix T = arm.fMe(q);
    // The error as a base-frame twist: translation, and the rotation Rd R^T as theta-u.
    const vpTranslationVector dt = td - T.getTranslationVector();
    const vpThetaUVector dr(Rd * T.getRotationMatrix().t());
    const double ep = std::sqrt(dt.sumSquare()), er = std::sqrt(dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2]);
    if (ep < 1e-4 && er < 1e-2 * M_PI / 180) {
      out.reached = true;
      return out;
    }
    vpColVector e(6);
    const double maxStep = 0.05; // m and rad per iteration
    const double s = std::min(1.0, maxStep / std::max(ep, er));
    for (int k = 0; k < 3; ++k) {
      e[k] = s * dt[k];
      e[3 + k] = s * dr[k];
    }
    const vpMatrix J = arm.fJe(q);
    // dq = J^T (J J^T + lambda^2 I)^-1 e
    vpMatrix A = J * J.t();
    const double lambda2 = 1e-4;
    for (unsigned k = 0; k < 6; ++k)
      A[k][k] += lambda2;
    const vpMatrix Jp = J.t() * A.inverseByLU();
    dq = Jp * e;
    // The redundancy: toward the seed in the null space of J, so that the arm stays near where it started.
    vpColVector toSeed(n);
    for (unsigned i = 0; i < n; ++i)
      toSeed[i] = ep > 1e-3 ? 0.1 * (seed[i] - q[i]) : 0.0; // near the goal: the goal alone
    dq += toSeed - Jp * (J * toSeed);
    for (unsigned i = 0; i < n; ++i)
      q[i] = std::min(hi[i], std::max(lo[i], q[i] + dq[i]));
  }
  // Which joint, held on its limit, the last step pushed against.
  double worst = 0;
  for (unsigned i = 0; i < n; ++i) {
    const bool atHi = q[i] >= hi[i] && dq[i] > 0, atLo = q[i] <= lo[i] && dq[i] < 0;
    const double push = std::fabs(dq[i]) / (arm.prismatic(i) ? 1e-3 : M_PI / 180); // per mm or per deg
    if ((atHi || atLo) && push > worst) {
      worst = push;
      out.blockingJoint = static_cast<int>(i);
    }
  }
  return out;
}

} // namespace pm::robot
