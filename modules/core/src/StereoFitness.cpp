#include "pm/core/StereoFitness.h"

#include <atomic>
#include <cmath>
#include <algorithm>
#include <exception>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define PM_HAVE_X86 1
#endif

#include "pm/core/BatchPool.h"
#include "pm/core/Error.h"

namespace pm::core {

void FitnessParams::validate() const
{
  auto tol = [](double t, const char *name) {
    if (!(t >= 0 && t <= 180))
      throw Error(std::string("fitness parameter ") + name + " must lie in [0, 180] degrees");
  };
  tol(inTolDeg, "in tolerance");
  tol(inBgTolDeg, "in background tolerance");
  tol(outBgTolDeg, "out background tolerance");
  for (double s : {inMatch, inBackground, inOther, outBackground, outOther, offImage})
    if (!std::isfinite(s))
      throw Error("fitness scores must be finite");
  if (!(minSaturation >= 0.f && minSaturation < 1.f))
    throw Error("fitness parameter minimum saturation must lie in [0, 1)");
}

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

namespace {

std::atomic<bool> g_forceScalar{false};

#ifdef PM_HAVE_X86
bool cpuHasAvx2() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }
#else
bool cpuHasAvx2() { return false; }
#endif

struct Tolerances
{
  std::int32_t bg, in, inBg, outBg;
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

template <bool kDepth>
void countScalar(const Projection &p, const Tolerances &t, const ModelSoA &m, std::size_t inBegin, std::size_t inEnd,
                 std::size_t outBegin, std::size_t outEnd, FitnessCounts &c)
{
  for (std::size_t i = inBegin; i < inEnd; ++i)
    classifyIn(sampleScalar<kDepth>(p, m.x[i], m.y[i], kDepth ? m.z[i] : 0.f), m.hue[i], t, c);
  for (std::size_t i = outBegin; i < outEnd; ++i)
    classifyOut(sampleScalar<kDepth>(p, m.x[i], m.y[i], kDepth ? m.z[i] : 0.f), t, c);
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

/*!
  Counts points [inBegin, inEnd) as S_in and [outBegin, outEnd) as S_out into \e c, 8 at a time
  (the last group masked: the arrays are padded).
*/
template <bool kDepth>
__attribute__((target("avx2,fma"))) void countAvx2(const Projection &p, const Tolerances &t, const ModelSoA &m,
                                                   std::size_t inBegin, std::size_t inEnd, std::size_t outBegin,
                                                   std::size_t outEnd, FitnessCounts &c)
{
  const __m256i neg = _mm256_set1_epi32(-1), noHue = _mm256_set1_epi32(HuePlane::kNoHue);
  const __m256i bg = _mm256_set1_epi32(t.bg);
  const __m256i tIn = _mm256_set1_epi32(t.in + 1), tInBg = _mm256_set1_epi32(t.inBg + 1), tOutBg = _mm256_set1_epi32(t.outBg + 1);
  __m256i nMatch = _mm256_setzero_si256(), nBg = _mm256_setzero_si256(), nOff = _mm256_setzero_si256();
  for (std::size_t i = inBegin; i < inEnd; i += 8) {
    const __m256i act = laneMask(std::min<std::size_t>(8, inEnd - i));
    const __m256i h = sample8<kDepth>(p, m, i, act);
    const __m256i off = _mm256_and_si256(_mm256_cmpeq_epi32(h, neg), act);
    const __m256i hasHue = _mm256_andnot_si256(_mm256_or_si256(_mm256_cmpeq_epi32(h, neg), _mm256_cmpeq_epi32(h, noHue)), neg);
    const __m256i match = _mm256_and_si256(hasHue, _mm256_cmpgt_epi32(tIn, wrapDist8(h, _mm256_loadu_si256(reinterpret_cast<const __m256i *>(m.hue + i)))));
    const __m256i isBg = _mm256_andnot_si256(match, _mm256_and_si256(hasHue, _mm256_cmpgt_epi32(tInBg, wrapDist8(h, bg))));
    nMatch = _mm256_sub_epi32(nMatch, match);
    nBg = _mm256_sub_epi32(nBg, isBg);
    nOff = _mm256_sub_epi32(nOff, off);
  }
  const int nIn = static_cast<int>(inEnd - inBegin), match = hsum(nMatch), onBg = hsum(nBg), offIn = hsum(nOff);
  c.inMatch += match;
  c.inBackground += onBg;
  c.inOff += offIn;
  c.inOther += nIn - match - onBg - offIn;

  __m256i oBg = _mm256_setzero_si256(), oOff = _mm256_setzero_si256();
  for (std::size_t j = outBegin; j < outEnd; j += 8) {
    const __m256i act = laneMask(std::min<std::size_t>(8, outEnd - j));
    const __m256i h = sample8<kDepth>(p, m, j, act);
    const __m256i off = _mm256_and_si256(_mm256_cmpeq_epi32(h, neg), act);
    const __m256i hasHue = _mm256_andnot_si256(_mm256_or_si256(_mm256_cmpeq_epi32(h, neg), _mm256_cmpeq_epi32(h, noHue)), neg);
    oBg = _mm256_sub_epi32(oBg, _mm256_and_si256(hasHue, _mm256_cmpgt_epi32(tOutBg, wrapDist8(h, bg))));
    oOff = _mm256_sub_epi32(oOff, off);
  }
  const int nOut = static_cast<int>(outEnd - outBegin), outBg = hsum(oBg), offOut = hsum(oOff);
  c.outBackground += outBg;
  c.outOff += offOut;
  c.outOther += nOut - outBg - offOut;
}
#endif


//! The scores of the classes of Eqs. (8), (9), as floats for the interpolation.
struct ClassScores
{
  float inMatch, inBackground, inOther, outBackground, outOther, offImage;
};

//! Adds one point's metric rows (image motion of u and v per camera-frame twist) to \e M.
template <class T>
inline void addMetricRows(const T ru[6], const T rv[6], T M[21])
{
  int k = 0;
  for (int r = 0; r < 6; ++r)
    for (int c = r; c < 6; ++c, ++k)
      M[k] += ru[r] * ru[c] + rv[r] * rv[c];
}

#ifdef PM_HAVE_X86
//! The score of each of 8 pixels of hue \e h for points of hue \e hm (S_in) or for S_out points.
template <bool kInner>
__attribute__((target("avx2,fma"))) inline __m256 pixelScores8(__m256i h, __m256i hm, const Tolerances &t, const ClassScores &cs)
{
  const __m256i hasHue = _mm256_xor_si256(_mm256_cmpeq_epi32(h, _mm256_set1_epi32(HuePlane::kNoHue)), _mm256_set1_epi32(-1));
  const __m256i nearBg = _mm256_and_si256(hasHue, _mm256_cmpgt_epi32(_mm256_set1_epi32((kInner ? t.inBg : t.outBg) + 1),
                                                                     wrapDist8(h, _mm256_set1_epi32(t.bg))));
  if (!kInner)
    return _mm256_blendv_ps(_mm256_set1_ps(cs.outOther), _mm256_set1_ps(cs.outBackground), _mm256_castsi256_ps(nearBg));
  const __m256i match = _mm256_and_si256(hasHue, _mm256_cmpgt_epi32(_mm256_set1_epi32(t.in + 1), wrapDist8(h, hm)));
  const __m256 s = _mm256_blendv_ps(_mm256_set1_ps(cs.inOther), _mm256_set1_ps(cs.inBackground), _mm256_castsi256_ps(nearBg));
  return _mm256_blendv_ps(s, _mm256_set1_ps(cs.inMatch), _mm256_castsi256_ps(match));
}

__attribute__((target("avx2,fma"))) inline double hsumPs(__m256 v)
{
  alignas(32) float f[8];
  _mm256_store_ps(f, v);
  double s = 0;
  for (float x : f)
    s += static_cast<double>(x);
  return s;
}

/*!
  The smooth score's sums over points [b, e) (S_in when \e kInner), 8 at a time: each point's
  four neighbouring pixels (two 32-bit gathers of the 16-bit plane read a pixel and the one to its
  right), their class scores interpolated bilinearly, the derivatives of that with respect to the
  point's camera-frame position, and (\e metric) the image-motion metric. The last group is
  masked (the arrays are padded); returns \e e.
*/
template <bool kInner>
__attribute__((target("avx2,fma"))) std::size_t smoothSumsAvx2(const Projection &p, const Tolerances &t, const ClassScores &cs,
                                                               const ModelSoA &m, std::size_t b, std::size_t e, bool metric,
                                                               SmoothSums &out)
{
  const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.f);
  __m256 val = zero, gx = zero, gy = zero, gz = zero, tx = zero, ty = zero, tz = zero;
  __m256 M[21];
  for (auto &x : M)
    x = zero;
  const __m256 px = _mm256_set1_ps(p.px), py = _mm256_set1_ps(p.py);
  const __m256 wLim = _mm256_set1_ps(static_cast<float>(p.w - 1)), hLim = _mm256_set1_ps(static_cast<float>(p.h - 1));
  const __m256 off = _mm256_set1_ps(cs.offImage);
  std::size_t i = b;
  for (; i < e; i += 8) { // the last group masked (the arrays are padded)
    const __m256 active = _mm256_castsi256_ps(laneMask(std::min<std::size_t>(8, e - i)));
    const __m256 X = _mm256_loadu_ps(m.x + i), Y = _mm256_loadu_ps(m.y + i), Z = _mm256_loadu_ps(m.z + i);
    // a: the point from the model origin, camera frame; X_c = a + t.
    const __m256 ax = _mm256_fmadd_ps(_mm256_set1_ps(p.r[0]), X, _mm256_fmadd_ps(_mm256_set1_ps(p.r[1]), Y, _mm256_mul_ps(_mm256_set1_ps(p.r[2]), Z)));
    const __m256 ay = _mm256_fmadd_ps(_mm256_set1_ps(p.r[3]), X, _mm256_fmadd_ps(_mm256_set1_ps(p.r[4]), Y, _mm256_mul_ps(_mm256_set1_ps(p.r[5]), Z)));
    const __m256 az = _mm256_fmadd_ps(_mm256_set1_ps(p.r[6]), X, _mm256_fmadd_ps(_mm256_set1_ps(p.r[7]), Y, _mm256_mul_ps(_mm256_set1_ps(p.r[8]), Z)));
    const __m256 xc = _mm256_add_ps(ax, _mm256_set1_ps(p.t[0])), yc = _mm256_add_ps(ay, _mm256_set1_ps(p.t[1]));
    const __m256 zc = _mm256_add_ps(az, _mm256_set1_ps(p.t[2]));
    const __m256 front = _mm256_cmp_ps(zc, _mm256_set1_ps(1e-3f), _CMP_GT_OQ);
    const __m256 iz = _mm256_div_ps(one, _mm256_blendv_ps(one, zc, front));
    const __m256 xn = _mm256_mul_ps(xc, iz), yn = _mm256_mul_ps(yc, iz);
    const __m256 u = _mm256_fmadd_ps(px, xn, _mm256_set1_ps(p.u0)), v = _mm256_fmadd_ps(py, yn, _mm256_set1_ps(p.v0));
    const __m256 inside = _mm256_and_ps(active, _mm256_and_ps(_mm256_and_ps(front, _mm256_and_ps(_mm256_cmp_ps(u, zero, _CMP_GE_OQ), _mm256_cmp_ps(v, zero, _CMP_GE_OQ))),
                                                              _mm256_and_ps(_mm256_cmp_ps(u, wLim, _CMP_LT_OQ), _mm256_cmp_ps(v, hLim, _CMP_LT_OQ))));
    const __m256 uu = _mm256_and_ps(u, inside), vv = _mm256_and_ps(v, inside); // 0 where outside: a safe pixel
    const __m256i ui = _mm256_cvttps_epi32(uu), vi = _mm256_cvttps_epi32(vv);
    const __m256 fu = _mm256_sub_ps(uu, _mm256_cvtepi32_ps(ui)), fv = _mm256_sub_ps(vv, _mm256_cvtepi32_ps(vi));
    const __m256i idx = _mm256_add_epi32(_mm256_mullo_epi32(vi, _mm256_set1_epi32(p.w)), ui);
    const int *base = reinterpret_cast<const int *>(p.hue);
    const __m256i top = _mm256_i32gather_epi32(base, idx, 2);
    const __m256i bot = _mm256_i32gather_epi32(base, _mm256_add_epi32(idx, _mm256_set1_epi32(p.w)), 2);
    const __m256i lo16 = _mm256_set1_epi32(0xffff);
    const __m256i hm = kInner ? _mm256_loadu_si256(reinterpret_cast<const __m256i *>(m.hue + i)) : _mm256_setzero_si256();
    const __m256 s00 = pixelScores8<kInner>(_mm256_and_si256(top, lo16), hm, t, cs);
    const __m256 s01 = pixelScores8<kInner>(_mm256_srli_epi32(top, 16), hm, t, cs);
    const __m256 s10 = pixelScores8<kInner>(_mm256_and_si256(bot, lo16), hm, t, cs);
    const __m256 s11 = pixelScores8<kInner>(_mm256_srli_epi32(bot, 16), hm, t, cs);
    const __m256 du = _mm256_sub_ps(s01, s00), dv = _mm256_sub_ps(s10, s00);
    const __m256 cross = _mm256_sub_ps(_mm256_sub_ps(s11, s10), du); // s11 - s10 - s01 + s00
    const __m256 w = _mm256_fmadd_ps(fu, _mm256_fmadd_ps(fv, cross, du), _mm256_fmadd_ps(fv, dv, s00));
    val = _mm256_add_ps(val, _mm256_and_ps(active, _mm256_blendv_ps(off, w, inside))); // nothing for an inactive lane
    out.inside += static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(_mm256_movemask_ps(inside))));
    // d(score)/du, d(score)/dv, then through the projection: g = d(score)/dX_c.
    const __m256 dwu = _mm256_and_ps(_mm256_fmadd_ps(fv, cross, du), inside), dwv = _mm256_and_ps(_mm256_fmadd_ps(fu, cross, dv), inside);
    const __m256 ux = _mm256_mul_ps(px, iz), vy = _mm256_mul_ps(py, iz);
    const __m256 gxp = _mm256_mul_ps(dwu, ux), gyp = _mm256_mul_ps(dwv, vy);
    const __m256 gzp = _mm256_sub_ps(zero, _mm256_fmadd_ps(gxp, xn, _mm256_mul_ps(gyp, yn)));
    gx = _mm256_add_ps(gx, gxp);
    gy = _mm256_add_ps(gy, gyp);
    gz = _mm256_add_ps(gz, gzp);
    tx = _mm256_add_ps(tx, _mm256_fmsub_ps(ay, gzp, _mm256_mul_ps(az, gyp)));
    ty = _mm256_add_ps(ty, _mm256_fmsub_ps(az, gxp, _mm256_mul_ps(ax, gzp)));
    tz = _mm256_add_ps(tz, _mm256_fmsub_ps(ax, gyp, _mm256_mul_ps(ay, gxp)));
    if (metric) {
      // Rows of the image motion per camera-frame twist (dv, dw): u: (ux, 0, uz, ay uz, az ux - ax uz, -ay ux),
      // v: (0, vy, vz, ay vz - az vy, -ax vz, ax vy); zero for a point off the image.
      const __m256 uxm = _mm256_and_ps(ux, inside), vym = _mm256_and_ps(vy, inside);
      const __m256 uz = _mm256_sub_ps(zero, _mm256_mul_ps(uxm, xn)), vz = _mm256_sub_ps(zero, _mm256_mul_ps(vym, yn));
      const __m256 ru[6] = {uxm, zero, uz, _mm256_mul_ps(ay, uz), _mm256_fmsub_ps(az, uxm, _mm256_mul_ps(ax, uz)), _mm256_sub_ps(zero, _mm256_mul_ps(ay, uxm))};
      const __m256 rv[6] = {zero, vym, vz, _mm256_fmsub_ps(ay, vz, _mm256_mul_ps(az, vym)), _mm256_sub_ps(zero, _mm256_mul_ps(ax, vz)), _mm256_mul_ps(ax, vym)};
      int k = 0;
      for (int r = 0; r < 6; ++r)
        for (int c = r; c < 6; ++c, ++k)
          M[k] = _mm256_fmadd_ps(ru[r], ru[c], _mm256_fmadd_ps(rv[r], rv[c], M[k]));
    }
  }
  out.value += hsumPs(val);
  out.G[0] += hsumPs(gx), out.G[1] += hsumPs(gy), out.G[2] += hsumPs(gz);
  out.T[0] += hsumPs(tx), out.T[1] += hsumPs(ty), out.T[2] += hsumPs(tz);
  if (metric)
    for (int k = 0; k < 21; ++k)
      out.M[k] += hsumPs(M[k]);
  return i;
}
#endif

