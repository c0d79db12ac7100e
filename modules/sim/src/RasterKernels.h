#pragma once
/*!
  \file RasterKernels.h
  The rasterizer's inner loops on vectors (private to Rasterizer.cpp): a texel's shading on 4 floats
  (SSE2) and, where the processor has AVX2, a span of 8 samples and a resolved row two pixels at a
  time. Each does the same float operations in the same order as the scalar loop it stands for, so
  the images are the same bit for bit whichever path runs (test_render checks it).
*/
#include <cstddef>
#include <cstdint>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define PM_RASTER_AVX2 1
#include <immintrin.h>
#else
#define PM_RASTER_AVX2 0
#endif

#include <visp3/core/vpRGBa.h>

#include "pm/sim/Mesh.h"

namespace pm::sim::raster {

//! One colour sample: R, G, B and a pad, so that a sample is one 16-byte vector.
constexpr std::size_t kStride = 4;

#if defined(__SSE2__)
//! The 3 channels and the next byte of the texel at \e p, as 4 floats.
inline __m128 texel4(const std::uint8_t *p)
{
  std::int32_t bits;
  std::memcpy(&bits, p, 4);
  const __m128i zero = _mm_setzero_si128();
  const __m128i b = _mm_cvtsi32_si128(bits);
  return _mm_cvtepi32_ps(_mm_unpacklo_epi16(_mm_unpacklo_epi8(b, zero), zero));
}
#endif

/*!
  Texture::sample's bilinear fetch with the four texels converted at once (the same arithmetic,
  so the same values), writing R, G, B times \e diff plus \e spec into \e out.
*/
inline void shadeTexel(const Texture &tex, float s, float t, float diff, float spec, float *out)
{
#if defined(__SSE2__)
  s = std::min(std::max(s, 0.f), static_cast<float>(tex.width - 1));
  t = std::min(std::max(t, 0.f), static_cast<float>(tex.height - 1));
  const int i = std::min(static_cast<int>(s), tex.width - 2 < 0 ? 0 : tex.width - 2);
  const int j = std::min(static_cast<int>(t), tex.height - 2 < 0 ? 0 : tex.height - 2);
  const std::size_t di = tex.width > 1 ? 3 : 0, dj = tex.height > 1 ? 3 * static_cast<std::size_t>(tex.width) : 0;
  const std::size_t k = 3 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(tex.width) + static_cast<std::size_t>(i));
  if (k + dj + di + 4 <= tex.rgb.size()) { // the 4-byte loads stay inside (all but the last texel)
    const std::uint8_t *p = tex.rgb.data() + k;
    const __m128 a = _mm_set1_ps(s - static_cast<float>(i)), b = _mm_set1_ps(t - static_cast<float>(j));
    const __m128 p00 = texel4(p), p10 = texel4(p + di), p01 = texel4(p + dj), p11 = texel4(p + dj + di);
    const __m128 top = _mm_add_ps(p00, _mm_mul_ps(a, _mm_sub_ps(p10, p00)));
    const __m128 bot = _mm_add_ps(p01, _mm_mul_ps(a, _mm_sub_ps(p11, p01)));
    const __m128 col = _mm_mul_ps(_mm_add_ps(top, _mm_mul_ps(b, _mm_sub_ps(bot, top))), _mm_set1_ps(1.f / 255.f));
    _mm_storeu_ps(out, _mm_add_ps(_mm_mul_ps(col, _mm_set1_ps(diff)), _mm_set1_ps(spec)));
    return;
  }
#endif
  float col[3];
  tex.sample(s, t, col);
  for (int c = 0; c < 3; ++c)
    out[c] = col[c] * diff + spec;
}

//! A span shorter than this (a small triangle's) is shaded one sample at a time: faster than a masked chunk.
constexpr std::size_t kMinAvx2Span = 4;

