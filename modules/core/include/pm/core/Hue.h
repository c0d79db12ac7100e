#pragma once
/*!
  \file Hue.h
  Hue, saturation and value of the HSV colour model, hue in degrees [0, 360).
  Same definition as vpImageConvert::RGBaToHSV (which gives H in [0, 1)), without its
  double-precision image pass. Hue distances wrap around: 0 and 359 degrees are 1 apart.
*/
#include <algorithm>
#include <cmath>
#include <vector>

#include <visp3/core/vpRGBa.h>

namespace pm::core {

/*!
  A colour in the HSV model (see Hue.h): hue in degrees, saturation and value in [0, 1].
  \code
  const pm::core::Hsv c = pm::core::rgbToHsv(255, 128, 0);                  // orange: h = 30.1 deg, s = 1, v = 1
  const float d = pm::core::hueDistance(c.h, pm::core::hueDeg(vpRGBa(255, 0, 0))); // 30.1 deg from red
  \endcode
*/
struct Hsv
{
  float h; //!< degrees in [0, 360); 0 for grey (s == 0)
  float s; //!< [0, 1]
  float v; //!< [0, 1]
};

//! HSV of an 8-bit RGB colour: s = (max - min) / max, v = max / 255, h in degrees (0 for grey).
inline Hsv rgbToHsv(unsigned char r, unsigned char g, unsigned char b)
{
  const int mx = std::max(r, std::max(g, b));
  const int mn = std::min(r, std::min(g, b));
  const int d = mx - mn;
  Hsv o{0.f, mx == 0 ? 0.f : static_cast<float>(d) / static_cast<float>(mx), static_cast<float>(mx) / 255.f};
  if (d == 0)
    return o;
  const float fd = static_cast<float>(d);
  float h;
  if (mx == r)
    h = static_cast<float>(g - b) / fd;
  else if (mx == g)
    h = 2.f + static_cast<float>(b - r) / fd;
  else
    h = 4.f + static_cast<float>(r - g) / fd;
  h *= 60.f;
  if (h < 0.f)
    h += 360.f;
  if (h >= 360.f)
    h -= 360.f;
  o.h = h;
  return o;
}

/*!
  The colour of hue \e h (degrees, any: taken modulo 360), saturation \e s and value \e v (each
  clamped to [0, 1]) as R, G, B in [0, 1]: rgbToHsv()'s inverse, in doubles.
*/
inline void hsvToRgb(double h, double s, double v, double rgb[3])
{
  const double hh = std::fmod(std::fmod(h, 360.0) + 360.0, 360.0) / 60.0;
  s = std::clamp(s, 0.0, 1.0);
  v = std::clamp(v, 0.0, 1.0);
  const int i = static_cast<int>(std::floor(hh)) % 6;
  const double f = hh - std::floor(hh), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  const double tab[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
  rgb[0] = tab[i][0], rgb[1] = tab[i][1], rgb[2] = tab[i][2];
}

//! HSV of a ViSP pixel (its alpha ignored).
inline Hsv rgbToHsv(const vpRGBa &c) { return rgbToHsv(c.R, c.G, c.B); }
//! Hue of a ViSP pixel in degrees [0, 360); 0 for grey.
inline float hueDeg(const vpRGBa &c) { return rgbToHsv(c).h; }

//! Distance between two hues on the circle, in [0, 180].
inline float hueDistance(float a, float b)
{
  float d = std::fabs(a - b);
  if (d >= 360.f)
    d = std::fmod(d, 360.f);
  return d > 180.f ? 360.f - d : d;
}

//! \e a - \e b on the circle, in (-180, 180] degrees: how far and which way hue \e a lies from \e b.
inline double hueDifference(double a, double b)
{
  const double d = a - b;
  return d - 360.0 * std::ceil((d - 180.0) / 360.0);
}

//! \e h brought onto [0, 360) degrees.
inline double hueOnCircle(double h)
{
  const double w = std::fmod(h, 360.0);
  return w < 0 ? (w + 360.0 >= 360.0 ? 0.0 : w + 360.0) : w;
}

//! Mean of hues on the circle (degrees in [0, 360)); 0 for an empty or balanced set.
inline float circularMeanHue(const std::vector<float> &hues)
{
  double sx = 0, sy = 0;
  for (float h : hues) {
    const double r = static_cast<double>(h) * M_PI / 180.0;
    sx += std::cos(r);
    sy += std::sin(r);
  }
  if (hues.empty() || (std::fabs(sx) < 1e-12 && std::fabs(sy) < 1e-12))
    return 0.f;
  double m = std::atan2(sy, sx) * 180.0 / M_PI;
  if (m < 0)
    m += 360.0;
  return static_cast<float>(m >= 360.0 ? 0.0 : m);
}

} // namespace pm::core