std::int32_t deci(double deg) { return static_cast<std::int32_t>(std::lround(deg * 10.0)); }

} // namespace

const char *StereoFitness::kernelName() { return (!g_forceScalar && cpuHasAvx2()) ? "avx2" : "scalar"; }
void StereoFitness::forceScalar(bool on) { g_forceScalar = on; }

StereoFitness::StereoFitness(const StereoRig &rig, const PhotoModel &model, const FitnessParams &params)
    : m_params(params)
{
  rig.validate();
  model.validate("(in memory)");
  params.validate();
  const RigCamera *cams[2] = {&rig.left, &rig.right};
  for (int k = 0; k < 2; ++k) {
    const vpHomogeneousMatrix cMh = cams[k]->cMh();
    Camera &c = m_cams[k];
    for (unsigned r = 0; r < 3; ++r)
      for (unsigned col = 0; col < 4; ++col)
        c.cMh[4 * r + col] = cMh[r][col] * (col == 3 ? 1e3 : 1.0); // translation in mm
    c.px = static_cast<float>(cams[k]->cam.get_px());
    c.py = static_cast<float>(cams[k]->cam.get_py());
    c.u0 = static_cast<float>(cams[k]->cam.get_u0());
    c.v0 = static_cast<float>(cams[k]->cam.get_v0());
    c.width = static_cast<int>(cams[k]->width);
    c.height = static_cast<int>(cams[k]->height);
    m_distortion[static_cast<std::size_t>(k)] = cams[k]->distortion;
    m_intrinsics[static_cast<std::size_t>(k)] = cams[k]->cam;
    if (!cams[k]->distortion.isNone())
      m_undistort[static_cast<std::size_t>(k)] = std::make_shared<const UndistortMap>(*cams[k]);
  }
  m_nIn = model.inner.size();
  m_nOut = model.outer.size();
  // Every view's S_in then S_out, one after the other in the same arrays; view 0 is the model's own.
  auto addView = [&](const std::vector<ModelPoint> &in, const std::vector<ModelPoint> &out, const double cam[3]) {
    View v;
    v.inBegin = m_x.size();
    v.inEnd = v.outBegin = v.inBegin + in.size();
    v.outEnd = v.outBegin + out.size();
    m_order.resize(v.outEnd);
    v.inSplit = v.inBegin + (in.size() + kRejectStride - 1) / kRejectStride;
    v.outSplit = v.outBegin + (out.size() + kRejectStride - 1) / kRejectStride;
    const double norm = std::sqrt(cam[0] * cam[0] + cam[1] * cam[1] + cam[2] * cam[2]);
    for (int k = 0; k < 3; ++k)
      v.dir[k] = norm > 0 ? cam[k] / norm : 0.0;
    // Each set in the order 0, s, 2s, ..., 1, 1 + s, ... (s = kRejectStride): its first share is an
    // even sample of it, for early rejection. F counts classes, so the order changes nothing else.
    std::size_t modelIndex = m_x.size();
    for (const auto *set : {&in, &out}) {
      for (std::size_t first = 0; first < kRejectStride; ++first)
        for (std::size_t i = first; i < set->size(); i += kRejectStride) {
          m_order[modelIndex + i] = static_cast<std::uint32_t>(m_x.size());
          const ModelPoint &p = (*set)[i];
          m_x.push_back(p.x);
          m_y.push_back(p.y);
          m_z.push_back(p.z);
          m_hue.push_back(deci(p.hue) % 3600);
          m_hasDepth = m_hasDepth || p.z != 0.f;
        }
      modelIndex += set->size();
    }
    m_views.push_back(v);
  };
  addView(model.inner, model.outer, model.cameraMm);
  for (const ModelView &mv : model.views)
    addView(mv.inner, mv.outer, mv.cameraMm);
  if (m_views.size() > kScanViews) {
    if (m_views.size() > 65535)
      throw Error("a photo-model may hold at most 65,535 views");
    // Each cell's centre direction takes the nearest view.
    m_viewCube.resize(6 * kCubeCells * kCubeCells);
    for (int face = 0; face < 6; ++face)
      for (int j = 0; j < kCubeCells; ++j)
        for (int i = 0; i < kCubeCells; ++i) {
          const double s = 2.0 * (i + 0.5) / kCubeCells - 1.0, t = 2.0 * (j + 0.5) / kCubeCells - 1.0;
          const int axis = face / 2;
          const double sign = face % 2 ? -1.0 : 1.0;
          double d[3];
          d[axis] = sign;
          d[(axis + 1) % 3] = s;
          d[(axis + 2) % 3] = t;
          std::size_t best = 0;
          double bestDot = -1e9;
          for (std::size_t v = 0; v < m_views.size(); ++v) {
            const double dd = (m_views[v].dir[0] * d[0] + m_views[v].dir[1] * d[1] + m_views[v].dir[2] * d[2]);
            if (dd > bestDot) {
              bestDot = dd;
              best = v;
            }
          }
          m_viewCube[cubeCell(d)] = static_cast<std::uint16_t>(best);
        }
  }
  // The vector kernels read groups of 8 past a set's end (masked): padding.
  m_x.resize(m_x.size() + 8, 0.f);
  m_y.resize(m_y.size() + 8, 0.f);
  m_z.resize(m_z.size() + 8, 0.f);
  m_hue.resize(m_hue.size() + 8, 0);
  m_bgHue = deci(model.backgroundHue) % 3600;
  m_tolIn = deci(params.inTolDeg);
  m_tolInBg = deci(params.inBgTolDeg);
  m_tolOutBg = deci(params.outBgTolDeg);
}

