#include "pm/tracker/TrackConfidence.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::tracker {

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
          tracking ? 1.0 : 0.0,
          precise ? 1.0 : 0.0,
          precise ? preciseResidualPx : 0.0,
          precise ? std::log1p(std::max(0.0, preciseSigmaMm)) : 0.0,
          precise ? std::log1p(std::max(0.0, preciseSigmaDeg)) : 0.0,
          precise ? separation : 0.0,
          precise ? std::log1p(std::max(0.0, cameraDisagreementPx)) : 0.0};
}

bool ConfidenceCues::measured(std::size_t i) const { return i < kFirstPreciseFeature || precise; }

const std::array<const char *, ConfidenceCues::kFeatures> &ConfidenceCues::featureNames()
{
  static const std::array<const char *, kFeatures> names{"quality",       "quality_min",   "in_match_min",   "out_background_min",
                                                         "tilt_deg_10",   "competitor_margin", "quality_drop",  "log1p_jump_mm",  "log1p_jump_deg",
                                                         "frames_tracked", "verified",     "tracking",
                                                         "precise",        "precise_residual_px", "log1p_precise_sigma_mm", "log1p_precise_sigma_deg",
                                                         "separation",     "log1p_camera_disagreement_px"};
  return names;
}

const char *toString(ConfidenceKind k)
{
  switch (k) {
  case ConfidenceKind::Auto:
    return "auto";
  case ConfidenceKind::Flat:
    return "flat";
  case ConfidenceKind::Stereo:
    return "stereo";
  case ConfidenceKind::AllAround:
    return "all-around";
  case ConfidenceKind::Custom:
    break;
  }
  return "custom";
}

ConfidenceKind confidenceKindFromString(const std::string &s)
{
  for (ConfidenceKind k : {ConfidenceKind::Auto, ConfidenceKind::Flat, ConfidenceKind::Stereo, ConfidenceKind::AllAround, ConfidenceKind::Custom})
    if (s == toString(k))
      return k;
  throw core::Error("confidence model: unknown kind '" + s + "' (auto, flat, stereo, all-around or custom)");
}

ConfidenceModel::ConfidenceModel() : ConfidenceModel(shipped(ConfidenceKind::Flat)) { kind = ConfidenceKind::Auto; }

std::array<bool, ConfidenceCues::kFeatures> ConfidenceModel::featuresUsed(ConfidenceKind kind)
{
  std::array<bool, ConfidenceCues::kFeatures> used{};
  for (std::size_t i = 0; i < 12; ++i)
    used[i] = true;
  if (kind == ConfidenceKind::Flat)
    return used;
  used[4] = false; // the tilt: a model that knows the relief is not biased by it
  if (kind == ConfidenceKind::AllAround)
    for (std::size_t i = 12; i < ConfidenceCues::kFeatures; ++i)
      used[i] = true;
  return used;
}

namespace {

/*!
  What right poses read in the lab (ConfidenceModel::reference): for the cues of the image, the median
  of seven lab toys' medians (C01, C05, C08, C12, R1, R2, R3) over the right tries on their passes'
  held-out views as steady locks (pm-make-model --target T, its trust_tries.csv; docs/trust.md); for
  the state's, a steady verified lock moving a little (2 mm, 1 deg a frame).
*/
constexpr std::array<double, ConfidenceCues::kFeatures> kLabRightReading{
    0.9930, 0.9910, 0.9925, 1.0000, 0.0, 0.2635, 0.0, 1.0986, 0.6931, 1.0, 1.0, 1.0, // log1p(2 mm), log1p(1 deg)
    1.0,    0.7098, 0.2192, 0.3050, 0.9118, 0.3316};

} // namespace

