#include "pm/precise/CorrespondenceLines.h"

#include <algorithm>
#include <cmath>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

#include "pm/core/Error.h"

namespace pm::precise {

void LineShape::prepare()
{
  if (functionLength < 2 || functionLength > kMaxFunction || functionLength % 2 != 0)
    throw core::Error("precise stage: the smoothed step must span an even number of segments in [2, " + std::to_string(kMaxFunction) + "]");
  if (distributionLength < 3 || distributionLength > kMaxDistribution)
    throw core::Error("precise stage: the distribution's length must lie in [3, " + std::to_string(kMaxDistribution) + "] segments");
  if (!(amplitude > 0 && amplitude < 0.5) || !(slope >= 0 && slope <= 10))
    throw core::Error("precise stage: the step's amplitude must lie in (0, 0.5) and its slope in [0, 10] segments");
  for (int i = 0; i < functionLength; ++i) {
    const double x = i - 0.5 * (functionLength - 1);
    const double f = slope > 0 ? 0.5 - amplitude * std::tanh(x / (2 * slope)) : 0.5 - amplitude * ((x > 0) - (x < 0));
    foreground[static_cast<std::size_t>(i)] = static_cast<float>(f);
    background[static_cast<std::size_t>(i)] = static_cast<float>(1 - f);
  }
  // A perfect edge seen through the step: the variance it still leaves (Laplace-like tails) or its slope.
  const double a = std::atanh(2 * amplitude);
  minVariance = std::max(1.0 / (2 * a * a), slope);
}

namespace {

//! cMo of camera \e cam at pose \e phi: R (row-major) and t (mm); and hRo.
struct Composed
{
  double R[9], t[3], hRo[9];
};

ModelInCamera modelIn(const Composed &c)
{
  ModelInCamera m;
  std::copy(c.R, c.R + 9, m.R);
  std::copy(c.t, c.t + 3, m.t);
  return m;
}

Composed compose(const LineCamera &cam, const core::Phi &phi)
{
  Composed c;
  const core::Rot3 h = core::rotationOf(phi);
  std::copy(h.begin(), h.end(), c.hRo);
  const double th[3] = {phi.x, phi.y, phi.z};
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k)
      c.R[3 * r + k] = cam.R[3 * r] * h[static_cast<std::size_t>(k)] + cam.R[3 * r + 1] * h[static_cast<std::size_t>(3 + k)] +
                       cam.R[3 * r + 2] * h[static_cast<std::size_t>(6 + k)];
    c.t[r] = cam.R[3 * r] * th[0] + cam.R[3 * r + 1] * th[1] + cam.R[3 * r + 2] * th[2] + cam.t[r];
  }
  return c;
}

inline void apply(const double R[9], const double t[3], const float X[3], double out[3])
{
  for (int r = 0; r < 3; ++r)
    out[r] = R[3 * r] * X[0] + R[3 * r + 1] * X[1] + R[3 * r + 2] * X[2] + t[r];
}

//! The raw pixel index under ideal pixel (x, y), or -1 off the image.
/*!
  std::lrint(x) inline (to nearest, ties to even, in the default rounding mode): on x86-64 the
  instruction glibc's lrint is, without the library call (collectColours rounds twice a pixel).
*/
inline long roundToLong(double x)
{
#if defined(__x86_64__)
  return _mm_cvtsd_si64(_mm_set_sd(x));
#else
  return std::lrint(x);
#endif
}

inline long pixelAt(const LineCamera &cam, long x, long y)
{
  if (x < 0 || y < 0 || x >= cam.w || y >= cam.h)
    return -1;
  const long i = y * cam.w + x;
  return cam.nearest ? cam.nearest[i] : i;
}

#if defined(__x86_64__) || defined(__i386__)
bool haveAvx2() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }

/*!
  The distribution for a step of 8 segments, 8 lanes at a time: out[d] = prod_j (f[d + j] hf[j] +
  b[d + j] hb[j]) for d < D; returns its sum. The same products as the scalar loop, in another order.
*/
__attribute__((target("avx2,fma"))) float distribution8(const float *f, const float *b, const float *hf, const float *hb, int D, float *out)
{
  const __m256 HF = _mm256_loadu_ps(hf), HB = _mm256_loadu_ps(hb);
  float area = 0;
  for (int d = 0; d < D; ++d) {
    __m256 v = _mm256_fmadd_ps(_mm256_loadu_ps(f + d), HF, _mm256_mul_ps(_mm256_loadu_ps(b + d), HB));
    __m128 h = _mm_mul_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    h = _mm_mul_ps(h, _mm_movehl_ps(h, h));
    h = _mm_mul_ss(h, _mm_shuffle_ps(h, h, 1));
    out[d] = _mm_cvtss_f32(h);
    area += out[d];
  }
  return area;
}
#endif

//! A contour point seen by a camera: where it projects, the outline's normal there, pixels per mm at its depth.
struct Projected
{
  double X[3], u, v, nu, nv, pxPerMm;
};

//! Projects contour point \e q through cMo \e c of camera \e cam; false behind the camera or when the normal is along the view.
inline bool projectContour(const LineCamera &cam, const Composed &c, const core::ContourPoint &q, Projected &p)
{
  const float X[3] = {q.x, q.y, q.z};
  double Xc[3];
  apply(c.R, c.t, X, Xc);
  if (!(Xc[2] > 1.0))
    return false;
  const double nx = c.R[0] * q.nx + c.R[1] * q.ny + c.R[2] * q.nz, ny = c.R[3] * q.nx + c.R[4] * q.ny + c.R[5] * q.nz;
  const double nn = std::hypot(nx, ny);
  if (!(nn > 1e-6))
    return false;
  p.X[0] = X[0], p.X[1] = X[1], p.X[2] = X[2];
  p.u = cam.px * Xc[0] / Xc[2] + cam.u0, p.v = cam.py * Xc[1] / Xc[2] + cam.v0;
  p.nu = nx / nn, p.nv = ny / nn;
  p.pxPerMm = cam.px / Xc[2];
  return true;
}

//! The contour points of the viewpoint \e view the lines use: \e count of them, evenly spread.
struct Selection
{
  std::size_t begin, n, count;
  std::size_t at(std::size_t k) const { return begin + k * n / count; }
};

Selection select(const OutlineViews &outlines, std::size_t view, std::size_t maxLines)
{
  const OutlineViews::View &v = outlines.view(view);
  const std::size_t n = v.end - v.begin;
  return {v.begin, n, std::min(n, maxLines)};
}

} // namespace

void composeCamera(const LineCamera &cam, const core::Phi &phi, double R[9], double t[3], core::Rot3 &hRo)
{
  hRo = core::rotationOf(phi);
  const double th[3] = {phi.x, phi.y, phi.z};
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k)
      R[3 * r + k] = cam.R[3 * r] * hRo[static_cast<std::size_t>(k)] + cam.R[3 * r + 1] * hRo[static_cast<std::size_t>(3 + k)] +
                     cam.R[3 * r + 2] * hRo[static_cast<std::size_t>(6 + k)];
    t[r] = cam.R[3 * r] * th[0] + cam.R[3 * r + 1] * th[1] + cam.R[3 * r + 2] * th[2] + cam.t[r];
  }
}


void cameraInModel(const LineCamera &cam, const core::Phi &phi, double out[3])
{
  // The camera centre in the hand frame, -R^T t, then into the model frame: hRo^T (c - t_o).
  double c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = -(cam.R[k] * cam.t[0] + cam.R[3 + k] * cam.t[1] + cam.R[6 + k] * cam.t[2]);
  const core::Rot3 h = core::rotationOf(phi);
  const double d[3] = {c[0] - phi.x, c[1] - phi.y, c[2] - phi.z};
  for (int k = 0; k < 3; ++k)
    out[k] = h[static_cast<std::size_t>(k)] * d[0] + h[static_cast<std::size_t>(3 + k)] * d[1] + h[static_cast<std::size_t>(6 + k)] * d[2];
}