void StereoFitness::setImages(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right)
{
  const std::array<PixelRect, 2> whole = {PixelRect{0, 0, m_cams[0].width, m_cams[0].height},
                                          PixelRect{0, 0, m_cams[1].width, m_cams[1].height}};
  setImages(left, right, whole);
}

void StereoFitness::setImages(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const std::array<PixelRect, 2> &windows)
{
  const vpImage<vpRGBa> *im[2] = {&left, &right};
  for (int k = 0; k < 2; ++k)
    if (static_cast<int>(im[k]->getWidth()) != m_cams[k].width || static_cast<int>(im[k]->getHeight()) != m_cams[k].height)
      throw Error(std::string(k == 0 ? "left" : "right") + " image is " + std::to_string(im[k]->getWidth()) + "x" +
                  std::to_string(im[k]->getHeight()) + " but the rig's camera is " + std::to_string(m_cams[k].width) +
                  "x" + std::to_string(m_cams[k].height));
  // The two planes on two cores (BatchPool: on the caller alone when the other core is busy).
  std::exception_ptr error[2];
  BatchPool::shared().run(2, [&](std::size_t k) {
    try {
      if (const auto &map = m_undistort[k])
        m_planes[k].compute(*im[k], m_params.minSaturation, *map);
      else
        m_planes[k].compute(*im[k], m_params.minSaturation, windows[k]);
    } catch (...) {
      error[k] = std::current_exception();
    }
  });
  for (const auto &e : error)
    if (e)
      std::rethrow_exception(e);
  m_hasImages = true;
}

