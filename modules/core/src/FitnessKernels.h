#pragma once
/*!
  \file FitnessKernels.h
  The stereo fitness's counting kernels (internal to core, not installed): a camera's projection
  of the model composed with a pose, and the scalar and AVX2 kernels that count the model's points
  into the classes of Eqs. (8), (9). Both project with the same operations in the same order
  (fused multiply-adds, one division, round to nearest), so they give the same pixel and F.
*/
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define PM_HAVE_X86 1
#endif

#include "pm/core/HuePlane.h"
#include "pm/core/StereoFitness.h"

namespace pm::core {

//! What one camera needs to project a model point: cMo as floats (mm), intrinsics, image size.
struct Projection
{
  float r[9], t[3];
  float px, py, u0, v0;
  int w, h;
  const std::uint16_t *hue;
};

//! One camera's part of the smooth score with its gradient: the sums over a view's points.
struct SmoothSums
{
  double value = 0;     //!< sum of the interpolated point scores (offImage for a point off the image)
  double G[3] = {0, 0, 0}; //!< sum of d(score)/dX_c (camera frame, per mm)
  double T[3] = {0, 0, 0}; //!< sum of a x d(score)/dX_c, a the point from the model origin (camera frame)
  double M[21] = {0};   //!< upper triangle of sum J^T J (camera-frame twist), rows (0,0..5), (1,1..5), ...
  std::size_t inside = 0; //!< points in the image (those the metric sums over)
};

namespace kernels {

#ifdef PM_HAVE_X86
inline bool cpuHasAvx2()
{
  static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); // the CPU, once
  return has;
}
#else
inline bool cpuHasAvx2() { return false; }
#endif

struct Tolerances
{
  std::int32_t bg, in, inBg, outBg;
  //! 1 for a hue (tenths of a degree, [0, 3600)) of the target's own (StereoFitness's target hues), else 0; padded by 3 bytes.
  const std::uint8_t *targetHue;
};

//! The model's points as the kernels read them: x, y, z (mm), hue (tenths of a degree).
struct ModelSoA
{
  const float *x, *y, *z;
  const std::int32_t *hue;
};

inline std::int32_t wrapDist(std::int32_t a, std::int32_t b)
{
  const std::int32_t d = a > b ? a - b : b - a;
  return std::min(d, 3600 - d);
}

/*!
  Projects point (X, Y, Z) (Z = 0 when \e kDepth is false: the flat model, exactly the paper's
  operations) and returns the image hue there (tenths of a degree, or kNoHue), or -1 if it falls
  off the image. The operations are those of the AVX2 kernel, in the same order (fused
  multiply-adds, one division, round to nearest), so both give the same pixel.
*/
template <bool kDepth>
inline bool pixelOf(const Projection &p, float X, float Y, float Z, long &ui, long &vi)
{
  const float t0 = kDepth ? std::fmaf(p.r[2], Z, p.t[0]) : p.t[0];
  const float t1 = kDepth ? std::fmaf(p.r[5], Z, p.t[1]) : p.t[1];
  const float t2 = kDepth ? std::fmaf(p.r[8], Z, p.t[2]) : p.t[2];
  const float xc = std::fmaf(p.r[0], X, std::fmaf(p.r[1], Y, t0));
  const float yc = std::fmaf(p.r[3], X, std::fmaf(p.r[4], Y, t1));
  const float zc = std::fmaf(p.r[6], X, std::fmaf(p.r[7], Y, t2));
  if (!(zc > 1e-3f))
    return false;
  const float iz = 1.f / zc;
  const float u = std::fmaf(p.px, xc * iz, p.u0), v = std::fmaf(p.py, yc * iz, p.v0);
  if (!(std::fabs(u) < 1e9f && std::fabs(v) < 1e9f))
    return false;
  ui = std::lrintf(u);
  vi = std::lrintf(v);
  return ui >= 0 && vi >= 0 && ui < p.w && vi < p.h;
}

template <bool kDepth>
inline std::int64_t pixelIndex(const Projection &p, float X, float Y, float Z)
{
  long ui = 0, vi = 0;
  return pixelOf<kDepth>(p, X, Y, Z, ui, vi) ? static_cast<std::int64_t>(vi) * p.w + ui : -1;
}

//! The hue under point (X, Y, Z) (pixelIndex's pixel), or -1 off the image.
template <bool kDepth>
inline std::int32_t sampleScalar(const Projection &p, float X, float Y, float Z)
{
  const std::int64_t i = pixelIndex<kDepth>(p, X, Y, Z);
  return i < 0 ? -1 : p.hue[i];
}

//! The pixels (pixelIndex) of points [b, e) that fall on the image outside \e skip, appended to \e out.
template <bool kDepth>
inline void collectPixels(const Projection &p, const float *x, const float *y, const float *z, std::size_t b, std::size_t e,
                          const PixelRect &skip, std::vector<std::int64_t> &out)
{
  for (std::size_t i = b; i < e; ++i) {
    long u = 0, v = 0;
    if (pixelOf<kDepth>(p, x[i], y[i], kDepth ? z[i] : 0.f, u, v) && !(u >= skip.u0 && u < skip.u1 && v >= skip.v0 && v < skip.v1))
      out.push_back(static_cast<std::int64_t>(v) * p.w + u);
  }
}


//! Whether hue \e h (sampleScalar's) is a hit of an S_in point of hue \e hm: on the image, with a hue within t.in of hm.
inline bool inHit(std::int32_t h, std::int32_t hm, const Tolerances &t) { return h >= 0 && h != HuePlane::kNoHue && wrapDist(h, hm) <= t.in; }
//! Whether hue \e h is a hit of an S_out point: on the image, with a hue within t.outBg of the background's.
inline bool outHit(std::int32_t h, const Tolerances &t) { return h >= 0 && h != HuePlane::kNoHue && wrapDist(h, t.bg) <= t.outBg; }
//! Whether hue \e h (on the image) is within t.inBg of the background's (an S_in point on background: a wrong pose, never hidden).
inline bool inBackground(std::int32_t h, const Tolerances &t) { return h != HuePlane::kNoHue && wrapDist(h, t.bg) <= t.inBg; }
//! Whether hue \e h (on the image) is one of the target's own hues (a miss on one is a wrong pose, never an occluder).
inline bool targetHue(std::int32_t h, const Tolerances &t) { return h != HuePlane::kNoHue && t.targetHue[h]; }

/*!
  The stereo visibility's rule, its first half, for an S_in point of hue \e hm: the camera sees hue
  \e h there, on the image, a miss, neither on the background's hue nor on one of the target's own
  (something else may stand in front). The point is hidden when the other camera, at the point's
  own projection, sees a hit (inHit); only then is the other camera sampled.
*/
inline bool inMayBeHidden(std::int32_t h, std::int32_t hm, const Tolerances &t)
{
  return h >= 0 && !inHit(h, hm, t) && !inBackground(h, t) && !targetHue(h, t);
}
//! The same for an S_out point: on the image, not the background's hue nor one of the target's own; hidden when the other camera sees the background (outHit).
inline bool outMayBeHidden(std::int32_t h, const Tolerances &t) { return h >= 0 && !outHit(h, t) && !targetHue(h, t); }

inline void classifyIn(std::int32_t h, std::int32_t hm, const Tolerances &t, FitnessCounts &c)
{
  if (h < 0) {
    ++c.inOff;
    return;
  }
  const bool hasHue = h != HuePlane::kNoHue;
  if (hasHue && wrapDist(h, hm) <= t.in)
    ++c.inMatch;
  else if (hasHue && wrapDist(h, t.bg) <= t.inBg)
    ++c.inBackground;
  else
    ++c.inOther;
}

inline void classifyOut(std::int32_t h, const Tolerances &t, FitnessCounts &c)
{
  if (h < 0)
    ++c.outOff;
  else if (h != HuePlane::kNoHue && wrapDist(h, t.bg) <= t.outBg)
    ++c.outBackground;
  else
    ++c.outOther;
}

/*!
  Counts points [inBegin, inEnd) as S_in and [outBegin, outEnd) as S_out of camera \e p into \e c.
  With \e other (the other camera, StereoFitness's stereo visibility), a point on the image that
  misses in \e p on a hue that is neither the target's nor the background's (something else
  stands there) but is a hit in
  \e other (the other camera sees there what the model says: its hue, the background) is hidden
  in \e p (inHidden, outHidden) instead of its class.
*/
template <bool kDepth>
void countScalar(const Projection &p, const Projection *other, const Tolerances &t, const ModelSoA &m, std::size_t inBegin,
                 std::size_t inEnd, std::size_t outBegin, std::size_t outEnd, FitnessCounts &c)
{
  for (std::size_t i = inBegin; i < inEnd; ++i) {
    const float z = kDepth ? m.z[i] : 0.f;
    const std::int32_t h = sampleScalar<kDepth>(p, m.x[i], m.y[i], z);
    if (other && inMayBeHidden(h, m.hue[i], t) && inHit(sampleScalar<kDepth>(*other, m.x[i], m.y[i], z), m.hue[i], t))
      ++c.inHidden;
    else
      classifyIn(h, m.hue[i], t, c);
  }
  for (std::size_t i = outBegin; i < outEnd; ++i) {
    const float z = kDepth ? m.z[i] : 0.f;
    const std::int32_t h = sampleScalar<kDepth>(p, m.x[i], m.y[i], z);
    if (other && outMayBeHidden(h, t) && outHit(sampleScalar<kDepth>(*other, m.x[i], m.y[i], z), t))
      ++c.outHidden;
    else
      classifyOut(h, t, c);
  }
}

#ifdef PM_HAVE_X86
//! Lanes [0, n) set (n in [0, 8]).
__attribute__((target("avx2,fma"))) inline __m256i laneMask(std::size_t n)
{
  return _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(n)), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
}