CorrespondenceLines::CorrespondenceLines(std::size_t maxLines, int maxSegments, int maxScale)
    : m_lines(maxLines), m_hidden(maxLines), m_segF(static_cast<std::size_t>(maxSegments)), m_segB(static_cast<std::size_t>(maxSegments)),
      m_dist(LineShape::kMaxDistribution), m_maxSegments(maxSegments), m_maxScale(maxScale)
{
}

std::size_t CorrespondenceLines::measure(const LineCamera &cam, const OutlineViews &outlines, const core::Phi &phi, const LineShape &shape,
                                         const ColourHistograms &colours, int scale, std::size_t maxLines, double minContinuous)
{
  m_n = 0;
  m_nHidden = 0;
  const int L = shape.segments();
  if (L > m_maxSegments || scale > m_maxScale || scale < 1)
    throw core::Error("precise stage: a line of " + std::to_string(L) + " segments of " + std::to_string(scale) +
                " px exceeds the buffers");
  const Composed c = compose(cam, phi);
  double cm[3];
  cameraInModel(cam, phi, cm);
  m_view = outlines.nearest(cm);
  const Selection sel = select(outlines, m_view, std::min(maxLines, m_lines.size()));
  const ModelInCamera here = modelIn(c), there = m_occlusion ? modelIn(compose(*m_other, phi)) : here;
  const int P = L * scale;
  const int D = shape.distributionLength, F = shape.functionLength;
  for (std::size_t k = 0; k < sel.count; ++k) {
    const core::ContourPoint &q = outlines.point(sel.at(k));
    Projected pr;
    if (!projectContour(cam, c, q, pr))
      continue;
    const double u = pr.u, v = pr.v, nu = pr.nu, nv = pr.nv;
    if (std::min(q.insideMm, q.outsideMm) * pr.pxPerMm / scale < minContinuous)
      continue;
    const bool hidden = m_occlusion && hiddenHere(cam, q, here, cm, there, pr.pxPerMm);
    // The segments' probabilities of lying on the target, from the inside end outward. The line steps
    // one pixel at a time along its dominant axis (the other coordinate rounded), so that every
    // pixel's place along the normal is known exactly: t_k = t0 + k / |n_dominant|.
    const bool alongU = std::fabs(nu) >= std::fabs(nv);
    const double nd = alongU ? nu : nv, nm = alongU ? nv : nu, cd = alongU ? u : v, cMinor = alongU ? v : u;
    const double sg = nd > 0 ? 1.0 : -1.0, pxStep = 1.0 / std::fabs(nd);
    const long start = std::lrint(cd - sg * (0.5 * P - 0.5));
    const double t0 = (static_cast<double>(start) - cd) / nd;
    // The whole line on the image (a straight line: its ends), then its pixels without further checks.
    const double mStart = cMinor + t0 * nm, mStep = pxStep * nm, mEnd = mStart + (P - 1) * mStep;
    const long majorEnd = start + static_cast<long>(sg) * (P - 1);
    const long majorMax = alongU ? cam.w : cam.h, minorMax = alongU ? cam.h : cam.w;
    if (std::min(start, majorEnd) < 0 || std::max(start, majorEnd) >= majorMax || std::min(mStart, mEnd) < -0.5 ||
        std::max(mStart, mEnd) + 0.5 >= static_cast<double>(minorMax))
      continue;
    const long majorStep = alongU ? static_cast<long>(sg) : static_cast<long>(sg) * cam.w, minorStride = alongU ? cam.w : 1;
    long major = alongU ? start : start * cam.w;
    double mc = mStart + 0.5; // rounded by truncation: mc >= 0 here
    bool ok = true;
    for (int s = 0; s < L && ok; ++s) {
      float pf = 1.f, pb = 1.f;
      for (int j = 0; j < scale; ++j, major += majorStep, mc += mStep) {
        long idx = major + static_cast<long>(mc) * minorStride;
        if (cam.nearest && (idx = cam.nearest[idx]) < 0) {
          ok = false;
          break;
        }
        const float post = colours.posterior(cam.image[idx]);
        pf *= post;
        pb *= 1.f - post;
      }
      const float sum = pf + pb;
      m_segF[static_cast<std::size_t>(s)] = sum > 0 ? pf / sum : 0.5f;
      m_segB[static_cast<std::size_t>(s)] = sum > 0 ? pb / sum : 0.5f;
    }
    if (!ok)
      continue;
    // The outline's position: the smoothed step slid along the line.
    float area = 0;
#if defined(__x86_64__) || defined(__i386__)
    static const bool avx2 = haveAvx2();
    if (avx2 && F == 8)
      area = distribution8(m_segF.data(), m_segB.data(), shape.foreground.data(), shape.background.data(), D, m_dist.data());
    else
#endif
      for (int d = 0; d < D; ++d) {
        float p = 1.f;
        for (int j = 0; j < F; ++j)
          p *= m_segF[static_cast<std::size_t>(d + j)] * shape.foreground[static_cast<std::size_t>(j)] +
               m_segB[static_cast<std::size_t>(d + j)] * shape.background[static_cast<std::size_t>(j)];
        m_dist[static_cast<std::size_t>(d)] = p;
        area += p;
      }
    if (!(area > 0))
      continue;
    double mean = 0, var = 0;
    for (int d = 0; d < D; ++d)
      mean += d * static_cast<double>(m_dist[static_cast<std::size_t>(d)] / area);
    for (int d = 0; d < D; ++d)
      var += (d - mean) * (d - mean) * static_cast<double>(m_dist[static_cast<std::size_t>(d)] / area);
    double sep = 0;
    for (int s = 0; s < L; ++s)
      sep += std::fabs(m_segF[static_cast<std::size_t>(s)] - m_segB[static_cast<std::size_t>(s)]);
    LineMeasure &m = hidden ? m_hidden[m_nHidden++] : m_lines[m_n++];
    m.X[0] = static_cast<float>(pr.X[0]), m.X[1] = static_cast<float>(pr.X[1]), m.X[2] = static_cast<float>(pr.X[2]);
    m.cu = static_cast<float>(u), m.cv = static_cast<float>(v);
    m.nu = static_cast<float>(nu), m.nv = static_cast<float>(nv);
    // The step centred on the boundary before segment d + F/2: t = t0 + ((d + F/2) scale - 1/2) pxStep.
    const double segPx = scale * pxStep;
    m.mean = static_cast<float>(t0 + ((mean + 0.5 * F) * scale - 0.5) * pxStep);
    m.variance = static_cast<float>(std::max(var, shape.minVariance) * segPx * segPx);
    m.separation = static_cast<float>(sep / L);
  }
  if (m_nHidden > 0 && static_cast<double>(m_nHidden) > m_occlusion->params().maxHiddenShare * static_cast<double>(m_n + m_nHidden)) {
    // Too much hidden to be an occluder in front of a right pose: every line counts.
    std::copy(m_hidden.begin(), m_hidden.begin() + static_cast<long>(m_nHidden), m_lines.begin() + static_cast<long>(m_n));
    m_n += m_nHidden;
    m_nHidden = 0;
  }
  return m_n;
}

