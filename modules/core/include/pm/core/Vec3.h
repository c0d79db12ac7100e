#pragma once
/*!
  \file Vec3.h
  A point or a direction in millimetres, and the few operations on it that the cameras' projection
  and the model builders use.

  \code
      const pm::core::Vec3 a{0, 0, 500}, b{10, 0, 500};
      const double d = std::sqrt(pm::core::dot(pm::core::sub(b, a), pm::core::sub(b, a))); // 10 mm
  \endcode
*/
#include <array>
#include <cmath>

namespace pm::core {

using Vec3 = std::array<double, 3>; //!< a point or direction (mm)

inline Vec3 sub(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }   //!< a - b
inline Vec3 add(const Vec3 &a, const Vec3 &b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }   //!< a + b
inline Vec3 scaled(const Vec3 &a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }              //!< s a
inline double dot(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; } //!< a . b
//! a x b
inline Vec3 cross(const Vec3 &a, const Vec3 &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
//! a / |a| (z when a is 0)
inline Vec3 unit(const Vec3 &a)
{
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? Vec3{a[0] / n, a[1] / n, a[2] / n} : Vec3{0, 0, 1};
}

} // namespace pm::core
