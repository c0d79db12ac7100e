#include "pm/lab/RunLog.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::lab {

void ErrorStats::add(double mm, double deg)
{
  ++frames;
  sumSquaredMm += mm * mm;
  maxMm = std::max(maxMm, mm);
  sumSquaredDeg += deg * deg;
  maxDeg = std::max(maxDeg, deg);
}

void ErrorStats::add(const ErrorStats &o)
{
  frames += o.frames;
  sumSquaredMm += o.sumSquaredMm;
  maxMm = std::max(maxMm, o.maxMm);
  sumSquaredDeg += o.sumSquaredDeg;
  maxDeg = std::max(maxDeg, o.maxDeg);
}

double ErrorStats::rmsMm() const { return frames ? std::sqrt(sumSquaredMm / static_cast<double>(frames)) : 0.0; }
double ErrorStats::rmsDeg() const { return frames ? std::sqrt(sumSquaredDeg / static_cast<double>(frames)) : 0.0; }

RunLog::RunLog(long expectedFrames, double fps, const robot::ArmModel &arm, std::size_t maxSamples, double convergedMm,
               double convergedDeg)
  : m_expected(expectedFrames), m_mm(convergedMm), m_deg(convergedDeg), m_qmin(arm.jointMin()), m_qmax(arm.jointMax()),
    m_vmax(arm.speedLimits()), m_maxSamples(maxSamples),
    m_conv(std::max(1L, std::lround(fps > 0 ? fps : 1.0)))
{
  if (expectedFrames < 1 || maxSamples < 1 || !(fps > 0))
    throw core::Error("RunLog: the run needs at least one frame, one plot sample and a positive frame rate");
  const long ms = static_cast<long>(maxSamples);
  m_bucket = (expectedFrames + ms - 1) / ms;
  m_samples.reserve(2 * maxSamples);
}

void RunLog::add(const LoopFrame &f)
{
  const double mm = f.translationErrorMm, deg = f.rotationErrorDeg;
  // Convergence: the first frame that starts m_window frames in a row within the bounds.
  if (!converged()) {
    const bool within = mm <= m_mm && deg <= m_deg;
    if (m_conv.add(m_frames, f.t, within))
      m_runRest = m_runMoving = ErrorStats{};
    if (within)
      (f.moving ? m_runMoving : m_runRest).add(mm, deg);
    if (converged()) {
      m_rest = m_runRest;
      m_moving = m_runMoving;
    }
  } else
    (f.moving ? m_moving : m_rest).add(mm, deg);
  (f.moving ? m_allMoving : m_allRest).add(mm, deg);
  const long tenth = std::min(9L, m_frames * 10 / m_expected);
  m_tenths[static_cast<std::size_t>(tenth)].add(mm, deg);

  for (unsigned i = 0; i < 7 && i < f.q.size() && i < f.qdot.size(); ++i) {
    m_violations += (f.q[i] < m_qmin[i] || f.q[i] > m_qmax[i]) ? 1 : 0;
    m_maxSpeedFraction = std::max(m_maxSpeedFraction, std::fabs(f.qdot[i]) / m_vmax[i]);
  }
  m_sumMs += f.track.computeMs;
  m_servoedOnWrong += f.servoing && f.wrongUsed() ? 1 : 0;
  m_servoedOnWrongRaw += f.servoing && f.wrongEstimate() ? 1 : 0;
  m_precise += f.track.precise ? 1 : 0;
  m_partlyHidden += f.track.visibleShare < 0.99 ? 1 : 0;
  m_minVisible = std::min(m_minVisible, f.track.visibleShare);
  if (converged() && f.track.state == tracker::TrackState::Tracking)
    m_estimate.add(f.estimateErrorMm, f.estimateErrorDeg);
  const double distanceMm = 1e3 * f.hMmTrue[2][3];
  m_nearestMm = std::min(m_nearestMm, distanceMm);
  if (f.track.state == tracker::TrackState::Tracking)
    m_byDistance[static_cast<std::size_t>(std::clamp(distanceMm / 10, 0.0, 199.0))].add(f.estimateErrorMm, f.estimateErrorDeg);
  m_held += f.servoing ? 0 : 1;
  if (!f.servoing)
    ++m_heldBy[f.heldBy ? f.heldBy : "oracle"];
  m_servoed += f.servoing ? 1 : 0;

  if (m_inBucket == 0) {
    m_open = RunSample{};
    m_open.t = f.t;
    m_open.truth = core::fromHomogeneousMatrix(f.hMmTrue);
    m_open.used = core::fromHomogeneousMatrix(f.hMmUsed);
    for (unsigned i = 0; i < 7 && i < f.q.size(); ++i)
      m_open.q[i] = f.q[i];
  }
  m_open.translationErrorMm = std::max(m_open.translationErrorMm, mm);
  m_open.rotationErrorDeg = std::max(m_open.rotationErrorDeg, deg);
  if (++m_inBucket == m_bucket) {
    m_samples.push_back(m_open);
    m_inBucket = 0;
    if (m_samples.size() >= 2 * m_maxSamples)
      halveSamples();
  }
  ++m_frames;
}

// A run longer than expected: pairs of samples become one, and buckets twice as long.
ErrorStats RunLog::estimateNearest(double spanMm) const
{
  ErrorStats e;
  if (m_frames == 0)
    return e;
  const auto first = static_cast<std::size_t>(std::clamp(m_nearestMm / 10, 0.0, 199.0));
  for (std::size_t b = first; b < m_byDistance.size() && 10.0 * static_cast<double>(b) < m_nearestMm + spanMm; ++b)
    e.add(m_byDistance[b]);
  return e;
}

void RunLog::halveSamples()
{
  std::size_t j = 0;
  for (std::size_t i = 0; i < m_samples.size(); i += 2, ++j) {
    RunSample s = m_samples[i];
    if (i + 1 < m_samples.size()) {
      s.translationErrorMm = std::max(s.translationErrorMm, m_samples[i + 1].translationErrorMm);
      s.rotationErrorDeg = std::max(s.rotationErrorDeg, m_samples[i + 1].rotationErrorDeg);
    }
    m_samples[j] = s;
  }
  m_samples.resize(j);
  m_bucket *= 2;
}

void RunLog::finish()
{
  if (m_inBucket > 0) {
    m_samples.push_back(m_open);
    m_inBucket = 0;
  }
  // A run within the bounds that reaches the end of the record counts, as it did in the batch rule.
  if (!converged()) {
    m_conv.finish();
    if (converged()) {
      m_rest = m_runRest;
      m_moving = m_runMoving;
    }
  }
}

} // namespace pm::lab