bool CorrespondenceLines::hiddenHere(const LineCamera &cam, const core::ContourPoint &q, const ModelInCamera &self, const double centre[3],
                                     const ModelInCamera &other, double pxPerMm) const
{
  return m_occlusion->hidden(cam, self, centre, *m_other, other, q, pxPerMm);
}

std::size_t CorrespondenceLines::accumulate(const LineCamera &cam, const core::Phi &phi, double weight, double g[6], double H[36],
                                            double *residual2) const
{
  const Composed c = compose(cam, phi);
  std::size_t n = 0;
  double Hl[21] = {0}; // upper triangle
  for (std::size_t i = 0; i < m_n; ++i) {
    const LineMeasure &m = m_lines[i];
    double Xc[3];
    apply(c.R, c.t, m.X, Xc);
    const double z = Xc[2];
    if (!(z > 1.0))
      continue;
    ++n;
    const double iz = 1.0 / z, u = cam.px * Xc[0] * iz + cam.u0, v = cam.py * Xc[1] * iz + cam.v0;
    const double d = m.nu * (u - m.cu) + m.nv * (v - m.cv);
    const double r = m.mean - d;
    if (residual2)
      *residual2 += r * r;
    // d(d)/dX_c, then into the hand frame (R_ch^T), then the twist: [g_h, a x g_h], a = hRo X.
    const double gc[3] = {m.nu * cam.px * iz, m.nv * cam.py * iz, -(m.nu * cam.px * Xc[0] + m.nv * cam.py * Xc[1]) * iz * iz};
    double gh[3];
    for (int k = 0; k < 3; ++k)
      gh[k] = cam.R[k] * gc[0] + cam.R[3 + k] * gc[1] + cam.R[6 + k] * gc[2];
    const double a[3] = {c.hRo[0] * m.X[0] + c.hRo[1] * m.X[1] + c.hRo[2] * m.X[2], c.hRo[3] * m.X[0] + c.hRo[4] * m.X[1] + c.hRo[5] * m.X[2],
                         c.hRo[6] * m.X[0] + c.hRo[7] * m.X[1] + c.hRo[8] * m.X[2]};
    const double J[6] = {gh[0], gh[1], gh[2], a[1] * gh[2] - a[2] * gh[1], a[2] * gh[0] - a[0] * gh[2], a[0] * gh[1] - a[1] * gh[0]};
    const double inv = weight / m.variance;
    for (int k = 0; k < 6; ++k)
      g[k] += inv * r * J[k];
    for (int r0 = 0, k = 0; r0 < 6; ++r0)
      for (int c0 = r0; c0 < 6; ++c0, ++k)
        Hl[k] += inv * J[r0] * J[c0];
  }
  for (int r0 = 0, k = 0; r0 < 6; ++r0)
    for (int c0 = r0; c0 < 6; ++c0, ++k) {
      H[6 * r0 + c0] += Hl[k];
      if (c0 != r0)
        H[6 * c0 + r0] += Hl[k];
    }
  return n;
}

