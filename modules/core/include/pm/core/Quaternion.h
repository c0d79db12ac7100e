#pragma once
/*!
  \file Quaternion.h
  Rotations as unit quaternions {w, x, y, z} (Hamilton's product), for the pose algebra a frame does
  (a pose turned about the model's axis, the turn between two poses carried on): values on the stack,
  no allocation, where ViSP's matrices allocate their storage on every product. The quaternion of a
  pose phi is {eta, eps} (Pose.h), and rotationOf(a * b) = rotationOf(a) rotationOf(b).

  \code
    const pm::core::Phi phi{0, 0, 500, 0.1, 0, 0};
    // The pose turned 90 deg about the model's own z axis (hRo Rz), its position kept:
    const pm::core::Phi turned = pm::core::withRotation(phi, pm::core::quaternionOf(phi) * pm::core::Quaternion::aboutZ(M_PI / 2));
    // The turn from phi to turned, and its angle (90 deg):
    const pm::core::Quaternion d = pm::core::quaternionOf(turned) * pm::core::quaternionOf(phi).conjugate();
    std::cout << d.angle() * 180 / M_PI << " deg\n";
  \endcode
*/
#include <algorithm>
#include <cmath>

#include "pm/core/Pose.h"

namespace pm::core {

//! A quaternion {w, x, y, z}; a rotation when of unit norm (see the file's description).
struct Quaternion
{
  double w = 1; //!< the scalar part
  /*! \var Quaternion::x
      \brief first of the vector part
      \var Quaternion::y
      \brief second of the vector part */
  double x = 0, y = 0, z = 0; //!< third of the vector part

  //! The rotation by \e angle (rad) about the z axis.
  static Quaternion aboutZ(double angle) { return {std::cos(0.5 * angle), 0, 0, std::sin(0.5 * angle)}; }
  //! The rotation by |\e v| (rad) about \e v / |v| (the identity for v = 0).
  static Quaternion fromRotationVector(double vx, double vy, double vz)
  {
    const double th = std::sqrt(vx * vx + vy * vy + vz * vz);
    if (th == 0)
      return {};
    const double s = std::sin(0.5 * th) / th;
    return {std::cos(0.5 * th), s * vx, s * vy, s * vz};
  }
  //! The inverse rotation (of a unit quaternion).
  Quaternion conjugate() const { return {w, -x, -y, -z}; }
  //! The rotation's angle in [0, pi] (rad), whichever of the two signs the quaternion has.
  double angle() const { return 2.0 * std::atan2(std::sqrt(x * x + y * y + z * z), std::fabs(w)); }
  /*!
    The rotation vector (axis times angle, rad) of the smaller of the two turns the quaternion
    stands for, written into \e v (zeros for the identity).
  */
  void rotationVector(double v[3]) const
  {
    const double n = std::sqrt(x * x + y * y + z * z);
    const double s = n > 0 ? (w < 0 ? -1.0 : 1.0) * angle() / n : 0.0;
    v[0] = s * x;
    v[1] = s * y;
    v[2] = s * z;
  }
};

//! Hamilton's product: the rotation \e b, then \e a (rotationOf(a * b) = rotationOf(a) rotationOf(b)).
inline Quaternion operator*(const Quaternion &a, const Quaternion &b)
{
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

//! The rotation of \e p as a quaternion {eta, eps}.
inline Quaternion quaternionOf(const Phi &p) { return {p.eta(), p.e1, p.e2, p.e3}; }

//! \e position's place with the rotation \e q (normalised, its sign chosen so that eta >= 0).
inline Phi withRotation(const Phi &position, const Quaternion &q)
{
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  const double s = (q.w < 0 ? -1.0 : 1.0) / n;
  return {position.x, position.y, position.z, s * q.x, s * q.y, s * q.z};
}

} // namespace pm::core
