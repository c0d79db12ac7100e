#include "pm/core/StereoScorer.h"

#include <algorithm>

#include "SmoothKernels.h"
#include "pm/core/BatchPool.h"

namespace pm::core {

void StereoScorer::smoothSumsScalar(const HueFrame &f, const Projection &p, std::size_t b, std::size_t e, std::size_t inEnd, bool metric,
                                     SmoothSums &out) const
{
  const FitnessParams &q = m_params;
  const kernels::Tolerances tol = tolerances(f);
  // A pixel's score for an S_in point of hue hm (or, hm < 0, for an S_out point): the classes of
  // Eqs. (8), (9) as the kernels count them.
  auto pixelScore = [&](std::int32_t h, std::int32_t hm) {
    FitnessCounts c;
    if (hm >= 0)
      kernels::classifyIn(h, hm, tol, c);
    else
      kernels::classifyOut(h, tol, c);
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
      kernels::addMetricRows(ru, rv, M);
    }
  }
  if (metric)
    for (int k = 0; k < 21; ++k)
      out.M[k] += M[k];
}

double StereoScorer::smoothCamera(const HueFrame &f, int cam, const Phi &phi, bool vectorised, bool metric, double *grad, double *metricOut,
                                   std::size_t *inside) const
{
  const Projection p = projectionOf(cam, phi, &f);
  const View &view = viewFor(p);
  SmoothSums sums;
  std::size_t inRest = view.inBegin, outRest = view.outBegin;
#ifdef PM_HAVE_X86
  if (vectorised && m_avx2) {
    const kernels::Tolerances tol = tolerances(f);
    const FitnessParams &q = m_params;
    const kernels::ClassScores cs{static_cast<float>(q.inMatch), static_cast<float>(q.inBackground), static_cast<float>(q.inOther),
                         static_cast<float>(q.outBackground), static_cast<float>(q.outOther), static_cast<float>(q.offImage)};
    const kernels::ModelSoA m{m_x.data(), m_y.data(), m_z.data(), m_hue.data()};
    inRest = kernels::smoothSumsAvx2<true>(p, tol, cs, m, view.inBegin, view.inEnd, metric, sums);
    outRest = kernels::smoothSumsAvx2<false>(p, tol, cs, m, view.outBegin, view.outEnd, metric, sums);
  }
#endif
  smoothSumsScalar(f, p, inRest, view.inEnd, view.inEnd, metric, sums);
  smoothSumsScalar(f, p, outRest, view.outEnd, view.inEnd, metric, sums);
  const std::size_t nIn = view.inEnd - view.inBegin, nOut = view.outEnd - view.outBegin;
  if (inside)
    *inside += sums.inside;
  if (grad) {
    // Camera frame -> hand frame: d/dv_h = R_ch^T d/dv_c (R_ch the rows of cMh), the same for the rotation.
    const double unit = normalised(1.0, nIn, nOut);
    const double *C = m_cams[cam].R;
    for (int k = 0; k < 3; ++k) {
      grad[k] += unit * (C[k] * sums.G[0] + C[3 + k] * sums.G[1] + C[6 + k] * sums.G[2]);
      grad[3 + k] += unit * (C[k] * sums.T[0] + C[3 + k] * sums.T[1] + C[6 + k] * sums.T[2]);
    }
  }
  if (metric && metricOut) {
    // M_h = B^T M_c B with B = blockdiag(R_ch, R_ch).
    double Mc[36];
    for (int r = 0, k = 0; r < 6; ++r)
      for (int c = r; c < 6; ++c, ++k)
        Mc[6 * r + c] = Mc[6 * c + r] = sums.M[k];
    const double *C = m_cams[cam].R;
    auto B = [C](int r, int c) { return (r < 3) == (c < 3) ? C[3 * (r % 3) + (c % 3)] : 0.0; };
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

double StereoScorer::evaluateSmoothGradient(const HueFrame &f, const Phi &phi, double grad[6], double *metric) const
{
  check(f, phi);
  // The cameras on two cores, each into its own sums (BatchPool: on the caller alone when the other core is busy).
  constexpr std::size_t K = CameraRig::kMaxCameras;
  double camG[K][6] = {}, camM[K][36], camS[K] = {};
  std::size_t camInside[K] = {};
  const std::size_t n = static_cast<std::size_t>(m_nCams);
  BatchPool::shared().run(n, [&](std::size_t cam) {
    if (metric)
      std::fill(camM[cam], camM[cam] + 36, 0.0);
    camS[cam] = smoothCamera(f, static_cast<int>(cam), phi, true, metric != nullptr, camG[cam], metric ? camM[cam] : nullptr, &camInside[cam]);
  });
  // Means over the cameras, summed in camera order (a stereo rig: (left + right) / 2 to the bit).
  double s = camS[0];
  std::size_t inside = camInside[0];
  for (std::size_t c = 1; c < n; ++c) {
    s += camS[c];
    inside += camInside[c];
  }
  for (int k = 0; k < 6; ++k) {
    double g = camG[0][k];
    for (std::size_t c = 1; c < n; ++c)
      g += camG[c][k];
    grad[k] = g * m_camWeight;
  }
  if (metric) // the mean over the points in the images
    for (int k = 0; k < 36; ++k) {
      double m = camM[0][k];
      for (std::size_t c = 1; c < n; ++c)
        m += camM[c][k];
      metric[k] = inside ? m / static_cast<double>(inside) : 0.0;
    }
  return s * m_camWeight;
}

double StereoScorer::evaluateSmooth(const HueFrame &f, const Phi &phi) const
{
  check(f, phi);
  double s = smoothCamera(f, 0, phi, false, false, nullptr, nullptr, nullptr);
  for (int cam = 1; cam < m_nCams; ++cam)
    s += smoothCamera(f, cam, phi, false, false, nullptr, nullptr, nullptr);
  return s * m_camWeight;
}

} // namespace pm::core