void CorrespondenceLines::collectColours(const LineCamera &cam, const OutlineViews &outlines, const core::Phi &phi, ColourHistograms &colours,
                                         std::size_t maxLines, double skipPx, double maxPx) const
{
  const Composed c = compose(cam, phi);
  double cm[3];
  cameraInModel(cam, phi, cm);
  const Selection sel = select(outlines, outlines.nearest(cm), maxLines);
  const ModelInCamera here = modelIn(c), there = m_occlusion ? modelIn(compose(*m_other, phi)) : here;
  for (std::size_t k = 0; k < sel.count; ++k) {
    const core::ContourPoint &q = outlines.point(sel.at(k));
    Projected pr;
    if (!projectContour(cam, c, q, pr) || (m_occlusion && hiddenHere(cam, q, here, cm, there, pr.pxPerMm)))
      continue; // an occluder's colours are neither the target's nor the background's
    const double u = pr.u, v = pr.v, nu = pr.nu, nv = pr.nv, pxPerMm = pr.pxPerMm;
    const double inLen = std::min(maxPx, q.insideMm * pxPerMm - skipPx), outLen = std::min(maxPx, q.outsideMm * pxPerMm - skipPx);
    for (double t = skipPx; t <= skipPx + inLen; t += 1.0) {
      const long idx = pixelAt(cam, roundToLong(u - t * nu), roundToLong(v - t * nv));
      if (idx < 0)
        break;
      colours.addForeground(cam.image[idx]);
    }
    for (double t = skipPx; t <= skipPx + outLen; t += 1.0) {
      const long idx = pixelAt(cam, roundToLong(u + t * nu), roundToLong(v + t * nv));
      if (idx < 0)
        break;
      colours.addBackground(cam.image[idx]);
    }
  }
}

} // namespace pm::precise