//! The pixels (v * w + u) of points i..i+7 and which of them fall on the image (active lanes only); the arrays are padded past their end.
template <bool kDepth>
__attribute__((target("avx2,fma"))) inline void project8(const Projection &p, const ModelSoA &m, std::size_t i, __m256i active,
                                                         __m256i &idx, __m256i &valid)
{
  const __m256 X = _mm256_loadu_ps(m.x + i), Y = _mm256_loadu_ps(m.y + i);
  __m256 t0 = _mm256_set1_ps(p.t[0]), t1 = _mm256_set1_ps(p.t[1]), t2 = _mm256_set1_ps(p.t[2]);
  if (kDepth) {
    const __m256 Z = _mm256_loadu_ps(m.z + i);
    t0 = _mm256_fmadd_ps(_mm256_set1_ps(p.r[2]), Z, t0);
    t1 = _mm256_fmadd_ps(_mm256_set1_ps(p.r[5]), Z, t1);
    t2 = _mm256_fmadd_ps(_mm256_set1_ps(p.r[8]), Z, t2);
  }
  const __m256 xc = _mm256_fmadd_ps(_mm256_set1_ps(p.r[0]), X, _mm256_fmadd_ps(_mm256_set1_ps(p.r[1]), Y, t0));
  const __m256 yc = _mm256_fmadd_ps(_mm256_set1_ps(p.r[3]), X, _mm256_fmadd_ps(_mm256_set1_ps(p.r[4]), Y, t1));
  const __m256 zc = _mm256_fmadd_ps(_mm256_set1_ps(p.r[6]), X, _mm256_fmadd_ps(_mm256_set1_ps(p.r[7]), Y, t2));
  const __m256 front = _mm256_cmp_ps(zc, _mm256_set1_ps(1e-3f), _CMP_GT_OQ);
  const __m256 iz = _mm256_div_ps(_mm256_set1_ps(1.f), zc);
  const __m256 u = _mm256_fmadd_ps(_mm256_set1_ps(p.px), _mm256_mul_ps(xc, iz), _mm256_set1_ps(p.u0));
  const __m256 v = _mm256_fmadd_ps(_mm256_set1_ps(p.py), _mm256_mul_ps(yc, iz), _mm256_set1_ps(p.v0));
  const __m256 absMask = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff));
  const __m256 big = _mm256_set1_ps(1e9f);
  const __m256 finite = _mm256_and_ps(_mm256_cmp_ps(_mm256_and_ps(u, absMask), big, _CMP_LT_OQ),
                                      _mm256_cmp_ps(_mm256_and_ps(v, absMask), big, _CMP_LT_OQ));
  const __m256i ui = _mm256_cvtps_epi32(u), vi = _mm256_cvtps_epi32(v);
  // 0 <= ui < w and 0 <= vi < h, as signed compares.
  const __m256i inU = _mm256_andnot_si256(_mm256_cmpgt_epi32(_mm256_setzero_si256(), ui), _mm256_cmpgt_epi32(_mm256_set1_epi32(p.w), ui));
  const __m256i inV = _mm256_andnot_si256(_mm256_cmpgt_epi32(_mm256_setzero_si256(), vi), _mm256_cmpgt_epi32(_mm256_set1_epi32(p.h), vi));
  valid = _mm256_and_si256(_mm256_and_si256(_mm256_and_si256(inU, inV), active), _mm256_castps_si256(_mm256_and_ps(front, finite)));
  idx = _mm256_add_epi32(_mm256_mullo_epi32(vi, _mm256_set1_epi32(p.w)), ui);
}

