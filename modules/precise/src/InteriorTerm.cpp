#include "pm/precise/InteriorTerm.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::precise {

InteriorTerm::InteriorTerm(const core::PhotoModel &model, std::size_t maxPoints)
{
  if (!model.hasColours)
    throw core::Error("the precise stage's interior term needs a model whose points carry the surface's colour (version 5)");
  auto add = [&](const std::vector<core::ModelPoint> &pts) {
    View v;
    v.begin = m_points.size();
    const std::size_t n = pts.size(), count = std::min(n, maxPoints);
    for (std::size_t k = 0; k < count; ++k) {
      const core::ModelPoint &q = pts[k * n / count];
      Point p;
      p.X[0] = q.x, p.X[1] = q.y, p.X[2] = q.z;
      double c[2];
      chroma(q.r, q.g, q.b, c);
      p.c[0] = static_cast<float>(c[0]), p.c[1] = static_cast<float>(c[1]);
      m_points.push_back(p);
    }
    v.end = m_points.size();
    m_maxPoints = std::max(m_maxPoints, v.end - v.begin);
    m_views.push_back(v);
  };
  add(model.inner);
  for (const core::ModelView &mv : model.views)
    add(mv.inner);
}

namespace {

//! The colour of ideal pixel (x, y) (integer), or false off the image.
inline bool pixel(const LineCamera &cam, long x, long y, double rgb[3])
{
  if (x < 0 || y < 0 || x >= cam.w || y >= cam.h)
    return false;
  long i = y * cam.w + x;
  if (cam.nearest && (i = cam.nearest[i]) < 0)
    return false;
  const vpRGBa &c = cam.image[i];
  rgb[0] = c.R, rgb[1] = c.G, rgb[2] = c.B;
  return true;
}

//! The chromaticity at (\e u, \e v), bilinear in the colour; false off the image.
inline bool chromaAt(const LineCamera &cam, double u, double v, double out[2])
{
  const long x = static_cast<long>(std::floor(u)), y = static_cast<long>(std::floor(v));
  const double fu = u - static_cast<double>(x), fv = v - static_cast<double>(y);
  double p00[3], p01[3], p10[3], p11[3];
  if (!pixel(cam, x, y, p00) || !pixel(cam, x + 1, y, p01) || !pixel(cam, x, y + 1, p10) || !pixel(cam, x + 1, y + 1, p11))
    return false;
  double c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = (1 - fv) * ((1 - fu) * p00[k] + fu * p01[k]) + fv * ((1 - fu) * p10[k] + fu * p11[k]);
  InteriorTerm::chroma(c[0], c[1], c[2], out);
  return true;
}

//! The chromaticity at (\e u, \e v) and its gradient by central differences over \e h pixels; false off the image.
inline bool chromaAndGradient(const LineCamera &cam, double u, double v, double h, double c[2], double dc[2][2])
{
  double cu0[2], cu1[2], cv0[2], cv1[2];
  if (!chromaAt(cam, u, v, c) || !chromaAt(cam, u - h, v, cu0) || !chromaAt(cam, u + h, v, cu1) || !chromaAt(cam, u, v - h, cv0) ||
      !chromaAt(cam, u, v + h, cv1))
    return false;
  for (int ch = 0; ch < 2; ++ch) {
    dc[ch][0] = (cu1[ch] - cu0[ch]) / (2 * h);
    dc[ch][1] = (cv1[ch] - cv0[ch]) / (2 * h);
  }
  return true;
}

} // namespace


std::size_t InteriorTerm::measure(const LineCamera &cam, std::size_t view, const core::Phi &phi, double h, InteriorSamples &s) const
{
  return measureVisible(cam, view, phi, h, s, nullptr, nullptr);
}

std::size_t InteriorTerm::measure(const LineCamera &cam, std::size_t view, const core::Phi &phi, double h, InteriorSamples &s,
                                  const LineCamera &other, const StereoOcclusion &occlusion) const
{
  return measureVisible(cam, view, phi, h, s, &other, &occlusion);
}

std::size_t InteriorTerm::measurePart(const LineCamera &cam, std::size_t view, const core::Phi &phi, double h, InteriorSamples &s,
                                      std::size_t part, std::size_t parts) const
{
  return measureVisible(cam, view, phi, h, s, nullptr, nullptr, part, parts);
}