void StereoFitness::addHueUnder(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const Phi *poses, std::size_t n)
{
  for (std::size_t k = 0; k < n; ++k)
    check(poses[k]);
  const vpImage<vpRGBa> *im[2] = {&left, &right};
  for (int cam = 0; cam < 2; ++cam)
    if (im[cam]->getWidth() != m_planes[static_cast<std::size_t>(cam)].width() ||
        im[cam]->getHeight() != m_planes[static_cast<std::size_t>(cam)].height())
      throw Error("fitness: the hue is added from images of another size than the last pair's");
  // The two cameras on two cores; addPixels cannot throw here (the sizes match, the pixels are in the image).
  BatchPool::shared().run(2, [&](std::size_t cam) {
    if (m_undistort[cam]) // its plane is the whole ideal image
      return;
    std::vector<std::int64_t> &pixels = m_pixelScratch[cam];
    pixels.clear();
    for (std::size_t k = 0; k < n; ++k) {
      const Projection p = projectionOf(static_cast<int>(cam), poses[k]);
      const View &view = viewFor(p);
#ifdef PM_HAVE_X86
      static const bool avx2 = cpuHasAvx2();
      const ModelSoA m{m_x.data(), m_y.data(), m_z.data(), m_hue.data()};
      if (avx2 && !g_forceScalar) // the counting kernel's projection, 8 points at a time
        (m_hasDepth ? collectPixelsAvx2<true> : collectPixelsAvx2<false>)(p, m, view.inBegin, view.outEnd, m_planes[cam].window(), pixels);
      else
#endif
        (m_hasDepth ? collectPixels<true> : collectPixels<false>)(p, m_x.data(), m_y.data(), m_z.data(), view.inBegin,
                                                                 view.outEnd, m_planes[cam].window(), pixels);
    }
    m_planes[cam].addPixels(*im[cam], m_params.minSaturation, pixels.data(), pixels.size());
  });
}

