#include "pm/tracker/SteadyFramePolicy.h"

#include <algorithm>

#include "pm/core/Error.h"

namespace pm::tracker {

void SteadyParams::validate() const
{
  if (!(budgetFraction > 0 && budgetFraction <= 1) || afterFrames < 1 || !(qualityDrop >= 0 && qualityDrop < 1) || hueMarginPx < 0 ||
      hueMarginPx > 10000)
    throw core::Error("tracker: the steady budget fraction must lie in (0, 1], the steady frames be at least 1, the steady "
                      "quality drop lie in [0, 1) and the steady hue margin in [0, 10000] px");
}

FramePlan SteadyFramePolicy::plan(bool verifying) const
{
  FramePlan p;
  p.verifying = verifying;
  p.steady = m_steadyFrames >= m_p.afterFrames;
  p.windowed = p.steady && !verifying && m_p.hueMarginPx > 0; // the challenger searches the whole images
  return p;
}

std::array<core::PixelRect, core::CameraRig::kMaxCameras> SteadyFramePolicy::windows(const core::StereoScorer &scorer,
                                                                                     const PoseHistory &history) const
{
  std::array<core::PixelRect, core::CameraRig::kMaxCameras> w{};
  const core::Phi &last = history.last().phi;
  core::Phi next = last; // constant velocity from the two last frames (else the last pose again)
  if (const core::Phi *before = history.beforeLast())
    for (std::size_t i = 0; i < 6; ++i)
      next[i] = 2 * last[i] - (*before)[i];
  if (!next.isValid())
    next = last;
  for (int cam = 0; cam < scorer.cameraCount(); ++cam) {
    const std::size_t c = static_cast<std::size_t>(cam);
    w[c] = scorer.footprint(last, cam).united(scorer.footprint(next, cam));
    w[c] = w[c].grown(m_p.hueMarginPx, scorer.camera(cam).w, scorer.camera(cam).h);
  }
  return w;
}

void SteadyFramePolicy::update(TrackState state, double q)
{
  const bool tracking = state == TrackState::Tracking;
  m_recentBestQ = std::max(tracking ? q : 0.0, m_recentBestQ - 0.001);
  m_steadyFrames = tracking && q >= m_recentBestQ - m_p.qualityDrop ? m_steadyFrames + 1 : 0;
}

void SteadyFramePolicy::reset()
{
  m_steadyFrames = 0;
  m_recentBestQ = 0;
}

} // namespace pm::tracker
