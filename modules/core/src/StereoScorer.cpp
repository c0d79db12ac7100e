#include "pm/core/StereoScorer.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "FitnessKernels.h"
#include "pm/core/BatchPool.h"
#include "pm/core/Error.h"

namespace pm::core {

const char *StereoScorer::kernelName() const { return m_avx2 ? "avx2" : "scalar"; }

void StereoScorer::useScalarKernel(bool on) { m_avx2 = !on && kernels::cpuHasAvx2(); }

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
  if (!(maxHiddenShare >= 0 && maxHiddenShare < 1))
    throw Error("fitness parameter max hidden share must lie in [0, 1)");
}

double FitnessCounts::visibleShare() const
{
  const int onImage = inMatch + inBackground + inOther + inHidden + outBackground + outOther + outHidden;
  return onImage > 0 ? 1.0 - static_cast<double>(inHidden + outHidden) / onImage : 1.0;
}

double FitnessDetail::meanVisible() const
{
  double sum = visible[0];
  for (int k = 1; k < cameras; ++k)
    sum += visible[static_cast<std::size_t>(k)];
  return sum / cameras;
}

StereoScorer::StereoScorer(const CameraRig &rig, const PhotoModel &model, const FitnessParams &params)
    : m_params(params), m_avx2(kernels::cpuHasAvx2())
{
  rig.validate();
  model.validate("(in memory)");
  params.validate();
  m_nCams = static_cast<int>(rig.size());
  m_camWeight = 1.0 / m_nCams; // exact for one camera and for two (0.5: (F_L + F_R) / 2 to the bit)
  for (int k = 0; k < m_nCams; ++k) // the stereo visibility's partner: the next camera, the last one's the one before it
    m_partner[static_cast<std::size_t>(k)] = !params.stereoVisibility || m_nCams < 2 ? -1 : k + 1 < m_nCams ? k + 1 : k - 1;
  for (std::size_t k = 0; k < rig.size(); ++k) {
    m_cams[k] = rig[k].projection();
    m_distortion[k] = rig[k].distortion;
    m_intrinsics[k] = rig[k].cam;
    if (!rig[k].distortion.isNone())
      m_undistort[k] = std::make_shared<const UndistortMap>(rig[k]);
  }
  m_nIn = model.inner.size();
  m_nOut = model.outer.size();
  // Every view's S_in then S_out, one after the other in the same arrays; view 0 is the model's own.
  auto addView = [&](const std::vector<ModelPoint> &in, const std::vector<ModelPoint> &out) {
    View v;
    v.inBegin = m_x.size();
    v.inEnd = v.outBegin = v.inBegin + in.size();
    v.outEnd = v.outBegin + out.size();
    m_order.resize(v.outEnd);
    v.inSplit = v.inBegin + (in.size() + kRejectStride - 1) / kRejectStride;
    v.outSplit = v.outBegin + (out.size() + kRejectStride - 1) / kRejectStride;
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
          m_hue.push_back(kernels::deci(p.hue) % 3600);
          m_hasDepth = m_hasDepth || p.z != 0.f;
        }
      modelIndex += set->size();
    }
    m_views.push_back(v);
  };
  addView(model.inner, model.outer);
  for (const ModelView &mv : model.views)
    addView(mv.inner, mv.outer);
  m_viewpoints = ViewpointIndex(model);
  // The vector kernels read groups of 8 past a set's end (masked): padding.
  m_x.resize(m_x.size() + 8, 0.f);
  m_y.resize(m_y.size() + 8, 0.f);
  m_z.resize(m_z.size() + 8, 0.f);
  m_hue.resize(m_hue.size() + 8, 0);
  m_modelBgHue = kernels::deci(model.backgroundHue) % 3600;
  m_tolIn = kernels::deci(params.inTolDeg);
  m_tolInBg = kernels::deci(params.inBgTolDeg);
  m_tolOutBg = kernels::deci(params.outBgTolDeg);
  m_targetHues = TargetHues(model);
}

HueFrame StereoScorer::newFrame() const { return HueFrame(m_modelBgHue); }

kernels::Tolerances StereoScorer::tolerances(const HueFrame &f) const
{
  return kernels::Tolerances{f.backgroundHueDeci(), m_tolIn, m_tolInBg, m_tolOutBg, m_targetHues.data()};
}

void StereoScorer::check(const HueFrame &f, const Phi &phi) const
{
  if (!phi.isValid())
    throw Error("fitness of an invalid pose phi = " + phi.toString() + ": |eps| must be <= 1 and every value finite");
  if (!f.hasImages())
    throw Error("fitness: no stereo pair was given (call setImages first)");
}

