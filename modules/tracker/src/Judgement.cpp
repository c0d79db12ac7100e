#include "pm/tracker/Judgement.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Pose.h"
#include "pm/core/Quaternion.h"

namespace pm::tracker {

JudgementParams JudgementParams::forModel(const core::PhotoModel &model) const
{
  JudgementParams p = *this;
  if (confidence.kind == ConfidenceKind::Auto) { // the coefficients of the model's kind, the threshold as given
    const ConfidenceKind kind = model.isAllAround() ? ConfidenceKind::AllAround : model.hasDepth() ? ConfidenceKind::Stereo : ConfidenceKind::Flat;
    p.confidence = ConfidenceModel::shipped(kind);
    p.confidence.threshold = confidence.threshold;
    if (model.trust.measured) // read through the camera of the model's pass (core::TrustCalibration)
      p.confidence = p.confidence.calibrated(model.trust);
  }
  if (model.trust.measured)
    p.uncertainty.gain = model.trust.sigmaGain;
  return p;
}

void JudgementParams::validate() const
{
  confidence.validate();
  uncertainty.validate();
}

Judgement::Judgement(const JudgementParams &params, double competitorMinDeg, const core::StereoScorer &scorer, const QualityScale &scale,
                     const precise::ModelErrorFloor &modelError)
    : m_p(params), m_competitorMinDeg(competitorMinDeg), m_scorer(scorer), m_scale(scale), m_modelError(modelError)
{
}

std::size_t Judgement::competitors(const core::Phi &phi, core::Phi *out) const
{
  const core::Quaternion q = core::quaternionOf(phi);
  std::size_t n = 0;
  for (std::size_t k = 0; k < 8; ++k) {
    core::Phi p;
    if (k < 7) { // turned about the model's z axis: -135..-45, 45..180 deg
      const double a = (static_cast<double>(k) - 3.0) * M_PI / 4.0 + (k >= 3 ? M_PI / 4.0 : 0.0);
      p = core::withRotation(phi, q * core::Quaternion::aboutZ(a));
    } else { // the tilt mirrored
      p = core::Phi{phi.x, phi.y, phi.z, -phi.e1, -phi.e2, phi.e3};
    }
    if (p.isValid())
      out[n++] = p;
  }
  return n;
}

Evidence Judgement::measure(const core::HueFrame &frame, const RefinedPose &refined) const
{
  Evidence e;
  const double quality = m_scale.quality(refined.pose.fitness);
  ConfidenceCues &c = e.cues;
  const core::FitnessDetail d = m_scorer.evaluateDetail(frame, refined.pose.phi);
  // Over the points not hidden: a right pose behind an occluder is judged as in the open.
  c.quality = m_scale.quality(d.meanVisible());
  auto shares = [](const core::FitnessCounts &n, double &in, double &out) {
    const int nIn = n.inMatch + n.inBackground + n.inOther + n.inOff, nOut = n.outBackground + n.outOther + n.outOff;
    in = nIn > 0 ? static_cast<double>(n.inMatch) / nIn : 0.0;
    out = nOut > 0 ? static_cast<double>(n.outBackground) / nOut : 0.0;
  };
  // The least of the cameras' (over the points not hidden: what is hidden leaves the confidence as it leaves F).
  shares(d.counts[0], c.inMatchMin, c.outBackgroundMin);
  c.qualityMin = m_scale.quality(d.visible[0]);
  e.visibleShare = d.counts[0].visibleShare();
  for (std::size_t k = 1; k < static_cast<std::size_t>(d.cameras); ++k) {
    double in, out;
    shares(d.counts[k], in, out);
    c.inMatchMin = std::min(c.inMatchMin, in);
    c.outBackgroundMin = std::min(c.outBackgroundMin, out);
    c.qualityMin = std::min(c.qualityMin, m_scale.quality(d.visible[k]));
    e.visibleShare = std::min(e.visibleShare, d.counts[k].visibleShare());
  }
  const core::Phi &phi = refined.pose.phi;
  const double r22 = 1.0 - 2.0 * (phi.e1 * phi.e1 + phi.e2 * phi.e2); // the model's z axis . the hand's
  c.tiltDeg = std::acos(std::clamp(r22, -1.0, 1.0)) * 180.0 / M_PI;
  // Competing poses of the same object: turned about the model's z axis, or the tilt mirrored.
  std::array<core::Phi, 8> all, rivals;
  std::array<double, 8> rivalF{};
  std::size_t nRivals = 0;
  const std::size_t n = competitors(phi, all.data());
  for (std::size_t k = 0; k < n; ++k)
    if (core::rotationDistanceDeg(all[k], phi) > m_competitorMinDeg) // a mirrored small tilt is the same pose
      rivals[nRivals++] = all[k];
  m_scorer.evaluate(frame, rivals.data(), nRivals, rivalF.data()); // one batch, on two cores
  double qAlt = -1e9;
  for (std::size_t k = 0; k < nRivals; ++k)
    qAlt = std::max(qAlt, m_scale.quality(rivalF[k]));
  c.competitorMargin = quality - qAlt;
  if (refined.precise) { // how well the precise stage's lines pin the pose (their sigmas, once), and how well they fit
    const precise::PreciseResult &p = refined.preciseResult;
    e.lineSigmas = precise::lineSigmas(p.information);
    const std::array<double, 6> &s = e.lineSigmas;
    c.precise = true;
    const double toReference = std::clamp(phi.z, 50.0, 5000.0) / ConfidenceCues::kPixelCueDistanceMm;
    c.preciseResidualPx = p.residualPx * toReference;
    c.preciseSigmaMm = std::min(1e3, std::max({s[0], s[1], s[2]}));
    c.preciseSigmaDeg = std::min(1e3, std::max({s[3], s[4], s[5]}));
    c.separation = p.separation;
    // The spread of the cameras' residuals (a stereo rig: |left - right|; one camera: 0).
    const auto first = p.residualPxPerCamera.begin(), last = first + static_cast<std::ptrdiff_t>(std::max<std::size_t>(p.cameras, 1));
    c.cameraDisagreementPx = (*std::max_element(first, last) - *std::min_element(first, last)) * toReference;
  }
  return e;
}

double Judgement::firstLockConfidence(const Evidence &e, double recentBestQ, bool verifiedAtOnce) const
{
  ConfidenceCues lock = e.cues;
  lock.qualityDrop = std::max(0.0, recentBestQ - lock.quality);
  lock.framesTracked = 1;
  lock.verified = verifiedAtOnce;
  lock.tracking = true;
  return m_p.confidence.confidence(lock);
}

Verdict Judgement::judge(const RefinedPose &refined, const Evidence &e, const JudgedState &state) const
{
  Verdict v;
  ConfidenceCues &c = v.cues;
  const core::Phi &phi = refined.pose.phi;
  c = e.cues;
  c.qualityDrop = std::max(0.0, state.recentBestQ - m_scale.quality(refined.pose.fitness));
  c.jumpMm = state.last ? core::translationDistanceMm(phi, *state.last) : 0.0;
  c.jumpDeg = state.last ? core::rotationDistanceDeg(phi, *state.last) : 0.0;
  c.framesTracked = state.framesTracked;
  c.verified = state.verified;
  c.tracking = state.state == TrackState::Tracking;
  if (refined.precise)
    v.uncertainty = m_p.uncertainty.uncertainty(e.lineSigmas, refined.preciseResult.residualPx, m_modelError.at(phi));
  v.verified = state.verified;
  v.visibleShare = e.visibleShare;
  v.confidence = m_p.confidence.confidence(c);
  v.trusted = c.tracking && v.verified && v.confidence >= m_p.confidence.threshold;
  v.heldBy = v.trusted        ? nullptr
             : !c.tracking    ? toString(state.state)
             : !v.verified    ? (state.lookingAgain ? "verification_ambiguous" : "verification")
                              : m_p.confidence.weakestCueName(c);
  return v;
}

} // namespace pm::tracker
