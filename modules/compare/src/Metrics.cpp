#include "pm/compare/Metrics.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Statistics.h"

namespace pm::compare {

FrameScore scoreFrame(const vpHomogeneousMatrix &estimate, const vpHomogeneousMatrix &truth)
{
  FrameScore s;
  s.translationMm = (estimate.getTranslationVector() - truth.getTranslationVector()).frobeniusNorm() * 1e3;
  s.rotationDeg = vpThetaUVector((estimate.getRotationMatrix().t() * truth.getRotationMatrix())).getTheta() * 180 / M_PI;
  if (!std::isfinite(s.translationMm) || !std::isfinite(s.rotationDeg))
    s.translationMm = s.rotationDeg = 1e9;
  return s;
}

namespace {
bool within(const FrameScore &f, double mm, double deg) { return f.translationMm < mm && f.rotationDeg < deg; }

} // namespace

std::optional<int> Summary::worstRecovery() const
{
  std::optional<int> w;
  for (const auto &r : recovery) {
    if (!r)
      return std::nullopt;
    w = std::max(w.value_or(0), *r);
  }
  return w;
}

bool Summary::neverRecovered() const
{
  return std::any_of(recovery.begin(), recovery.end(), [](const auto &r) { return !r.has_value(); });
}

Summary summarize(const std::vector<FrameScore> &frames, const std::vector<int> &lossEnds)
{
  Summary s;
  s.frames = frames.size();
  if (frames.empty())
    return s;
  std::vector<double> ms;
  double n5 = 0, n1 = 0, nv = 0;
  for (const FrameScore &f : frames) {
    ms.push_back(f.ms);
    s.meanMs += f.ms;
    s.meanTranslationMm += f.translationMm;
    s.meanRotationDeg += f.rotationDeg;
    s.maxTranslationMm = std::max(s.maxTranslationMm, f.translationMm);
    s.maxRotationDeg = std::max(s.maxRotationDeg, f.rotationDeg);
    n5 += within(f, kRbotMm, kRbotDeg);
    n1 += within(f, kStrictMm, kStrictDeg);
    nv += f.valid;
  }
  const double n = static_cast<double>(frames.size());
  s.meanMs /= n;
  s.meanTranslationMm /= n;
  s.meanRotationDeg /= n;
  s.success5cm5deg = n5 / n;
  s.success1cm2deg = n1 / n;
  s.validFraction = nv / n;
  s.p99Ms = core::percentile(ms, 0.99);
  for (std::size_t e = 0; e < lossEnds.size(); ++e) {
    const std::size_t from = static_cast<std::size_t>(std::max(0, lossEnds[e]));
    const std::size_t to = e + 1 < lossEnds.size() ? static_cast<std::size_t>(lossEnds[e + 1]) : frames.size();
    std::optional<int> rec;
    std::size_t run = 0;
    for (std::size_t k = from; k < std::min(to, frames.size()) && !rec; ++k) {
      run = within(frames[k], kRbotMm, kRbotDeg) ? run + 1 : 0;
      if (run == static_cast<std::size_t>(kRecoveredRun))
        rec = static_cast<int>(k + 1 - kRecoveredRun - from);
    }
    s.recovery.push_back(rec);
  }
  return s;
}

Summary pool(const std::vector<Summary> &parts, const std::vector<std::vector<FrameScore>> &frames)
{
  std::vector<FrameScore> all;
  for (const auto &f : frames)
    all.insert(all.end(), f.begin(), f.end());
  Summary s = summarize(all);
  for (const Summary &p : parts)
    s.recovery.insert(s.recovery.end(), p.recovery.begin(), p.recovery.end());
  return s;
}

} // namespace pm::compare
