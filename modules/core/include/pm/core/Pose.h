#pragma once
/*!
  \file Pose.h
  The pose parameter of the paper, phi = [x, y, z, eps1, eps2, eps3] (Eqs. 1, 6, 7).

  Position in millimetres (the paper's unit), orientation as the vector part of a unit
  quaternion q = {eta, eps} with eta = sqrt(1 - |eps|^2) >= 0. ViSP's matrices are in metres,
  so toHomogeneousMatrix() divides the position by 1000 and fromHomogeneousMatrix() multiplies.
  phi is the pose of the model frame M in the hand frame H: it is hMo in ViSP's notation.
*/
#include <array>
#include <cmath>
#include <string>

#include <visp3/core/vpHomogeneousMatrix.h>

namespace pm::core {

/*!
  The pose phi = [x, y, z, eps1, eps2, eps3] of the model frame M in the hand frame H, hMo (see
  Pose.h): position in mm, orientation as the vector part of a unit quaternion (eta >= 0). The
  default is the identity at the hand's origin.
  \code
  pm::core::Phi phi;
  phi.z = 500;                                       // 500 mm ahead of the hand
  phi.e3 = std::sin(0.5 * vpMath::rad(30));          // turned 30 deg about the hand's z axis
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix(phi); // translation in metres
  const pm::core::StereoRig rig = pm::core::StereoRig::symmetric(vpCameraParameters(800, 800, 320, 240), 640, 480, 0.1, 0.0);
  const vpHomogeneousMatrix cMo = rig.left.cMh() * hMo;         // the model in the left camera
  const pm::core::Phi back = pm::core::fromHomogeneousMatrix(hMo);
  std::cout << back.toString() << ", " << pm::core::rotationDistanceDeg(phi, back) << " deg apart\n";
  \endcode
*/
struct Phi
{
  /*! \var Phi::x
      \brief x of the position (mm)
      \var Phi::y
      \brief y of the position (mm) */
  double x = 0, y = 0, z = 0;          //!< z of the position (mm)
  /*! \var Phi::e1
      \brief eps1, first of the quaternion vector part eps (|eps| <= 1)
      \var Phi::e2
      \brief eps2, second of the quaternion vector part eps */
  double e1 = 0, e2 = 0, e3 = 0;       //!< eps3, third of the quaternion vector part eps

  //! Number of variables.
  static constexpr std::size_t size = 6;
  //! Variable \e i (0..5: x, y, z, e1, e2, e3), for code that loops over them.
  double &operator[](std::size_t i) { return (&x)[i]; }
  //! Variable \e i (0..5: x, y, z, e1, e2, e3).
  double operator[](std::size_t i) const { return (&x)[i]; }

  //! eps . eps
  double epsNorm2() const { return e1 * e1 + e2 * e2 + e3 * e3; }
  //! Scalar part eta >= 0; only meaningful when isValid().
  double eta() const { return std::sqrt(std::max(0.0, 1.0 - epsNorm2())); }
  //! All six finite and |eps| <= 1.
  bool isValid() const;
  //! "[x, y, z, e1, e2, e3]", for messages.
  std::string toString() const;
};

//! A row-major 3x3 rotation matrix.
using Rot3 = std::array<double, 9>;
/*!
  The rotation hRo of \e p, Eq. (7), row-major, filled without allocation (hot path). \e p is not
  checked: for |eps| > 1 (eta taken as 0) the result is not a rotation.
*/
inline Rot3 rotationOf(const Phi &p)
{
  const double e1 = p.e1, e2 = p.e2, e3 = p.e3, n = p.eta();
  return {1 - 2 * (e2 * e2 + e3 * e3), 2 * (e1 * e2 - n * e3),       2 * (e1 * e3 + n * e2),
          2 * (e1 * e2 + n * e3),       1 - 2 * (e1 * e1 + e3 * e3), 2 * (e2 * e3 - n * e1),
          2 * (e1 * e3 - n * e2),       2 * (e2 * e3 + n * e1),       1 - 2 * (e1 * e1 + e2 * e2)};
}

//! phi -> hMo (metres). Throws pm::core::Error if phi is not valid (|eps| > 1 or not finite).
vpHomogeneousMatrix toHomogeneousMatrix(const Phi &phi);
//! The same into \e hMo, whose storage is kept (no allocation).
void toHomogeneousMatrix(const Phi &phi, vpHomogeneousMatrix &hMo);
/*!
  \e phi moved by a small motion \e twist of the model about its own origin, expressed in the hand
  frame: the origin moves by (twist[0], twist[1], twist[2]) mm and the model turns by the rotation
  vector (twist[3], twist[4], twist[5]) (rad): hMo' = [exp(w) R, t + v]. The result has eta >= 0.
*/
Phi applyTwist(const Phi &phi, const double twist[6]);
//! Distance between the positions of \e a and \e b (mm).
double translationDistanceMm(const Phi &a, const Phi &b);
//! Angle of the rotation between the orientations of \e a and \e b (deg, in [0, 180]).
double rotationDistanceDeg(const Phi &a, const Phi &b);

//! hMo (metres) -> phi with eta >= 0. Throws pm::core::Error if hMo is not a rigid transformation.
Phi fromHomogeneousMatrix(const vpHomogeneousMatrix &hMo);

} // namespace pm::core