Projection StereoScorer::projectionOf(int cam, const Phi &phi, const HueFrame *f) const
{
  const PinholeCamera::Projection &c = m_cams[cam];
  const Rot3 R = rotationOf(phi);
  const double t[3] = {phi.x, phi.y, phi.z};
  Projection p;
  // cMo = cMh * hMo, in mm.
  for (int r = 0; r < 3; ++r) {
    for (int col = 0; col < 3; ++col)
      p.r[3 * r + col] = static_cast<float>(c.R[3 * r] * R[col] + c.R[3 * r + 1] * R[3 + col] + c.R[3 * r + 2] * R[6 + col]);
    p.t[r] = static_cast<float>(c.R[3 * r] * t[0] + c.R[3 * r + 1] * t[1] + c.R[3 * r + 2] * t[2] + c.t[r]);
  }
  p.px = static_cast<float>(c.px);
  p.py = static_cast<float>(c.py);
  p.u0 = static_cast<float>(c.u0);
  p.v0 = static_cast<float>(c.v0);
  p.w = c.w;
  p.h = c.h;
  p.hue = f ? f->plane(cam).data() : nullptr;
  return p;
}

void StereoScorer::countView(const HueFrame &f, const Projection &p, const Projection *other, const View &v, int stage, FitnessCounts &counts) const
{
  const std::size_t inB = stage == 2 ? v.inSplit : v.inBegin, inE = stage == 1 ? v.inSplit : v.inEnd;
  const std::size_t outB = stage == 2 ? v.outSplit : v.outBegin, outE = stage == 1 ? v.outSplit : v.outEnd;
  const kernels::Tolerances tol = tolerances(f);
  const kernels::ModelSoA m{m_x.data(), m_y.data(), m_z.data(), m_hue.data()};
#ifdef PM_HAVE_X86
  if (m_avx2) {
    if (m_hasDepth)
      kernels::countAvx2<true>(p, other, tol, m, inB, inE, outB, outE, counts);
    else
      kernels::countAvx2<false>(p, other, tol, m, inB, inE, outB, outE, counts);
    return;
  }
#endif
  if (m_hasDepth)
    kernels::countScalar<true>(p, other, tol, m, inB, inE, outB, outE, counts);
  else
    kernels::countScalar<false>(p, other, tol, m, inB, inE, outB, outE, counts);
}

const StereoScorer::View &StereoScorer::viewFor(const Projection &p) const
{
  if (m_views.size() == 1)
    return m_views[0];
  // The camera's centre in the model frame, -R^T t of cMm, as a direction from the origin: the view
  // whose camera looked from the nearest direction.
  double c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = -(static_cast<double>(p.r[k]) * p.t[0] + static_cast<double>(p.r[3 + k]) * p.t[1] + static_cast<double>(p.r[6 + k]) * p.t[2]);
  return m_views[m_viewpoints.nearest(c)];
}

void StereoScorer::checkCamera(int camera) const
{
  if (camera < 0 || camera >= m_nCams)
    throw Error("fitness: no camera " + std::to_string(camera) + " on a rig of " + std::to_string(m_nCams));
}

FitnessCounts StereoScorer::countCamera(const HueFrame &f, int cam, const Phi &phi) const
{
  const Projection p = projectionOf(cam, phi, &f);
  const int partner = partnerOf(cam);
  const Projection o = partner >= 0 ? projectionOf(partner, phi, &f) : p;
  FitnessCounts counts;
  countView(f, p, partner >= 0 ? &o : nullptr, viewFor(p), 0, counts);
  return counts;
}

double StereoScorer::stereoScore(const HueFrame &f, const Phi &phi) const
{
  // The mean of the cameras' scores, summed in camera order (a stereo rig: (F_L + F_R) / 2 to the bit).
  double sum = score(countCamera(f, 0, phi));
  for (int cam = 1; cam < m_nCams; ++cam)
    sum += score(countCamera(f, cam, phi));
  return sum * m_camWeight;
}