//! The hue under points i..i+7 (-1: off the image or an inactive lane).
template <bool kDepth>
__attribute__((target("avx2,fma"))) inline __m256i sample8(const Projection &p, const ModelSoA &m, std::size_t i, __m256i active)
{
  __m256i idx, valid;
  project8<kDepth>(p, m, i, active, idx, valid);
  // 32-bit gather at byte offset 2*idx (the plane is padded), keep the low 16 bits.
  const __m256i g = _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), reinterpret_cast<const int *>(p.hue), idx, valid, 2);
  const __m256i hue = _mm256_and_si256(g, _mm256_set1_epi32(0xffff));
  return _mm256_blendv_epi8(_mm256_set1_epi32(-1), hue, valid);
}

/*!
  collectPixels 8 points at a time (the same pixels: the counting kernel's projection): the pixels of
  points [b, e) on the image and outside \e skip, appended to \e out.
*/
template <bool kDepth>
__attribute__((target("avx2,fma"))) void collectPixelsAvx2(const Projection &p, const ModelSoA &m, std::size_t b, std::size_t e,
                                                           const PixelRect &skip, std::vector<std::int64_t> &out)
{
  const __m256i su0 = _mm256_set1_epi32(skip.u0 - 1), su1 = _mm256_set1_epi32(skip.u1), sv0 = _mm256_set1_epi32(skip.v0 - 1),
                sv1 = _mm256_set1_epi32(skip.v1), w = _mm256_set1_epi32(p.w);
  for (std::size_t i = b; i < e; i += 8) {
    __m256i idx, valid;
    project8<kDepth>(p, m, i, laneMask(std::min<std::size_t>(8, e - i)), idx, valid);
    // Back to (u, v) to test the skipped rectangle: v = idx / w by float division (exact for these sizes).
    const __m256i v = _mm256_cvttps_epi32(_mm256_div_ps(_mm256_add_ps(_mm256_cvtepi32_ps(idx), _mm256_set1_ps(0.5f)), _mm256_cvtepi32_ps(w)));
    const __m256i u = _mm256_sub_epi32(idx, _mm256_mullo_epi32(v, w));
    const __m256i inSkip = _mm256_and_si256(_mm256_and_si256(_mm256_cmpgt_epi32(u, su0), _mm256_cmpgt_epi32(su1, u)),
                                            _mm256_and_si256(_mm256_cmpgt_epi32(v, sv0), _mm256_cmpgt_epi32(sv1, v)));
    unsigned mask = static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_andnot_si256(inSkip, valid))));
    if (!mask)
      continue;
    alignas(32) std::int32_t k[8];
    _mm256_store_si256(reinterpret_cast<__m256i *>(k), idx);
    for (; mask; mask &= mask - 1)
      out.push_back(k[__builtin_ctz(mask)]);
  }
}

