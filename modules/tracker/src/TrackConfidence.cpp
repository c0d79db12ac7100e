#include "pm/tracker/TrackConfidence.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"

namespace pm {

std::array<double, ConfidenceCues::kFeatures> ConfidenceCues::features() const
{
  return {quality,
          qualityMin,
          inMatchMin,
          outBackgroundMin,
          tiltDeg / 10.0,
          competitorMargin,
          std::max(0.0, qualityDrop),
          std::log1p(std::max(0.0, jumpMm)),
          std::log1p(std::max(0.0, jumpDeg)),
          std::min(framesTracked, 30) / 30.0,
          verified ? 1.0 : 0.0,
          tracking ? 1.0 : 0.0};
}

const std::array<const char *, ConfidenceCues::kFeatures> &ConfidenceCues::featureNames()
{
  static const std::array<const char *, kFeatures> names{"quality",       "quality_min",   "in_match_min",   "out_background_min",
                                                         "tilt_deg_10",   "competitor_margin", "quality_drop",  "log1p_jump_mm",  "log1p_jump_deg",
                                                         "frames_tracked", "verified",     "tracking"};
  return names;
}

ConfidenceModel::ConfidenceModel()
    // Fitted by `pm-confidence --fit` on its labelled set (28,809 frames, 11 runs; README "Trust");
    // at the threshold under 1 percent of the wrong frames there are trusted.
    : weights{0.9438, 1.1876, 1.0343, 0.0937, -2.3464, 1.9558, -0.5062, -0.8389, -0.5246, 0.4761, 0.8054, 0.1629},
      bias(1.0548), threshold(0.95)
{
}

double ConfidenceModel::confidence(const ConfidenceCues &c) const
{
  const auto x = c.features();
  double s = bias;
  for (std::size_t i = 0; i < x.size(); ++i)
    s += weights[i] * x[i];
  return 1.0 / (1.0 + std::exp(-s));
}

void ConfidenceModel::validate() const
{
  bool finite = std::isfinite(bias);
  for (double w : weights)
    finite = finite && std::isfinite(w);
  if (!finite)
    throw Error("confidence model: every weight and the bias must be finite");
  if (!(threshold > 0 && threshold < 1))
    throw Error("confidence model: the threshold must lie in (0, 1)");
}

} // namespace pm