ConfidenceModel ConfidenceModel::shipped(ConfidenceKind kind)
{
  ConfidenceModel m{Blank{}};
  m.kind = kind;
  m.threshold = 0.95;
  m.reference = kLabRightReading;
  switch (kind) {
  case ConfidenceKind::Flat:
    // Fitted by `pm-confidence --fit` on its labelled set (28,809 frames, 11 runs; docs/trust.md);
    // at the threshold under 1 percent of the wrong frames there are trusted.
    m.weights = {0.9438, 1.1876, 1.0343, 0.0937, -2.3464, 1.9558, -0.5062, -0.8389, -0.5246, 0.4761, 0.8054, 0.1629, 0, 0, 0, 0, 0, 0};
    m.bias = 1.0548;
    return m;
  case ConfidenceKind::Stereo:
    // Fitted by `pm-confidence --stereo --fit` (49,761 frames, 19 runs, 7,339 wrong; docs/trust.md):
    // cross-validated AUROC 0.9763; at the threshold 7 wrong frames trusted, 30054 right ones.
    m.weights = {1.8421, 1.6605, -0.4246, 5.8886, 0, 5.6691, 1.0458, 0.3288, -0.6372, 0.1653, 0.7802, 0.0035, 0, 0, 0, 0, 0, 0};
    m.bias = -8.0152;
    return m;
  case ConfidenceKind::AllAround:
    // Fitted by `pm-confidence --all-around --fit` (49,761 frames, 19 runs, 4,820 wrong; docs/trust.md):
    // cross-validated AUROC 0.9973; at the threshold 4 wrong frames trusted, 40535 right ones.
    m.weights = {0.2637, 0.4884, 0.1780, 4.3443, 0, 1.8374, 0.3350, -0.1896, -0.3810, 0.3061, 0.4307, 0.1071, 1.2699, -2.1948, -1.6159, -0.0675, 3.3966, 0.0416};
    m.bias = -4.9382;
    return m;
  case ConfidenceKind::Auto:
  case ConfidenceKind::Custom:
    break;
  }
  throw core::Error(std::string("confidence model: no shipped coefficients for the kind '") + toString(kind) + "'");
}

double ConfidenceModel::confidence(const ConfidenceCues &c) const
{
  const auto x = c.features();
  double s = bias;
  for (std::size_t i = 0; i < x.size(); ++i)
    s += weights[i] * (x[i] + (c.measured(i) ? shift[i] : 0.0));
  return 1.0 / (1.0 + std::exp(-s));
}

std::size_t ConfidenceModel::weakestCue(const ConfidenceCues &c) const
{
  const auto x = c.features();
  std::size_t weakest = ConfidenceCues::kFeatures;
  double lowest = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!c.measured(i))
      continue;
    const double d = weights[i] * (x[i] + shift[i] - reference[i]);
    if (d < lowest) {
      lowest = d;
      weakest = i;
    }
  }
  return weakest;
}

const char *ConfidenceModel::weakestCueName(const ConfidenceCues &c) const
{
  const std::size_t i = weakestCue(c);
  return i < ConfidenceCues::kFeatures ? ConfidenceCues::featureNames()[i] : "confidence";
}

ConfidenceModel ConfidenceModel::calibrated(const core::TrustCalibration &t) const
{
  ConfidenceModel m = *this;
  const auto &names = ConfidenceCues::featureNames();
  for (const auto &[name, value] : t.cueShifts) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      throw core::Error("trust calibration: \"" + name + "\" is not a cue of the confidence");
    m.shift[static_cast<std::size_t>(it - names.begin())] += value;
  }
  m.bias += t.confidenceOffset;
  return m;
}

void ConfidenceModel::validate() const
{
  bool finite = std::isfinite(bias);
  for (std::size_t i = 0; i < weights.size(); ++i)
    finite = finite && std::isfinite(weights[i]) && std::isfinite(shift[i]) && std::isfinite(reference[i]);
  if (!finite)
    throw core::Error("confidence model: every weight and the bias must be finite");
  if (!(threshold > 0 && threshold < 1))
    throw core::Error("confidence model: the threshold must lie in (0, 1)");
}

} // namespace pm::tracker