std::size_t InteriorTerm::measureVisible(const LineCamera &cam, std::size_t view, const core::Phi &phi, double h, InteriorSamples &s,
                                         const LineCamera *other, const StereoOcclusion *occlusion, std::size_t part, std::size_t parts) const
{
  s.n = 0;
  if (view >= m_views.size())
    return 0;
  double R[9], t[3];
  core::Rot3 hRo;
  composeCamera(cam, phi, R, t, hRo);
  ModelInCamera here{}, there{};
  double centre[3] = {0, 0, 0};
  if (occlusion) {
    std::copy(R, R + 9, here.R);
    std::copy(t, t + 3, here.t);
    core::Rot3 unused;
    composeCamera(*other, phi, there.R, there.t, unused);
    cameraInModel(cam, phi, centre);
  }
  const std::size_t begin = m_views[view].begin, count = m_views[view].end - begin;
  const std::size_t first = begin + count * part / parts, last = begin + count * (part + 1) / parts;
  for (std::size_t i = first; i < last && s.n < s.samples.size(); ++i) {
    const Point &p = m_points[i];
    double Xc[3];
    for (int r = 0; r < 3; ++r)
      Xc[r] = R[3 * r] * p.X[0] + R[3 * r + 1] * p.X[1] + R[3 * r + 2] * p.X[2] + t[r];
    if (!(Xc[2] > 1.0))
      continue;
    const double u = cam.px * Xc[0] / Xc[2] + cam.u0, v = cam.py * Xc[1] / Xc[2] + cam.v0;
    double c[2], dc[2][2];
    if (!chromaAndGradient(cam, u, v, h, c, dc))
      continue;
    if (occlusion) {
      const double X[3] = {p.X[0], p.X[1], p.X[2]};
      if (occlusion->pointHidden(cam, here, centre, *other, there, X))
        continue;
    }
    InteriorSamples::Sample &m = s.samples[s.n++];
    for (int k = 0; k < 3; ++k)
      m.X[k] = p.X[k];
    m.u = static_cast<float>(u), m.v = static_cast<float>(v);
    for (int ch = 0; ch < 2; ++ch) {
      m.c[ch] = static_cast<float>(c[ch]);
      m.dc[ch][0] = static_cast<float>(dc[ch][0]);
      m.dc[ch][1] = static_cast<float>(dc[ch][1]);
      m.model[ch] = p.c[ch];
    }
  }
  return s.n;
}

std::size_t InteriorTerm::accumulate(const LineCamera &cam, const core::Phi &phi, const InteriorSamples &s, double sigma, double weight,
                                     double g[6], double H[36], double *residual2)
{
  double R[9], t[3];
  core::Rot3 hRo;
  composeCamera(cam, phi, R, t, hRo);
  const double inv2 = weight / (sigma * sigma), huber = 2.0 * sigma;
  double Hl[21] = {0};
  std::size_t used = 0;
  for (std::size_t i = 0; i < s.n; ++i) {
    const InteriorSamples::Sample &m = s.samples[i];
    double Xc[3];
    for (int r = 0; r < 3; ++r)
      Xc[r] = R[3 * r] * m.X[0] + R[3 * r + 1] * m.X[1] + R[3 * r + 2] * m.X[2] + t[r];
    if (!(Xc[2] > 1.0))
      continue;
    ++used;
    const double iz = 1.0 / Xc[2], du = cam.px * Xc[0] * iz + cam.u0 - m.u, dv = cam.py * Xc[1] * iz + cam.v0 - m.v;
    // The image's chromaticity where the point projects now, linearised about where it was measured.
    const double r[2] = {m.c[0] + m.dc[0][0] * du + m.dc[0][1] * dv - m.model[0], m.c[1] + m.dc[1][0] * du + m.dc[1][1] * dv - m.model[1]};
    const double norm = std::sqrt(r[0] * r[0] + r[1] * r[1]);
    const double w = norm <= huber ? 1.0 : huber / norm;
    if (residual2)
      *residual2 += r[0] * r[0] + r[1] * r[1];
    // The pixel's motion per twist: d(u, v)/dX_c, into the hand frame, then [g_h, a x g_h].
    const double a[3] = {hRo[0] * m.X[0] + hRo[1] * m.X[1] + hRo[2] * m.X[2], hRo[3] * m.X[0] + hRo[4] * m.X[1] + hRo[5] * m.X[2],
                         hRo[6] * m.X[0] + hRo[7] * m.X[1] + hRo[8] * m.X[2]};
    double Ju[6], Jv[6];
    for (int axis = 0; axis < 2; ++axis) {
      const double gc[3] = {axis == 0 ? cam.px * iz : 0.0, axis == 1 ? cam.py * iz : 0.0,
                            -(axis == 0 ? cam.px * Xc[0] : cam.py * Xc[1]) * iz * iz};
      double gh[3];
      for (int k = 0; k < 3; ++k)
        gh[k] = cam.R[k] * gc[0] + cam.R[3 + k] * gc[1] + cam.R[6 + k] * gc[2];
      double *J = axis == 0 ? Ju : Jv;
      J[0] = gh[0], J[1] = gh[1], J[2] = gh[2];
      J[3] = a[1] * gh[2] - a[2] * gh[1], J[4] = a[2] * gh[0] - a[0] * gh[2], J[5] = a[0] * gh[1] - a[1] * gh[0];
    }
    for (int ch = 0; ch < 2; ++ch) {
      double J[6];
      for (int k = 0; k < 6; ++k)
        J[k] = m.dc[ch][0] * Ju[k] + m.dc[ch][1] * Jv[k];
      for (int k = 0; k < 6; ++k)
        g[k] -= w * inv2 * r[ch] * J[k];
      for (int r0 = 0, k = 0; r0 < 6; ++r0)
        for (int c0 = r0; c0 < 6; ++c0, ++k)
          Hl[k] += w * inv2 * J[r0] * J[c0];
    }
  }
  for (int r0 = 0, k = 0; r0 < 6; ++r0)
    for (int c0 = r0; c0 < 6; ++c0, ++k) {
      H[6 * r0 + c0] += Hl[k];
      if (c0 != r0)
        H[6 * c0 + r0] += Hl[k];
    }
  return used;
}

} // namespace pm::precise