PixelRect StereoFitness::footprint(const Phi &phi, int camera) const
{
  if (!phi.isValid())
    throw Error("footprint of an invalid pose " + phi.toString());
  const Projection p = projectionOf(camera, phi);
  const View &view = viewFor(p);
  double umin = 1e9, vmin = 1e9, umax = -1e9, vmax = -1e9;
  for (std::size_t i = view.inBegin; i < view.outEnd; ++i) {
    const double X = m_x[i], Y = m_y[i], Z = m_z[i];
    const double zc = p.r[6] * X + p.r[7] * Y + p.r[8] * Z + p.t[2];
    if (zc <= 1e-3)
      continue;
    const double u = p.px * (p.r[0] * X + p.r[1] * Y + p.r[2] * Z + p.t[0]) / zc + p.u0;
    const double v = p.py * (p.r[3] * X + p.r[4] * Y + p.r[5] * Z + p.t[1]) / zc + p.v0;
    umin = std::min(umin, u), umax = std::max(umax, u), vmin = std::min(vmin, v), vmax = std::max(vmax, v);
  }
  if (umax < umin)
    return {};
  // A point at u lands on pixel round(u): the box of the pixels they land on, clipped.
  const PixelRect box{static_cast<int>(std::max(-1.0, std::floor(umin))), static_cast<int>(std::max(-1.0, std::floor(vmin))),
                      static_cast<int>(std::min(1e6, std::ceil(umax) + 1)), static_cast<int>(std::min(1e6, std::ceil(vmax) + 1))};
  return box.grown(0, p.w, p.h);
}

void StereoFitness::check(const Phi &phi) const
{
  if (!phi.isValid())
    throw Error("fitness of an invalid pose phi = " + phi.toString() + ": |eps| must be <= 1 and every value finite");
  if (!m_hasImages)
    throw Error("fitness: no stereo pair was given (call setImages first)");
}

Projection StereoFitness::projectionOf(int cam, const Phi &phi) const
{
  const Camera &c = m_cams[cam];
  const Rot3 R = rotationOf(phi);
  const double t[3] = {phi.x, phi.y, phi.z};
  Projection p;
  // cMo = cMh * hMo, in mm.
  for (int r = 0; r < 3; ++r) {
    for (int col = 0; col < 3; ++col)
      p.r[3 * r + col] = static_cast<float>(c.cMh[4 * r] * R[col] + c.cMh[4 * r + 1] * R[3 + col] + c.cMh[4 * r + 2] * R[6 + col]);
    p.t[r] = static_cast<float>(c.cMh[4 * r] * t[0] + c.cMh[4 * r + 1] * t[1] + c.cMh[4 * r + 2] * t[2] + c.cMh[4 * r + 3]);
  }
  p.px = c.px;
  p.py = c.py;
  p.u0 = c.u0;
  p.v0 = c.v0;
  p.w = c.width;
  p.h = c.height;
  p.hue = m_planes[static_cast<std::size_t>(cam)].data();
  return p;
}

std::size_t StereoFitness::cubeCell(const double c[3])
{
  const double a[3] = {std::fabs(c[0]), std::fabs(c[1]), std::fabs(c[2])};
  const int axis = a[0] >= a[1] && a[0] >= a[2] ? 0 : (a[1] >= a[2] ? 1 : 2);
  const double m = a[axis] > 0 ? a[axis] : 1.0;
  const int face = 2 * axis + (c[axis] < 0 ? 1 : 0);
  auto cell = [](double x) { // x in [-1, 1]
    const int k = static_cast<int>((x + 1.0) * 0.5 * kCubeCells);
    return std::min(kCubeCells - 1, std::max(0, k));
  };
  const int i = cell(c[(axis + 1) % 3] / m), j = cell(c[(axis + 2) % 3] / m);
  return (static_cast<std::size_t>(face) * kCubeCells + static_cast<std::size_t>(j)) * kCubeCells + static_cast<std::size_t>(i);
}

const StereoFitness::View &StereoFitness::viewFor(const Projection &p) const
{
  if (m_views.size() == 1)
    return m_views[0];
  // The camera's centre in the model frame, -R^T t of cMm, as a direction from the origin: the view
  // whose camera looked from the nearest direction.
  double c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = -(static_cast<double>(p.r[k]) * p.t[0] + static_cast<double>(p.r[3 + k]) * p.t[1] + static_cast<double>(p.r[6 + k]) * p.t[2]);
  if (!m_viewCube.empty())
    return m_views[m_viewCube[cubeCell(c)]];
  std::size_t best = 0;
  double bestDot = -2;
  for (std::size_t i = 0; i < m_views.size(); ++i) {
    const double d = m_views[i].dir[0] * c[0] + m_views[i].dir[1] * c[1] + m_views[i].dir[2] * c[2];
    if (d > bestDot) {
      bestDot = d;
      best = i;
    }
  }
  return m_views[best];
}

