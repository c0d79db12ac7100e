#include "pm/core/HuePlane.h"

#include "pm/core/Error.h"
#include "pm/core/UndistortMap.h"

#include <algorithm>
#include <cmath>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define PM_HAVE_X86 1
#endif

namespace pm::core {

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
#ifdef PM_HAVE_X86
/*!
  The same formula as hueOf, 8 pixels at a time, with the same IEEE operations in the same order
  (one division, then + sector, * 600, + 3600 if negative, + 0.5, truncation), so both agree to the bit.
*/
__attribute__((target("avx2"))) void hueAvx2(const vpRGBa *src, std::uint16_t *dst, std::size_t n, float minSat)
{
  const __m256i byte = _mm256_set1_epi32(0xff);
  const __m256 zero = _mm256_setzero_ps(), k600 = _mm256_set1_ps(600.f), k3600 = _mm256_set1_ps(3600.f);
  const __m256i noHue = _mm256_set1_epi32(minSat > 0.f ? HuePlane::kNoHue : 0);
  const __m256 vMinSat = _mm256_set1_ps(minSat);
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m256i px = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(src + i)); // R G B A bytes
    const __m256i r = _mm256_and_si256(px, byte), g = _mm256_and_si256(_mm256_srli_epi32(px, 8), byte);
    const __m256i b = _mm256_and_si256(_mm256_srli_epi32(px, 16), byte);
    const __m256i mx = _mm256_max_epi32(r, _mm256_max_epi32(g, b)), mn = _mm256_min_epi32(r, _mm256_min_epi32(g, b));
    const __m256i d = _mm256_sub_epi32(mx, mn);
    const __m256i isR = _mm256_cmpeq_epi32(mx, r), isG = _mm256_andnot_si256(isR, _mm256_cmpeq_epi32(mx, g));
    const __m256i num = _mm256_blendv_epi8(_mm256_blendv_epi8(_mm256_sub_epi32(r, g), _mm256_sub_epi32(b, r), isG),
                                           _mm256_sub_epi32(g, b), isR);
    const __m256 off = _mm256_blendv_ps(_mm256_blendv_ps(_mm256_set1_ps(4.f), _mm256_set1_ps(2.f), _mm256_castsi256_ps(isG)),
                                        zero, _mm256_castsi256_ps(isR));
    const __m256i dz = _mm256_cmpeq_epi32(d, _mm256_setzero_si256());
    const __m256 fd = _mm256_cvtepi32_ps(_mm256_blendv_epi8(d, _mm256_set1_epi32(1), dz));
    __m256 h = _mm256_mul_ps(_mm256_add_ps(off, _mm256_div_ps(_mm256_cvtepi32_ps(num), fd)), k600);
    h = _mm256_blendv_ps(h, _mm256_add_ps(h, k3600), _mm256_cmp_ps(h, zero, _CMP_LT_OQ));
    __m256i q = _mm256_cvttps_epi32(_mm256_add_ps(h, _mm256_set1_ps(0.5f)));
    q = _mm256_blendv_epi8(q, _mm256_sub_epi32(q, _mm256_set1_epi32(3600)), _mm256_cmpgt_epi32(q, _mm256_set1_epi32(3599)));
    // Grey: d == 0, or d < minSat * max.
    const __m256i low = _mm256_castps_si256(_mm256_cmp_ps(_mm256_cvtepi32_ps(d), _mm256_mul_ps(vMinSat, _mm256_cvtepi32_ps(mx)), _CMP_LT_OQ));
    q = _mm256_blendv_epi8(q, noHue, _mm256_or_si256(dz, low));
    // Pack 8 x 32-bit to 8 x 16-bit (values fit in 16 bits unsigned).
    const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(q, q), 0x08);
    _mm_storeu_si128(reinterpret_cast<__m128i *>(dst + i), _mm256_castsi256_si128(packed));
  }
  for (; i < n; ++i)
    dst[i] = hueOf(src[i].R, src[i].G, src[i].B, minSat);
}

bool cpuHasAvx2() { return __builtin_cpu_supports("avx2"); }
#endif

//! The hue of \e n consecutive pixels.
void hueRun(const vpRGBa *src, std::uint16_t *dst, std::size_t n, float minSat)
{
#ifdef PM_HAVE_X86
  static const bool avx2 = cpuHasAvx2();
  if (avx2) {
    hueAvx2(src, dst, n, minSat);
    return;
  }
#endif
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i)
    dst[i] = hueOf(src[i].R, src[i].G, src[i].B, minSat);
}

} // namespace

std::uint16_t hueDeci(const vpRGBa &c, float minSaturation) { return hueOf(c.R, c.G, c.B, minSaturation); }

PixelRect PixelRect::united(const PixelRect &o) const
{
  if (o.empty())
    return *this;
  if (empty())
    return o;
  return {std::min(u0, o.u0), std::min(v0, o.v0), std::max(u1, o.u1), std::max(v1, o.v1)};
}

