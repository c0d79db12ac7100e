#include "pm/precise/StereoOcclusion.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "pm/core/Error.h"
#include "pm/core/HuePlane.h"
#include "pm/precise/CorrespondenceLines.h"

namespace pm::precise {

void StereoOcclusionParams::validate() const
{
  if (!(maxHiddenShare >= 0 && maxHiddenShare < 1))
    throw core::Error("precise stage: the hidden lines' largest share must lie in [0, 1)");
  if (!(backgroundTolDeg >= 0 && backgroundTolDeg <= 180))
    throw core::Error("precise stage: the hidden lines' background tolerance must lie in [0, 180] degrees");
  if (!(minSaturation >= 0.f && minSaturation < 1.f))
    throw core::Error("precise stage: the hidden lines' least saturation must lie in [0, 1)");
  for (double d : probesPx)
    if (!(d > 0 && d <= 100))
      throw core::Error("precise stage: the hidden lines' probes must lie in (0, 100] px inside the outline");
  if (!(frontMinMm > 0 && frontMaxMm > frontMinMm && frontMaxMm <= 5000 && frontStepMm >= 0.5 && frontStepMm <= frontMaxMm - frontMinMm))
    throw core::Error("precise stage: the occluders' depths must satisfy 0 < front min < front max <= 5000 mm, a step of 0.5 mm to their span");
  if (!(sameHueDeg >= 0 && sameHueDeg <= 180))
    throw core::Error("precise stage: the occluders' same hue must lie in [0, 180] degrees");
}

StereoOcclusion::StereoOcclusion(const core::PhotoModel &model, const StereoOcclusionParams &params)
    : m_params((params.validate(), params)), m_targetHues(model)
{
  m_backgroundHue = std::lround(model.backgroundHue * 10.0) % 3600;
  m_backgroundTol = std::lround(params.backgroundTolDeg * 10.0);
  m_sameHueTol = std::lround(params.sameHueDeg * 10.0);
}

bool StereoOcclusion::sameHue(long a, long b) const
{
  if (a == core::HuePlane::kNoHue || b == core::HuePlane::kNoHue)
    return a == b;
  const long d = std::labs(a - b);
  return std::min(d, 3600 - d) <= m_sameHueTol;
}

bool StereoOcclusion::seenInFront(long h, const double X[3], const double centre[3], const LineCamera &other,
                                  const ModelInCamera &otherPose) const
{
  double dir[3] = {centre[0] - X[0], centre[1] - X[1], centre[2] - X[2]};
  const double len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  if (!(len > 0))
    return false;
  for (double &d : dir)
    d /= len;
  const double last = std::min(m_params.frontMaxMm, len - m_params.frontMinMm);
  for (double s = m_params.frontMinMm; s <= last; s += m_params.frontStepMm) {
    const double P[3] = {X[0] + s * dir[0], X[1] + s * dir[1], X[2] + s * dir[2]};
    const long ho = hueUnder(other, otherPose, P);
    if (ho >= 0 && sameHue(ho, h))
      return true;
  }
  return false;
}

long StereoOcclusion::hueUnder(const LineCamera &cam, const ModelInCamera &pose, const double X[3]) const
{
  double Xc[3];
  for (int r = 0; r < 3; ++r)
    Xc[r] = pose.R[3 * r] * X[0] + pose.R[3 * r + 1] * X[1] + pose.R[3 * r + 2] * X[2] + pose.t[r];
  if (!(Xc[2] > 1.0))
    return -1;
  const long u = std::lrint(cam.px * Xc[0] / Xc[2] + cam.u0), v = std::lrint(cam.py * Xc[1] / Xc[2] + cam.v0);
  if (u < 0 || v < 0 || u >= cam.w || v >= cam.h)
    return -1;
  long i = v * cam.w + u;
  if (cam.nearest && (i = cam.nearest[i]) < 0)
    return -1;
  return core::hueDeci(cam.image[i], m_params.minSaturation);
}

bool StereoOcclusion::pointHidden(const LineCamera &self, const ModelInCamera &selfPose, const double selfCentre[3], const LineCamera &other,
                                  const ModelInCamera &otherPose, const double X[3]) const
{
  const long h = hueUnder(self, selfPose, X);
  if (h < 0 || m_targetHues.has(static_cast<std::uint32_t>(h)))
    return false; // off the image, or the target's own colour: seen
  if (h != core::HuePlane::kNoHue) {
    const long dh = std::labs(h - m_backgroundHue);
    if (std::min(dh, 3600 - dh) <= m_backgroundTol)
      return false; // the background where the target should be: a wrong pose, not an occluder
  }
  const long ho = hueUnder(other, otherPose, X);
  return ho >= 0 && m_targetHues.has(static_cast<std::uint32_t>(ho)) && seenInFront(h, X, selfCentre, other, otherPose);
}

bool StereoOcclusion::hidden(const LineCamera &self, const ModelInCamera &selfPose, const double selfCentre[3], const LineCamera &other,
                             const ModelInCamera &otherPose, const core::ContourPoint &q, double pxPerMm) const
{
  if (!self.image || !other.image || !(pxPerMm > 0))
    return false;
  const double maxMm = 0.8 * q.insideMm;
  int hidden = 0;
  for (double px : m_params.probesPx) {
    const double d = std::min(px / pxPerMm, maxMm);
    const double X[3] = {q.x - d * q.nx, q.y - d * q.ny, q.z - d * q.nz};
    hidden += pointHidden(self, selfPose, selfCentre, other, otherPose, X) ? 1 : 0;
  }
  return 2 * hidden > static_cast<int>(m_params.probesPx.size());
}

} // namespace pm::precise
