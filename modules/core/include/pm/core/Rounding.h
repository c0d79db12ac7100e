#pragma once
/*!
  \file Rounding.h
  std::lround inline: the nearest integer, halves away from zero, to the bit, without the library
  call (two a point in a model's hottest loops: 2 % of pm-make-model's time was that call).
*/
namespace pm::core {

/*!
  The integer nearest \e x, halves away from zero: std::lround's value for every finite \e x with
  |x| < 2^63 (beyond that, or NaN, undefined, where std::lround's is unspecified). The conversion
  truncates toward zero; x minus that integer is exact in double, so the halves are decided exactly
  (x + 0.5 rounded, as a shortcut, would take 0.49999999999999994 to 1).
  \code
  const long a = pm::core::roundHalfAway(2.5), b = pm::core::roundHalfAway(-2.5); // 3 and -3
  \endcode
*/
inline long roundHalfAway(double x)
{
  const long t = static_cast<long>(x);         // toward zero
  const double f = x - static_cast<double>(t); // exact: the fraction, of x's sign
  return t + static_cast<long>(f >= 0.5) - static_cast<long>(f <= -0.5); // no branch: the halves fall either way at random
}

} // namespace pm::core