__attribute__((target("avx2,fma"))) inline __m256i wrapDist8(__m256i a, __m256i b)
{
  const __m256i d = _mm256_abs_epi32(_mm256_sub_epi32(a, b));
  return _mm256_min_epi32(d, _mm256_sub_epi32(_mm256_set1_epi32(3600), d));
}

__attribute__((target("avx2,fma"))) inline int hsum(__m256i v)
{
  __m128i s = _mm_add_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
  s = _mm_add_epi32(s, _mm_shuffle_epi32(s, 0x4e));
  s = _mm_add_epi32(s, _mm_shuffle_epi32(s, 0xb1));
  return _mm_cvtsi128_si32(s);
}

//! Lanes of \e mask whose hue \e h (on the image, or kNoHue) is not one of the target's own (Tolerances::targetHue).
__attribute__((target("avx2,fma"))) inline __m256i notTargetHue8(__m256i h, __m256i mask, const Tolerances &t)
{
  const __m256i withHue = _mm256_andnot_si256(_mm256_cmpeq_epi32(h, _mm256_set1_epi32(HuePlane::kNoHue)), mask);
  const __m256i g = _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), reinterpret_cast<const int *>(t.targetHue), h, withHue, 1);
  const __m256i isTarget = _mm256_and_si256(withHue, _mm256_cmpgt_epi32(_mm256_and_si256(g, _mm256_set1_epi32(0xff)), _mm256_setzero_si256()));
  return _mm256_andnot_si256(isTarget, mask);
}

