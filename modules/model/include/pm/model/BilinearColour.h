#pragma once
/*!
  \file BilinearColour.h
  A photo's colour between its pixels, for the model builder's readings across an outline
  (SubpixelOutline.h, EdgeBlur.h).

  \code
      const std::array<double, 3> rgb = pm::model::bilinearColour(photo, 120.25, 64.5);
  \endcode
*/
#include <algorithm>
#include <array>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::model {

//! The colour of \e im (at least 2 x 2) at column \e u, row \e v: bilinear, the image's border repeated.
inline std::array<double, 3> bilinearColour(const vpImage<vpRGBa> &im, double u, double v)
{
  const int w = static_cast<int>(im.getWidth()), h = static_cast<int>(im.getHeight());
  u = std::clamp(u, 0.0, w - 1.0), v = std::clamp(v, 0.0, h - 1.0);
  const int x = std::min(static_cast<int>(u), w - 2), y = std::min(static_cast<int>(v), h - 2);
  const double fu = u - x, fv = v - y;
  const vpRGBa &a = im[y][x], &b = im[y][x + 1], &c = im[y + 1][x], &d = im[y + 1][x + 1];
  auto mix = [&](double pa, double pb, double pc, double pd) {
    return (1 - fv) * ((1 - fu) * pa + fu * pb) + fv * ((1 - fu) * pc + fu * pd);
  };
  return {mix(a.R, b.R, c.R, d.R), mix(a.G, b.G, c.G, d.G), mix(a.B, b.B, c.B, d.B)};
}

} // namespace pm::model
