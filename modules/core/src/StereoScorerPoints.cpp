#include "pm/core/StereoScorer.h"

#include <algorithm>
#include <cmath>

#include "FitnessKernels.h"
#include "pm/core/Error.h"

namespace pm::core {

double StereoScorer::visibleFraction(const Phi &phi, int camera) const
{
  if (!phi.isValid())
    throw Error("visible fraction at an invalid pose " + phi.toString());
  checkCamera(camera);
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

double StereoScorer::reprojectionRms(const Phi &a, const Phi &b) const
{
  if (!a.isValid() || !b.isValid())
    throw Error("reprojection between invalid poses " + a.toString() + " and " + b.toString());
  double sum = 0;
  std::size_t n = 0;
  for (int cam = 0; cam < m_nCams; ++cam) {
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

std::size_t StereoScorer::outerPointsMax() const
{
  std::size_t n = 0;
  for (const View &v : m_views)
    n = std::max(n, v.outEnd - v.outBegin);
  return n;
}

std::size_t StereoScorer::outerHues(const HueFrame &f, const Phi &phi, int camera, float *out, std::size_t capacity) const
{
  check(f, phi);
  checkCamera(camera);
  const Projection p = projectionOf(camera, phi, &f);
  const View &view = viewFor(p);
  std::size_t n = 0;
  for (std::size_t i = view.outBegin; i < view.outEnd && n < capacity; ++i) {
    const std::int32_t h = m_hasDepth ? kernels::sampleScalar<true>(p, m_x[i], m_y[i], m_z[i]) : kernels::sampleScalar<false>(p, m_x[i], m_y[i], 0.f);
    if (h >= 0)
      out[n++] = static_cast<float>(h) / 10.f;
  }
  return n;
}

std::vector<PointScore> StereoScorer::pointScores(const HueFrame &f, const Phi &phi, int camera) const
{
  check(f, phi);
  checkCamera(camera);
  const int partner = partnerOf(camera);
  const bool visibility = partner >= 0;
  const Projection p = projectionOf(camera, phi, &f), o = projectionOf(visibility ? partner : camera, phi, &f);
  const View &view = viewFor(p);
  const kernels::Tolerances tol = tolerances(f);
  std::vector<PointScore> out;
  for (std::size_t k = view.inBegin; k < view.outEnd; ++k) { // in the model's order
    const std::size_t i = m_order[k];
    const bool inner = k < view.inEnd;
    FitnessCounts c;
    const std::int32_t h = m_hasDepth ? kernels::sampleScalar<true>(p, m_x[i], m_y[i], m_z[i]) : kernels::sampleScalar<false>(p, m_x[i], m_y[i], 0.f);
    const std::int32_t ho = !visibility || h < 0 ? -1
                            : m_hasDepth ? kernels::sampleScalar<true>(o, m_x[i], m_y[i], m_z[i])
                                         : kernels::sampleScalar<false>(o, m_x[i], m_y[i], 0.f);
    const bool hidden = visibility && (inner ? kernels::inMayBeHidden(h, m_hue[i], tol) && kernels::inHit(ho, m_hue[i], tol)
                                                            : kernels::outMayBeHidden(h, tol) && kernels::outHit(ho, tol));
    if (inner)
      kernels::classifyIn(h, m_hue[i], tol, c);
    else
      kernels::classifyOut(h, tol, c);
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
    s.cls = hidden ? PointScore::Hidden
            : c.inMatch ? PointScore::InMatch
            : c.inBackground ? PointScore::InBackground
            : c.inOther ? PointScore::InOther
            : c.outBackground ? PointScore::OutBackground
            : c.outOther ? PointScore::OutOther
                         : PointScore::Off;
    out.push_back(s);
  }
  return out;
}

} // namespace pm::core