//! Lanes whose hue (sample8's) is on the image and is a hue.
__attribute__((target("avx2,fma"))) inline __m256i hasHue8(__m256i h)
{
  const __m256i neg = _mm256_set1_epi32(-1);
  return _mm256_andnot_si256(_mm256_or_si256(_mm256_cmpeq_epi32(h, neg), _mm256_cmpeq_epi32(h, _mm256_set1_epi32(HuePlane::kNoHue))), neg);
}

/*!
  countScalar 8 points at a time (the last group masked: the arrays are padded); the other camera
  is sampled only for the lanes that miss in \e p, and not at all for a group without a miss.
*/
template <bool kDepth>
__attribute__((target("avx2,fma"))) void countAvx2(const Projection &p, const Projection *other, const Tolerances &t, const ModelSoA &m,
                                                   std::size_t inBegin, std::size_t inEnd, std::size_t outBegin,
                                                   std::size_t outEnd, FitnessCounts &c)
{
  const __m256i neg = _mm256_set1_epi32(-1);
  const __m256i bg = _mm256_set1_epi32(t.bg);
  const __m256i tIn = _mm256_set1_epi32(t.in + 1), tInBg = _mm256_set1_epi32(t.inBg + 1), tOutBg = _mm256_set1_epi32(t.outBg + 1);
  __m256i nMatch = _mm256_setzero_si256(), nBg = _mm256_setzero_si256(), nOff = _mm256_setzero_si256(), nHidden = _mm256_setzero_si256();
  for (std::size_t i = inBegin; i < inEnd; i += 8) {
    const __m256i act = laneMask(std::min<std::size_t>(8, inEnd - i));
    const __m256i h = sample8<kDepth>(p, m, i, act);
    const __m256i hm = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(m.hue + i));
    const __m256i off = _mm256_and_si256(_mm256_cmpeq_epi32(h, neg), act);
    const __m256i hasHue = hasHue8(h);
    const __m256i match = _mm256_and_si256(hasHue, _mm256_cmpgt_epi32(tIn, wrapDist8(h, hm)));
    const __m256i isBg = _mm256_andnot_si256(match, _mm256_and_si256(hasHue, _mm256_cmpgt_epi32(tInBg, wrapDist8(h, bg))));
    if (other) {
      __m256i miss = _mm256_andnot_si256(_mm256_or_si256(_mm256_or_si256(match, isBg), off), act); // neither its hue nor the background's
      if (!_mm256_testz_si256(miss, miss))
        miss = notTargetHue8(h, miss, t);
      if (!_mm256_testz_si256(miss, miss)) {
        const __m256i ho = sample8<kDepth>(*other, m, i, miss);
        const __m256i hidden = _mm256_and_si256(miss, _mm256_and_si256(hasHue8(ho), _mm256_cmpgt_epi32(tIn, wrapDist8(ho, hm))));
        nHidden = _mm256_sub_epi32(nHidden, hidden);
      }
    }
    nMatch = _mm256_sub_epi32(nMatch, match);
    nBg = _mm256_sub_epi32(nBg, isBg);
    nOff = _mm256_sub_epi32(nOff, off);
  }
  const int nIn = static_cast<int>(inEnd - inBegin), match = hsum(nMatch), onBg = hsum(nBg), offIn = hsum(nOff), hidIn = hsum(nHidden);
  c.inMatch += match;
  c.inBackground += onBg;
  c.inOff += offIn;
  c.inHidden += hidIn;
  c.inOther += nIn - match - onBg - offIn - hidIn;

  __m256i oBg = _mm256_setzero_si256(), oOff = _mm256_setzero_si256(), oHidden = _mm256_setzero_si256();
  for (std::size_t j = outBegin; j < outEnd; j += 8) {
    const __m256i act = laneMask(std::min<std::size_t>(8, outEnd - j));
    const __m256i h = sample8<kDepth>(p, m, j, act);
    const __m256i off = _mm256_and_si256(_mm256_cmpeq_epi32(h, neg), act);
    const __m256i hit = _mm256_and_si256(hasHue8(h), _mm256_cmpgt_epi32(tOutBg, wrapDist8(h, bg)));
    if (other) {
      __m256i miss = _mm256_andnot_si256(_mm256_or_si256(hit, off), act);
      if (!_mm256_testz_si256(miss, miss))
        miss = notTargetHue8(h, miss, t);
      if (!_mm256_testz_si256(miss, miss)) {
        const __m256i ho = sample8<kDepth>(*other, m, j, miss);
        oHidden = _mm256_sub_epi32(oHidden, _mm256_and_si256(miss, _mm256_and_si256(hasHue8(ho), _mm256_cmpgt_epi32(tOutBg, wrapDist8(ho, bg)))));
      }
    }
    oBg = _mm256_sub_epi32(oBg, hit);
    oOff = _mm256_sub_epi32(oOff, off);
  }
  const int nOut = static_cast<int>(outEnd - outBegin), outBg = hsum(oBg), offOut = hsum(oOff), hidOut = hsum(oHidden);
  c.outBackground += outBg;
  c.outOff += offOut;
  c.outHidden += hidOut;
  c.outOther += nOut - outBg - offOut - hidOut;
}
#endif

//! Degrees to the tenths of a degree the kernels compare.
inline std::int32_t deci(double deg) { return static_cast<std::int32_t>(std::lround(deg * 10.0)); }

} // namespace kernels
} // namespace pm::core
