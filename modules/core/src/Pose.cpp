#include "pm/core/Pose.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <visp3/core/vpQuaternionVector.h>

#include "pm/core/Error.h"

namespace pm::core {

bool Phi::isValid() const
{
  for (std::size_t i = 0; i < size; ++i)
    if (!std::isfinite((*this)[i]))
      return false;
  return epsNorm2() <= 1.0;
}

std::string Phi::toString() const
{
  std::ostringstream s;
  s << "[" << x << ", " << y << ", " << z << ", " << e1 << ", " << e2 << ", " << e3 << "]";
  return s.str();
}

vpHomogeneousMatrix toHomogeneousMatrix(const Phi &phi)
{
  vpHomogeneousMatrix M;
  toHomogeneousMatrix(phi, M);
  return M;
}

void toHomogeneousMatrix(const Phi &phi, vpHomogeneousMatrix &M)
{
  if (!phi.isValid())
    throw Error("invalid pose phi = " + phi.toString() +
                ": the quaternion vector part must have |eps| <= 1 and every value be finite");
  const Rot3 r = rotationOf(phi);
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j)
      M[i][j] = r[3 * i + j];
  M[0][3] = phi.x * 1e-3;
  M[1][3] = phi.y * 1e-3;
  M[2][3] = phi.z * 1e-3;
  M[3][0] = M[3][1] = M[3][2] = 0;
  M[3][3] = 1;
}

Phi fromHomogeneousMatrix(const vpHomogeneousMatrix &hMo)
{
  if (!hMo.isAnHomogeneousMatrix())
    throw Error("the matrix is not a rigid transformation (rotation not orthonormal)");
  vpRotationMatrix R;
  hMo.extract(R);
  vpQuaternionVector q(R); // (x, y, z, w)
  double s = q.w() < 0 ? -1.0 : 1.0;
  const double n = std::sqrt(q.x() * q.x() + q.y() * q.y() + q.z() * q.z() + q.w() * q.w());
  s /= n;
  Phi p;
  p.x = hMo[0][3] * 1e3;
  p.y = hMo[1][3] * 1e3;
  p.z = hMo[2][3] * 1e3;
  p.e1 = s * q.x();
  p.e2 = s * q.y();
  p.e3 = s * q.z();
  return p;
}

Phi applyTwist(const Phi &phi, const double twist[6])
{
  Phi q = phi;
  q.x += twist[0];
  q.y += twist[1];
  q.z += twist[2];
  const double th = std::sqrt(twist[3] * twist[3] + twist[4] * twist[4] + twist[5] * twist[5]);
  if (th == 0)
    return q;
  // q' = q_w (x) q (Hamilton; Eq. (7) is its rotation matrix, so R(q_w (x) q) = exp(w) R(q)).
  const double c = std::cos(0.5 * th), s = std::sin(0.5 * th) / th;
  const double w[3] = {s * twist[3], s * twist[4], s * twist[5]};
  const double n = phi.eta();
  double eta = c * n - (w[0] * phi.e1 + w[1] * phi.e2 + w[2] * phi.e3);
  double e1 = c * phi.e1 + n * w[0] + (w[1] * phi.e3 - w[2] * phi.e2);
  double e2 = c * phi.e2 + n * w[1] + (w[2] * phi.e1 - w[0] * phi.e3);
  double e3 = c * phi.e3 + n * w[2] + (w[0] * phi.e2 - w[1] * phi.e1);
  const double norm = std::sqrt(eta * eta + e1 * e1 + e2 * e2 + e3 * e3);
  const double sign = eta < 0 ? -1.0 : 1.0;
  q.e1 = sign * e1 / norm;
  q.e2 = sign * e2 / norm;
  q.e3 = sign * e3 / norm;
  return q;
}

double translationDistanceMm(const Phi &a, const Phi &b)
{
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

double rotationDistanceDeg(const Phi &a, const Phi &b)
{
  // The quaternions' dot product is cos(angle / 2), for either sign of each.
  const double d = std::fabs(a.eta() * b.eta() + a.e1 * b.e1 + a.e2 * b.e2 + a.e3 * b.e3);
  return 2.0 * std::acos(std::min(1.0, d)) * 180.0 / M_PI;
}

} // namespace pm::core