void StereoFitness::countView(const Projection &p, const View &v, int stage, FitnessCounts &counts) const
{
  const std::size_t inB = stage == 2 ? v.inSplit : v.inBegin, inE = stage == 1 ? v.inSplit : v.inEnd;
  const std::size_t outB = stage == 2 ? v.outSplit : v.outBegin, outE = stage == 1 ? v.outSplit : v.outEnd;
  const Tolerances tol{m_bgHue, m_tolIn, m_tolInBg, m_tolOutBg};
  const ModelSoA m{m_x.data(), m_y.data(), m_z.data(), m_hue.data()};
#ifdef PM_HAVE_X86
  static const bool avx2 = cpuHasAvx2();
  if (avx2 && !g_forceScalar) {
    if (m_hasDepth)
      countAvx2<true>(p, tol, m, inB, inE, outB, outE, counts);
    else
      countAvx2<false>(p, tol, m, inB, inE, outB, outE, counts);
    return;
  }
#endif
  if (m_hasDepth)
    countScalar<true>(p, tol, m, inB, inE, outB, outE, counts);
  else
    countScalar<false>(p, tol, m, inB, inE, outB, outE, counts);
}

FitnessCounts StereoFitness::countCamera(int cam, const Phi &phi) const
{
  const Projection p = projectionOf(cam, phi);
  FitnessCounts counts;
  countView(p, viewFor(p), 0, counts);
  return counts;
}

double StereoFitness::stereoScoreOrReject(const Phi &phi, double rejectBelow, double &cost) const
{
  const Projection p[2] = {projectionOf(0, phi), projectionOf(1, phi)};
  const View *v[2] = {&viewFor(p[0]), &viewFor(p[1])};
  FitnessCounts c[2];
  double estimate = 0, done = 0, all = 0;
  for (int cam = 0; cam < 2; ++cam) {
    countView(p[cam], *v[cam], 1, c[cam]);
    estimate += 0.5 * score(c[cam]); // the share's own mean score: an estimate of F_cam
    done += static_cast<double>((v[cam]->inSplit - v[cam]->inBegin) + (v[cam]->outSplit - v[cam]->outBegin));
    all += static_cast<double>((v[cam]->inEnd - v[cam]->inBegin) + (v[cam]->outEnd - v[cam]->outBegin));
  }
  if (estimate < rejectBelow) {
    cost = all > 0 ? done / all : 1.0;
    return estimate;
  }
  for (int cam = 0; cam < 2; ++cam)
    countView(p[cam], *v[cam], 2, c[cam]);
  cost = 1.0;
  return 0.5 * (score(c[0]) + score(c[1]));
}

double StereoFitness::visibleFraction(const Phi &phi, int camera) const
{
  if (!phi.isValid())
    throw Error("visible fraction at an invalid pose " + phi.toString());
  const Projection p = projectionOf(camera, phi);
  const View &view = viewFor(p);
  std::size_t in = 0;
  for (std::size_t i = view.inBegin; i < view.outEnd; ++i) {
    const double X = m_x[i], Y = m_y[i], Z = m_z[i];
    const double xc = p.r[0] * X + p.r[1] * Y + p.r[2] * Z + p.t[0], yc = p.r[3] * X + p.r[4] * Y + p.r[5] * Z + p.t[1];
    const double zc = p.r[6] * X + p.r[7] * Y + p.r[8] * Z + p.t[2];
    if (zc <= 1e-3)
      continue;
    const double u = p.px * xc / zc + p.u0, v = p.py * yc / zc + p.v0;
    in += u >= -0.5 && v >= -0.5 && u < p.w - 0.5 && v < p.h - 0.5;
  }
  return static_cast<double>(in) / static_cast<double>(view.outEnd - view.inBegin);
}