double StereoScorer::stereoScoreOrReject(const HueFrame &f, const Phi &phi, double rejectBelow, double &cost) const
{
  std::array<Projection, CameraRig::kMaxCameras> p;
  std::array<const View *, CameraRig::kMaxCameras> v{};
  for (int cam = 0; cam < m_nCams; ++cam) {
    p[static_cast<std::size_t>(cam)] = projectionOf(cam, phi, &f);
    v[static_cast<std::size_t>(cam)] = &viewFor(p[static_cast<std::size_t>(cam)]);
  }
  auto partner = [&](int cam) { return partnerOf(cam) >= 0 ? &p[static_cast<std::size_t>(partnerOf(cam))] : nullptr; };
  std::array<FitnessCounts, CameraRig::kMaxCameras> c;
  double estimate = 0, done = 0, all = 0;
  for (int cam = 0; cam < m_nCams; ++cam) {
    const std::size_t k = static_cast<std::size_t>(cam);
    countView(f, p[k], partner(cam), *v[k], 1, c[k]);
    estimate += m_camWeight * score(c[k]); // the share's own mean score: an estimate of F_cam
    done += static_cast<double>((v[k]->inSplit - v[k]->inBegin) + (v[k]->outSplit - v[k]->outBegin));
    all += static_cast<double>((v[k]->inEnd - v[k]->inBegin) + (v[k]->outEnd - v[k]->outBegin));
  }
  if (estimate < rejectBelow) {
    cost = all > 0 ? done / all : 1.0;
    return estimate;
  }
  for (int cam = 0; cam < m_nCams; ++cam)
    countView(f, p[static_cast<std::size_t>(cam)], partner(cam), *v[static_cast<std::size_t>(cam)], 2, c[static_cast<std::size_t>(cam)]);
  cost = 1.0;
  double sum = score(c[0]);
  for (int cam = 1; cam < m_nCams; ++cam)
    sum += score(c[static_cast<std::size_t>(cam)]);
  return sum * m_camWeight;
}

void StereoScorer::cappedHidden(const FitnessCounts &c, int &inHidden, int &outHidden) const
{
  const int nIn = c.inMatch + c.inBackground + c.inOther + c.inOff + c.inHidden;
  const int nOut = c.outBackground + c.outOther + c.outOff + c.outHidden;
  inHidden = std::min(c.inHidden, static_cast<int>(m_params.maxHiddenShare * nIn));
  outHidden = std::min(c.outHidden, static_cast<int>(m_params.maxHiddenShare * nOut));
}

double StereoScorer::score(const FitnessCounts &c) const { return scoreOf(c, false); }

double StereoScorer::visibleScore(const FitnessCounts &c) const { return scoreOf(c, true); }

double StereoScorer::scoreOf(const FitnessCounts &c, bool visibleOnly) const
{
  const FitnessParams &q = m_params;
  // A hidden point scores 0, neither for the pose nor against it. F keeps it in the count, so that
  // a pose never gains by hiding its misses; the visible score leaves it out of the count too.
  // Those beyond the cap count as the misses they are.
  int inHidden = 0, outHidden = 0;
  cappedHidden(c, inHidden, outHidden);
  const double sum = q.inMatch * c.inMatch + q.inBackground * c.inBackground + q.inOther * (c.inOther + c.inHidden - inHidden) +
                     q.offImage * (c.inOff + c.outOff) + q.outBackground * c.outBackground + q.outOther * (c.outOther + c.outHidden - outHidden);
  const int nIn = c.inMatch + c.inBackground + c.inOther + c.inOff + c.inHidden - (visibleOnly ? inHidden : 0);
  const int nOut = c.outBackground + c.outOther + c.outOff + c.outHidden - (visibleOnly ? outHidden : 0);
  return normalised(sum, static_cast<std::size_t>(nIn), static_cast<std::size_t>(nOut));
}

double StereoScorer::normalised(double sum, std::size_t nIn, std::size_t nOut) const
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

double StereoScorer::evaluate(const HueFrame &f, const Phi &phi) const
{
  check(f, phi);
  return stereoScore(f, phi);
}

void StereoScorer::evaluate(const HueFrame &f, const Phi *phis, std::size_t n, double *out) const
{
  for (std::size_t i = 0; i < n; ++i) // first, so that nothing throws inside the parallel loop
    check(f, phis[i]);
  // On two cores (BatchPool: the caller never waits for the helper to start). Each result depends
  // on its pose only, so they are the same whoever computes them.
  BatchPool::shared().run(n, [&](std::size_t i) { out[i] = stereoScore(f, phis[i]); });
}

void StereoScorer::evaluate(const HueFrame &f, const Phi *phis, std::size_t n, double *out, double rejectBelow, double *cost) const
{
  for (std::size_t i = 0; i < n; ++i)
    check(f, phis[i]);
  BatchPool::shared().run(n, [&](std::size_t i) { out[i] = stereoScoreOrReject(f, phis[i], rejectBelow, cost[i]); });
}

FitnessDetail StereoScorer::evaluateDetail(const HueFrame &f, const Phi &phi) const
{
  check(f, phi);
  FitnessDetail d;
  d.cameras = m_nCams;
  for (std::size_t k = 0; k < static_cast<std::size_t>(m_nCams); ++k) {
    d.counts[k] = countCamera(f, static_cast<int>(k), phi);
    d.score[k] = score(d.counts[k]);
    d.visible[k] = visibleScore(d.counts[k]);
  }
  double sum = d.score[0];
  for (std::size_t k = 1; k < static_cast<std::size_t>(m_nCams); ++k)
    sum += d.score[k];
  d.fitness = sum * m_camWeight;
  return d;
}

} // namespace pm::core