PixelRect PixelRect::grown(int m, int w, int h) const
{
  if (empty())
    return {};
  return {std::max(0, u0 - m), std::max(0, v0 - m), std::min(w, u1 + m), std::min(h, v1 + m)};
}

void HuePlane::compute(const vpImage<vpRGBa> &I, float minSaturation)
{
  m_w = I.getWidth();
  m_h = I.getHeight();
  const std::size_t n = static_cast<std::size_t>(m_w) * m_h;
  if (m_hue.size() != n + 2)
    m_hue.assign(n + 2, kNoHue); // +2: padding for 32-bit gathers at the last pixel
  hueRun(I.bitmap, m_hue.data(), n, minSaturation);
  m_valid = {0, 0, static_cast<int>(m_w), static_cast<int>(m_h)};
  m_extra.clear();
}

void HuePlane::compute(const vpImage<vpRGBa> &I, float minSaturation, const PixelRect &roi)
{
  const int w = static_cast<int>(I.getWidth()), h = static_cast<int>(I.getHeight());
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  if (m_hue.size() != n + 2 || m_w != I.getWidth()) {
    m_hue.assign(n + 2, kNoHue);
    m_valid = {};
  }
  m_w = I.getWidth();
  m_h = I.getHeight();
  for (std::int64_t k : m_extra)
    m_hue[static_cast<std::size_t>(k)] = kNoHue;
  m_extra.clear();
  const PixelRect r = roi.grown(0, w, h);
  // Reset what held a hue and falls outside the new window, row by row.
  for (int v = m_valid.v0; v < m_valid.v1; ++v) {
    std::uint16_t *row = m_hue.data() + static_cast<std::size_t>(v) * m_w;
    if (r.empty() || v < r.v0 || v >= r.v1) {
      std::fill(row + m_valid.u0, row + m_valid.u1, kNoHue);
      continue;
    }
    if (m_valid.u0 < r.u0)
      std::fill(row + m_valid.u0, row + std::min(r.u0, m_valid.u1), kNoHue);
    if (m_valid.u1 > r.u1)
      std::fill(row + std::max(r.u1, m_valid.u0), row + m_valid.u1, kNoHue);
  }
  // A window's rows are short runs of a large image: the hardware prefetcher restarts at each, so
  // the rows a few ahead are fetched while this one is computed (a frame from a camera is in memory,
  // not in the caches; pm-bench Hue_StereoPair_AsTracked_SteadyWindows_NewFrames).
  constexpr int kAhead = 4;
  const std::size_t rowBytes = static_cast<std::size_t>(r.u1 - r.u0) * sizeof(vpRGBa);
  for (int v = r.v0; v < r.v1; ++v) {
    const std::size_t at = static_cast<std::size_t>(v) * m_w + static_cast<std::size_t>(r.u0);
    if (v + kAhead < r.v1) {
      const char *ahead = reinterpret_cast<const char *>(I.bitmap + at + static_cast<std::size_t>(kAhead) * m_w);
      for (std::size_t b = 0; b < rowBytes; b += 64)
        __builtin_prefetch(ahead + b);
    }
    hueRun(I.bitmap + at, m_hue.data() + at, static_cast<std::size_t>(r.u1 - r.u0), minSaturation);
  }
  m_valid = r;
}

void HuePlane::addPixels(const vpImage<vpRGBa> &I, float minSaturation, const std::int64_t *pixels, std::size_t n)
{
  if (I.getWidth() != m_w || I.getHeight() != m_h)
    throw Error("hue plane: pixels added from an image of another size than the plane's");
  const std::int64_t size = static_cast<std::int64_t>(m_w) * m_h;
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t k = pixels[i];
    if (k < 0 || k >= size)
      throw Error("hue plane: pixel index " + std::to_string(k) + " outside the image");
    const vpRGBa &c = I.bitmap[k];
    m_hue[static_cast<std::size_t>(k)] = hueOf(c.R, c.G, c.B, minSaturation);
    m_extra.push_back(k);
  }
}

void HuePlane::compute(const vpImage<vpRGBa> &I, float minSaturation, const UndistortMap &map)
{
  if (I.getWidth() != map.width() || I.getHeight() != map.height())
    throw Error("hue plane: the image is " + std::to_string(I.getWidth()) + "x" + std::to_string(I.getHeight()) +
                " but its camera's undistortion map is " + std::to_string(map.width()) + "x" + std::to_string(map.height()));
  compute(I, minSaturation);
  m_raw.swap(m_hue); // the raw image's hue, then gathered into the ideal image
  if (m_hue.size() != m_raw.size())
    m_hue.assign(m_raw.size(), kNoHue);
  const std::int32_t *idx = map.nearest().data();
  const std::uint16_t *src = m_raw.data();
  std::uint16_t *dst = m_hue.data();
  const std::size_t n = map.nearest().size();
  for (std::size_t i = 0; i < n; ++i)
    dst[i] = idx[i] >= 0 ? src[idx[i]] : kNoHue;
}

} // namespace pm::core