double StereoFitness::reprojectionRms(const Phi &a, const Phi &b) const
{
  if (!a.isValid() || !b.isValid())
    throw Error("reprojection between invalid poses " + a.toString() + " and " + b.toString());
  double sum = 0;
  std::size_t n = 0;
  for (int cam = 0; cam < 2; ++cam) {
    const Projection pa = projectionOf(cam, a), pb = projectionOf(cam, b);
    for (std::size_t i = 0; i < m_nIn + m_nOut; ++i) {
      double uv[2][2];
      bool front = true;
      for (int k = 0; k < 2; ++k) {
        const Projection &p = k ? pb : pa;
        const double X = m_x[i], Y = m_y[i], Z = m_z[i];
        const double xc = p.r[0] * X + p.r[1] * Y + p.r[2] * Z + p.t[0], yc = p.r[3] * X + p.r[4] * Y + p.r[5] * Z + p.t[1];
        const double zc = p.r[6] * X + p.r[7] * Y + p.r[8] * Z + p.t[2];
        front = front && zc > 1e-3;
        uv[k][0] = p.px * xc / zc + p.u0;
        uv[k][1] = p.py * yc / zc + p.v0;
      }
      if (!front)
        continue;
      sum += (uv[0][0] - uv[1][0]) * (uv[0][0] - uv[1][0]) + (uv[0][1] - uv[1][1]) * (uv[0][1] - uv[1][1]);
      ++n;
    }
  }
  return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

std::vector<PointScore> StereoFitness::pointScores(const Phi &phi, int camera) const
{
  check(phi);
  const Projection p = projectionOf(camera, phi);
  const View &view = viewFor(p);
  const Tolerances tol{m_bgHue, m_tolIn, m_tolInBg, m_tolOutBg};
  std::vector<PointScore> out;
  for (std::size_t k = view.inBegin; k < view.outEnd; ++k) { // in the model's order
    const std::size_t i = m_order[k];
    const bool inner = k < view.inEnd;
    FitnessCounts c;
    const std::int32_t h = m_hasDepth ? sampleScalar<true>(p, m_x[i], m_y[i], m_z[i]) : sampleScalar<false>(p, m_x[i], m_y[i], 0.f);
    if (inner)
      classifyIn(h, m_hue[i], tol, c);
    else
      classifyOut(h, tol, c);
    PointScore s;
    const float X = m_x[i], Y = m_y[i], Z = m_z[i];
    const float xc = p.r[0] * X + p.r[1] * Y + p.r[2] * Z + p.t[0], yc = p.r[3] * X + p.r[4] * Y + p.r[5] * Z + p.t[1];
    const float zc = p.r[6] * X + p.r[7] * Y + p.r[8] * Z + p.t[2];
    s.u = zc > 0 ? p.px * xc / zc + p.u0 : -1.f;
    s.v = zc > 0 ? p.py * yc / zc + p.v0 : -1.f;
    const LensDistortion &lens = m_distortion[static_cast<std::size_t>(camera)];
    if (zc > 0 && !lens.isNone()) {
      const vpImagePoint raw = lens.distort(m_intrinsics[static_cast<std::size_t>(camera)], vpImagePoint(s.v, s.u));
      s.u = static_cast<float>(raw.get_u());
      s.v = static_cast<float>(raw.get_v());
    }
    s.inner = inner;
    s.cls = c.inMatch ? PointScore::InMatch
            : c.inBackground ? PointScore::InBackground
            : c.inOther ? PointScore::InOther
            : c.outBackground ? PointScore::OutBackground
            : c.outOther ? PointScore::OutOther
                         : PointScore::Off;
    out.push_back(s);
  }
  return out;
}

double StereoFitness::score(const FitnessCounts &c) const
{
  const FitnessParams &q = m_params;
  const double sum = q.inMatch * c.inMatch + q.inBackground * c.inBackground + q.inOther * c.inOther +
                     q.offImage * (c.inOff + c.outOff) + q.outBackground * c.outBackground + q.outOther * c.outOther;
  const int nIn = c.inMatch + c.inBackground + c.inOther + c.inOff, nOut = c.outBackground + c.outOther + c.outOff;
  return normalised(sum, static_cast<std::size_t>(nIn), static_cast<std::size_t>(nOut));
}

double StereoFitness::normalised(double sum, std::size_t nIn, std::size_t nOut) const
{
  if (nIn == m_nIn && nOut == m_nOut) // the model's own view: Eq. (10) as the paper writes it, to the bit
    return sum / static_cast<double>(nIn + nOut);
  // A further view holds other numbers of S_in and S_out points, so its best attainable score
  // (every S_in point on its hue, every S_out point on background) differs: scaled to the model's
  // own view's, so that no view wins by its proportions alone.
  const FitnessParams &q = m_params;
  const double best0 = (q.inMatch * static_cast<double>(m_nIn) + q.outBackground * static_cast<double>(m_nOut)) /
                       static_cast<double>(m_nIn + m_nOut);
  return sum * best0 / (q.inMatch * static_cast<double>(nIn) + q.outBackground * static_cast<double>(nOut));
}

double StereoFitness::evaluate(const Phi &phi) const
{
  check(phi);
  return stereoScore(phi);
}

void StereoFitness::evaluate(const Phi *phis, std::size_t n, double *out) const
{
  for (std::size_t i = 0; i < n; ++i) // first, so that nothing throws inside the parallel loop
    check(phis[i]);
  // On two cores (BatchPool: the caller never waits for the helper to start). Each result depends
  // on its pose only, so they are the same whoever computes them.
  BatchPool::shared().run(n, [&](std::size_t i) { out[i] = stereoScore(phis[i]); });
}

void StereoFitness::evaluate(const Phi *phis, std::size_t n, double *out, double rejectBelow, double *cost) const
{
  for (std::size_t i = 0; i < n; ++i)
    check(phis[i]);
  BatchPool::shared().run(n, [&](std::size_t i) { out[i] = stereoScoreOrReject(phis[i], rejectBelow, cost[i]); });
}

void StereoFitness::smoothSumsScalar(const Projection &p, std::size_t b, std::size_t e, std::size_t inEnd, bool metric,
                                     SmoothSums &out) const
{
  const FitnessParams &q = m_params;
  const Tolerances tol{m_bgHue, m_tolIn, m_tolInBg, m_tolOutBg};
  // A pixel's score for an S_in point of hue hm (or, hm < 0, for an S_out point): the classes of
  // Eqs. (8), (9) as the kernels count them.
  auto pixelScore = [&](std::int32_t h, std::int32_t hm) {
    FitnessCounts c;
    if (hm >= 0)
      classifyIn(h, hm, tol, c);
    else
      classifyOut(h, tol, c);
    return q.inMatch * c.inMatch + q.inBackground * c.inBackground + q.inOther * c.inOther +
           q.outBackground * c.outBackground + q.outOther * c.outOther;
  };
  double M[21] = {0};
  for (std::size_t i = b; i < e; ++i) {
    const double X = m_x[i], Y = m_y[i], Z = m_z[i];
    const double xc = p.r[0] * X + p.r[1] * Y + p.r[2] * Z + p.t[0], yc = p.r[3] * X + p.r[4] * Y + p.r[5] * Z + p.t[1];
    const double zc = p.r[6] * X + p.r[7] * Y + p.r[8] * Z + p.t[2];
    if (!(zc > 1e-3)) {
      out.value += q.offImage;
      continue;
    }
    const double u = p.px * xc / zc + p.u0, v = p.py * yc / zc + p.v0;
    if (!(u >= 0 && v >= 0 && u < p.w - 1 && v < p.h - 1)) {
      out.value += q.offImage;
      continue;
    }
    const int ui = static_cast<int>(u), vi = static_cast<int>(v);
    const double fu = u - ui, fv = v - vi;
    ++out.inside;
    const std::uint16_t *row = p.hue + static_cast<std::size_t>(vi) * static_cast<std::size_t>(p.w) + static_cast<std::size_t>(ui);
    const std::int32_t hm = i < inEnd ? m_hue[i] : -1;
    const double s00 = pixelScore(row[0], hm), s01 = pixelScore(row[1], hm), s10 = pixelScore(row[p.w], hm), s11 = pixelScore(row[p.w + 1], hm);
    out.value += (1 - fv) * ((1 - fu) * s00 + fu * s01) + fv * ((1 - fu) * s10 + fu * s11);
    // The derivatives: through u, v to the point's camera-frame position X_c, and a = X_c - t.
    const double iz = 1.0 / zc, ux = p.px * iz, vy = p.py * iz, uz = -ux * xc * iz, vz = -vy * yc * iz;
    const double a[3] = {xc - p.t[0], yc - p.t[1], zc - p.t[2]};
    const double dwu = (1 - fv) * (s01 - s00) + fv * (s11 - s10), dwv = (1 - fu) * (s10 - s00) + fu * (s11 - s01);
    const double g[3] = {dwu * ux, dwv * vy, dwu * uz + dwv * vz};
    for (int k = 0; k < 3; ++k)
      out.G[k] += g[k];
    out.T[0] += a[1] * g[2] - a[2] * g[1];
    out.T[1] += a[2] * g[0] - a[0] * g[2];
    out.T[2] += a[0] * g[1] - a[1] * g[0];
    if (metric) {
      const double ru[6] = {ux, 0, uz, a[1] * uz, a[2] * ux - a[0] * uz, -a[1] * ux};
      const double rv[6] = {0, vy, vz, a[1] * vz - a[2] * vy, -a[0] * vz, a[0] * vy};
      addMetricRows(ru, rv, M);
    }
  }
  if (metric)
    for (int k = 0; k < 21; ++k)
      out.M[k] += M[k];
}

double StereoFitness::smoothCamera(int cam, const Phi &phi, bool vectorised, bool metric, double *grad, double *metricOut,
                                   std::size_t *inside) const
{
  const Projection p = projectionOf(cam, phi);
  const View &view = viewFor(p);
  SmoothSums sums;
  std::size_t inRest = view.inBegin, outRest = view.outBegin;
#ifdef PM_HAVE_X86
  static const bool avx2 = cpuHasAvx2();
  if (vectorised && avx2 && !g_forceScalar) {
    const Tolerances tol{m_bgHue, m_tolIn, m_tolInBg, m_tolOutBg};
    const FitnessParams &q = m_params;
    const ClassScores cs{static_cast<float>(q.inMatch), static_cast<float>(q.inBackground), static_cast<float>(q.inOther),
                         static_cast<float>(q.outBackground), static_cast<float>(q.outOther), static_cast<float>(q.offImage)};
    const ModelSoA m{m_x.data(), m_y.data(), m_z.data(), m_hue.data()};
    inRest = smoothSumsAvx2<true>(p, tol, cs, m, view.inBegin, view.inEnd, metric, sums);
    outRest = smoothSumsAvx2<false>(p, tol, cs, m, view.outBegin, view.outEnd, metric, sums);
  }
#endif
  smoothSumsScalar(p, inRest, view.inEnd, view.inEnd, metric, sums);
  smoothSumsScalar(p, outRest, view.outEnd, view.inEnd, metric, sums);
  const std::size_t nIn = view.inEnd - view.inBegin, nOut = view.outEnd - view.outBegin;
  if (inside)
    *inside += sums.inside;
  if (grad) {
    // Camera frame -> hand frame: d/dv_h = R_ch^T d/dv_c (R_ch the rows of cMh), the same for the rotation.
    const double unit = normalised(1.0, nIn, nOut);
    const double *C = m_cams[cam].cMh;
    for (int k = 0; k < 3; ++k) {
      grad[k] += unit * (C[k] * sums.G[0] + C[4 + k] * sums.G[1] + C[8 + k] * sums.G[2]);
      grad[3 + k] += unit * (C[k] * sums.T[0] + C[4 + k] * sums.T[1] + C[8 + k] * sums.T[2]);
    }
  }
  if (metric && metricOut) {
    // M_h = B^T M_c B with B = blockdiag(R_ch, R_ch).
    double Mc[36];
    for (int r = 0, k = 0; r < 6; ++r)
      for (int c = r; c < 6; ++c, ++k)
        Mc[6 * r + c] = Mc[6 * c + r] = sums.M[k];
    const double *C = m_cams[cam].cMh;
    auto B = [C](int r, int c) { return (r < 3) == (c < 3) ? C[4 * (r % 3) + (c % 3)] : 0.0; };
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) {
        double acc = 0;
        for (int k = 0; k < 6; ++k)
          for (int l = 0; l < 6; ++l)
            acc += B(k, r) * Mc[6 * k + l] * B(l, c);
        metricOut[6 * r + c] += acc;
      }
  }
  return normalised(sums.value, nIn, nOut);
}

