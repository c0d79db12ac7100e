#pragma once
/*!
  \file SmoothKernels.h
  The smooth score's AVX2 kernel (internal to core, not installed): each point's four neighbouring
  pixels scored and interpolated bilinearly, the derivatives with respect to its camera-frame
  position, and the image-motion metric.
*/
#include "FitnessKernels.h"

namespace pm::core::kernels {

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

} // namespace pm::core::kernels
