#include "pm/core/HuePlane.h"

#include <algorithm>
#include <cmath>

namespace pm {

namespace {
// Branch-free hue in tenths of a degree; the compiler vectorises the loop that calls it.
inline std::uint16_t hueOf(int r, int g, int b, float minSat)
{
  const int mx = std::max(r, std::max(g, b)), mn = std::min(r, std::min(g, b)), d = mx - mn;
  const float fd = d > 0 ? static_cast<float>(d) : 1.f;
  // Sector offset and signed numerator of the standard formula (max = r, g, b in that order).
  const float num = mx == r ? static_cast<float>(g - b) : (mx == g ? static_cast<float>(b - r) : static_cast<float>(r - g));
  const float off = mx == r ? 0.f : (mx == g ? 2.f : 4.f);
  float h = (off + num / fd) * 600.f;
  h = h < 0.f ? h + 3600.f : h;
  int q = static_cast<int>(h + 0.5f);
  q = q >= 3600 ? q - 3600 : q;
  const bool grey = d == 0 || static_cast<float>(d) < minSat * static_cast<float>(mx);
  return grey ? (minSat > 0.f ? HuePlane::kNoHue : std::uint16_t(0)) : static_cast<std::uint16_t>(q);
}
} // namespace

std::uint16_t hueDeci(const vpRGBa &c, float minSaturation) { return hueOf(c.R, c.G, c.B, minSaturation); }

void HuePlane::compute(const vpImage<vpRGBa> &I, float minSaturation)
{
  m_w = I.getWidth();
  m_h = I.getHeight();
  const std::size_t n = static_cast<std::size_t>(m_w) * m_h;
  if (m_hue.size() != n + 2)
    m_hue.assign(n + 2, kNoHue); // +2: padding for 32-bit gathers at the last pixel
  const vpRGBa *src = I.bitmap;
  std::uint16_t *dst = m_hue.data();
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i)
    dst[i] = hueOf(src[i].R, src[i].G, src[i].B, minSaturation);
}

} // namespace pm