double StereoFitness::evaluateSmoothGradient(const Phi &phi, double grad[6], double *metric) const
{
  check(phi);
  // The two cameras on two cores, each into its own sums (BatchPool: on the caller alone when the other core is busy).
  double camG[2][6] = {{0, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 0}}, camM[2][36], camS[2];
  std::size_t camInside[2] = {0, 0};
  BatchPool::shared().run(2, [&](std::size_t cam) {
    if (metric)
      std::fill(camM[cam], camM[cam] + 36, 0.0);
    camS[cam] = smoothCamera(static_cast<int>(cam), phi, true, metric != nullptr, camG[cam], metric ? camM[cam] : nullptr, &camInside[cam]);
  });
  const double s = 0.5 * (camS[0] + camS[1]);
  const std::size_t inside = camInside[0] + camInside[1];
  for (int k = 0; k < 6; ++k)
    grad[k] = 0.5 * (camG[0][k] + camG[1][k]);
  if (metric) // the mean over the points in the images
    for (int k = 0; k < 36; ++k)
      metric[k] = inside ? (camM[0][k] + camM[1][k]) / static_cast<double>(inside) : 0.0;
  return s;
}

double StereoFitness::evaluateSmooth(const Phi &phi) const
{
  check(phi);
  return 0.5 * (smoothCamera(0, phi, false, false, nullptr, nullptr, nullptr) + smoothCamera(1, phi, false, false, nullptr, nullptr, nullptr));
}

FitnessDetail StereoFitness::evaluateDetail(const Phi &phi) const
{
  check(phi);
  FitnessDetail d;
  d.countsLeft = countCamera(0, phi);
  d.countsRight = countCamera(1, phi);
  d.left = score(d.countsLeft);
  d.right = score(d.countsRight);
  d.fitness = 0.5 * (d.left + d.right);
  return d;
}

} // namespace pm::core