#if PM_RASTER_AVX2
/*!
  The span loop of drawTriangles<false> on 8 samples at a time (AVX2): the same operations in the
  same order as the scalar loop (no fused multiply-add), so the same values bit for bit; a chunk
  whose texels reach the texture's last byte is left to the scalar loop. The last chunk of a span
  runs with the lanes past its end masked off (no read, no write). Returns the number of samples
  done: all of them, or the multiple of 8 before a chunk left to the scalar loop.
*/
__attribute__((target("avx2"))) inline std::size_t shadeSpanAvx2(const float *v0, const float *d, std::size_t count,
                                                          float *invDepth, std::uint8_t *ids, float *color,
                                                          const Texture &tex, bool useMask, std::uint8_t id)
{
  const __m256 lane = _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256 maxS = _mm256_set1_ps(static_cast<float>(tex.width - 1)), maxT = _mm256_set1_ps(static_cast<float>(tex.height - 1));
  const __m256i maxI = _mm256_set1_epi32(tex.width - 2 < 0 ? 0 : tex.width - 2);
  const __m256i maxJ = _mm256_set1_epi32(tex.height - 2 < 0 ? 0 : tex.height - 2);
  const __m256i width = _mm256_set1_epi32(tex.width), three = _mm256_set1_epi32(3);
  const int di = tex.width > 1 ? 3 : 0, dj = tex.height > 1 ? 3 * tex.width : 0;
  const __m256i vdi = _mm256_set1_epi32(di), vdj = _mm256_set1_epi32(dj);
  const __m256i lastSafe = _mm256_set1_epi32(static_cast<int>(tex.rgb.size()) - 4 - dj - di); // k <= this: in bounds
  const __m256i byte = _mm256_set1_epi32(0xff);
  const __m256 zero = _mm256_setzero_ps(), scale = _mm256_set1_ps(1.f / 255.f);
  const auto *base = reinterpret_cast<const int *>(tex.rgb.data());
  std::size_t done = 0;
  if (count < kMinAvx2Span)
    return 0;
  const __m256 countF = _mm256_set1_ps(static_cast<float>(count));
  for (; done < count; done += 8) {
    const __m256 kf = _mm256_add_ps(_mm256_set1_ps(static_cast<float>(done)), lane);
    const std::size_t at = done;
    const __m256 w = _mm256_add_ps(_mm256_set1_ps(v0[0]), _mm256_mul_ps(kf, _mm256_set1_ps(d[0])));
    __m256 pass;
    if (done + 8 <= count) {
      pass = _mm256_cmp_ps(w, _mm256_loadu_ps(invDepth + at), _CMP_NLE_UQ);
    } else { // the span's last samples: the lanes past its end neither read nor write
      const __m256 inSpan = _mm256_cmp_ps(kf, countF, _CMP_LT_OQ);
      pass = _mm256_and_ps(inSpan, _mm256_cmp_ps(w, _mm256_maskload_ps(invDepth + at, _mm256_castps_si256(inSpan)), _CMP_NLE_UQ));
    }
    const __m256 iz = _mm256_div_ps(_mm256_set1_ps(1.f), w);
    if (useMask) {
      const __m256 m = _mm256_add_ps(_mm256_set1_ps(v0[3]), _mm256_mul_ps(kf, _mm256_set1_ps(d[3])));
      pass = _mm256_and_ps(pass, _mm256_cmp_ps(m, zero, _CMP_NGT_UQ));
    }
    int bits = _mm256_movemask_ps(pass);
    if (!bits)
      continue;
    // (Lambdas do not inherit the target attribute: the attribute planes written out.)
#define PM_ATTR(q) _mm256_mul_ps(_mm256_add_ps(_mm256_set1_ps(v0[q]), _mm256_mul_ps(kf, _mm256_set1_ps(d[q]))), iz)
    __m256 s = PM_ATTR(1), t = PM_ATTR(2);
    const __m256 diff = PM_ATTR(4), spec = PM_ATTR(5);
#undef PM_ATTR
    s = _mm256_min_ps(_mm256_max_ps(s, zero), maxS);
    t = _mm256_min_ps(_mm256_max_ps(t, zero), maxT);
    const __m256i i = _mm256_min_epi32(_mm256_cvttps_epi32(s), maxI), j = _mm256_min_epi32(_mm256_cvttps_epi32(t), maxJ);
    const __m256 a = _mm256_sub_ps(s, _mm256_cvtepi32_ps(i)), b = _mm256_sub_ps(t, _mm256_cvtepi32_ps(j));
    const __m256i k = _mm256_mullo_epi32(_mm256_add_epi32(_mm256_mullo_epi32(j, width), i), three);
    const __m256i active = _mm256_castps_si256(pass);
    if (_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_and_si256(active, _mm256_cmpgt_epi32(k, lastSafe)))))
      return done; // a 4-byte texel load would pass the texture's end: the scalar loop takes over
    const __m256i g00 = _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), base, k, active, 1);
    const __m256i g10 = _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), base, _mm256_add_epi32(k, vdi), active, 1);
    const __m256i g01 = _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), base, _mm256_add_epi32(k, vdj), active, 1);
    const __m256i g11 = _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), base, _mm256_add_epi32(k, _mm256_add_epi32(vdj, vdi)), active, 1);
    __m256 out[3];
    for (int c = 0; c < 3; ++c) {
      const __m128i sh = _mm_cvtsi32_si128(8 * c);
#define PM_CHAN(g) _mm256_cvtepi32_ps(_mm256_and_si256(_mm256_srl_epi32(g, sh), byte))
      const __m256 p00 = PM_CHAN(g00), p10 = PM_CHAN(g10), p01 = PM_CHAN(g01), p11 = PM_CHAN(g11);
#undef PM_CHAN
      const __m256 top = _mm256_add_ps(p00, _mm256_mul_ps(a, _mm256_sub_ps(p10, p00)));
      const __m256 bot = _mm256_add_ps(p01, _mm256_mul_ps(a, _mm256_sub_ps(p11, p01)));
      const __m256 col = _mm256_mul_ps(_mm256_add_ps(top, _mm256_mul_ps(b, _mm256_sub_ps(bot, top))), scale);
      out[c] = _mm256_add_ps(_mm256_mul_ps(col, diff), spec);
    }
    // The 8 samples' (R, G, B, 0) in memory order: two samples per register.
    const __m256 t0 = _mm256_unpacklo_ps(out[0], out[1]), t1 = _mm256_unpackhi_ps(out[0], out[1]);
    const __m256 t2 = _mm256_unpacklo_ps(out[2], zero), t3 = _mm256_unpackhi_ps(out[2], zero);
    const __m256 u0 = _mm256_shuffle_ps(t0, t2, 0x44), u1 = _mm256_shuffle_ps(t0, t2, 0xee);
    const __m256 u2 = _mm256_shuffle_ps(t1, t3, 0x44), u3 = _mm256_shuffle_ps(t1, t3, 0xee);
    const __m256 rgb[4] = {_mm256_permute2f128_ps(u0, u1, 0x20), _mm256_permute2f128_ps(u2, u3, 0x20),
                           _mm256_permute2f128_ps(u0, u1, 0x31), _mm256_permute2f128_ps(u2, u3, 0x31)};
    float *o = color + kStride * at;
    if (bits == 0xff) {
      _mm256_storeu_ps(invDepth + at, w);
      for (int q = 0; q < 4; ++q)
        _mm256_storeu_ps(o + 8 * q, rgb[q]);
      std::memset(ids + at, id, 8);
    } else {
      _mm256_maskstore_ps(invDepth + at, active, w);
      for (int q = 0; q < 4; ++q) {
        const __m256i pick = _mm256_setr_epi32(2 * q, 2 * q, 2 * q, 2 * q, 2 * q + 1, 2 * q + 1, 2 * q + 1, 2 * q + 1);
        _mm256_maskstore_ps(o + 8 * q, _mm256_permutevar8x32_epi32(active, pick), rgb[q]);
      }
      while (bits) {
        const int q = __builtin_ctz(static_cast<unsigned>(bits));
        bits &= bits - 1;
        ids[at + static_cast<std::size_t>(q)] = id;
      }
    }
  }
  return count;
}

