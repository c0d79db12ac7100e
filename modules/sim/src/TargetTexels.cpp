#include "TargetTexels.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "pm/core/Hue.h"

namespace pm::sim::catalog {

TargetShape targetGrid(const TargetInfo &info, double texelMm, double marginMm, bool underside)
{
  TargetShape s;
  s.info = info;
  s.texelMm = texelMm;
  s.cols = static_cast<int>(std::ceil((info.widthMm + 2 * marginMm) / texelMm));
  s.rows = static_cast<int>(std::ceil((info.heightMm + 2 * marginMm) / texelMm));
  s.originCol = (s.cols - 1) / 2.0;
  s.originRow = (s.rows - 1) / 2.0;
  const std::size_t n = static_cast<std::size_t>(s.cols) * static_cast<std::size_t>(s.rows);
  s.rgb.assign(3 * n, 0);
  s.sdf.assign(n, 0.f);
  s.height.assign(n, 0.f);
  if (underside)
    s.base.assign(n, 0.f);
  return s;
}

void setTexel(TargetShape &s, std::size_t k, const Hsv3 &c)
{
  double rgb[3];
  core::hsvToRgb(c.h, c.s, c.v, rgb);
  for (int ch = 0; ch < 3; ++ch)
    s.rgb[3 * k + static_cast<std::size_t>(ch)] = static_cast<std::uint8_t>(std::lround(std::clamp(rgb[ch], 0.0, 1.0) * 255));
}

} // namespace pm::sim::catalog