/*!
  resolve() of one pixel row with supersampling 2, two pixels at a time (AVX2): the same float
  operations in the same order as the 4-channel loop (the samples of a pixel added row by row, left
  to right), so the same bytes. \e c0, \e c1: the colour of the row's two sample rows; \e id0,
  \e id1: their ids; \e noise: (R, G, B) per pixel, readable one float past the last pixel (what
  lies there goes to the alpha channel, set to 255). Returns the number of pixels done (even).
*/
__attribute__((target("avx2"))) inline unsigned resolveRowSs2Avx2(const float *c0, const float *c1, const std::uint8_t *id0,
                                                            const std::uint8_t *id1, const float *clear4,
                                                            const float *noise, float norm, float sigma, unsigned w,
                                                            vpRGBa *dst)
{
  const __m256 clear = _mm256_broadcast_ps(reinterpret_cast<const __m128 *>(clear4));
  const __m256 vnorm = _mm256_set1_ps(norm), vsigma = _mm256_set1_ps(sigma), zero = _mm256_setzero_ps();
  const __m256 top = _mm256_set1_ps(255.f), half = _mm256_set1_ps(0.5f);
  const __m128i spread = _mm_setr_epi8(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3);
  const __m128i opaque = _mm_set1_epi32(static_cast<int>(0xff000000u));
  // The 4 samples of two pixels on one sample row, the clear colour where nothing was drawn;
  // returns [first samples | ...] as P (left sample of each pixel) and Q (right sample).
  auto row = [&](const float *c, const std::uint8_t *id, unsigned u, __m256 &P, __m256 &Q) __attribute__((target("avx2"))) {
    std::int32_t ids;
    std::memcpy(&ids, id + 2 * u, 4);
    const __m128i lanes = _mm_shuffle_epi8(_mm_cvtsi32_si128(ids), spread); // each id 4 times
    const __m256i empty0 = _mm256_cmpeq_epi32(_mm256_cvtepu8_epi32(lanes), _mm256_setzero_si256());
    const __m256i empty1 = _mm256_cmpeq_epi32(_mm256_cvtepu8_epi32(_mm_srli_si128(lanes, 8)), _mm256_setzero_si256());
    const __m256 X = _mm256_blendv_ps(_mm256_loadu_ps(c + 8 * u), clear, _mm256_castsi256_ps(empty0));
    const __m256 Y = _mm256_blendv_ps(_mm256_loadu_ps(c + 8 * u + 8), clear, _mm256_castsi256_ps(empty1));
    P = _mm256_permute2f128_ps(X, Y, 0x20);
    Q = _mm256_permute2f128_ps(X, Y, 0x31);
  };
  unsigned u = 0;
  for (; u + 2 <= w; u += 2) {
    __m256 P0, Q0, P1, Q1;
    row(c0, id0, u, P0, Q0);
    row(c1, id1, u, P1, Q1);
    const __m256 acc = _mm256_add_ps(_mm256_add_ps(_mm256_add_ps(P0, Q0), P1), Q1);
    const __m256 g = _mm256_loadu2_m128(noise + 3 * u + 3, noise + 3 * u); // (R, G, B, next R) of each pixel
    __m256 x = _mm256_add_ps(_mm256_mul_ps(acc, vnorm), _mm256_mul_ps(vsigma, g));
    x = _mm256_add_ps(_mm256_min_ps(_mm256_max_ps(x, zero), top), half);
    const __m256i q = _mm256_cvttps_epi32(x);
    const __m128i w16 = _mm_packus_epi32(_mm256_castsi256_si128(q), _mm256_extracti128_si256(q, 1));
    const __m128i bytes = _mm_or_si128(_mm_packus_epi16(w16, w16), opaque);
    _mm_storel_epi64(reinterpret_cast<__m128i *>(dst + u), bytes);
  }
  return u;
}
#endif

} // namespace pm::sim::raster
