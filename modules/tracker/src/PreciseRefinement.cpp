#include "pm/tracker/PreciseRefinement.h"

#include <algorithm>

#include "pm/core/Error.h"

namespace pm::tracker {

void PreciseRefinementParams::validate() const
{
  stage.validate();
  if (!(maxDropQ >= 0) || !(restartMm > 0) || !(restartDeg > 0) || !(maxMoveMm > 0) || !(maxMoveDeg > 0))
    throw core::Error("tracker: the precise stage's fitness drop must be non-negative and its restart and move distances positive");
  if (!(landingWidthDeg >= 0 && landingWidthDeg <= 90))
    throw core::Error("tracker: the landing correction's width must lie in [0, 90] deg (0: off)");
  if (!(lookForHiddenBelow >= 0 && lookForHiddenBelow <= 1))
    throw core::Error("tracker: the precise stage's visible share to look for hidden lines below must lie in [0, 1]");
  if (!(learnAsideMinConfidence >= 0 && learnAsideMinConfidence <= 1))
    throw core::Error("tracker: the confidence a new lock's frame needs to teach the colours aside must lie in [0, 1]");
}

PreciseRefinement::PreciseRefinement(const PreciseRefinementParams &params, const core::CameraRig &rig, const core::PhotoModel &model,
                                     const core::StereoScorer &scorer, const QualityScale &scale)
    : m_p(params), m_scorer(scorer), m_scale(scale), m_range(rig, model.trust)
{
  if (!params.enabled || !model.hasContours())
    return;
  // One rule for what the rig sees of an occluder: the fitness's stereo visibility (on or off, its
  // background tolerance, saturation and largest hidden share) decides the lines' too.
  precise::PreciseParams stage = params.stage;
  const core::FitnessParams &f = scorer.params();
  stage.occlusion.enabled = f.stereoVisibility;
  stage.occlusion.maxHiddenShare = f.maxHiddenShare;
  stage.occlusion.backgroundTolDeg = f.inBgTolDeg;
  stage.occlusion.minSaturation = f.minSaturation;
  m_stage = std::make_unique<precise::PreciseStage>(rig, model, stage);
}

PreciseRefinement::Attempt PreciseRefinement::refine(const core::HueFrame &frame, const ScoredPose &searched, const PoseHistory &history,
                                                     const core::Phi &predicted, const core::CameraImages &images)
{
  m_stage->setImages(images);
  const double minF = searched.fitness - m_scale.fitnessSpan(m_p.maxDropQ);
  auto acceptable = [&](const precise::PreciseResult &p, const core::Phi &start, double &F) {
    if (!p.ok || core::translationDistanceMm(p.phi, start) > m_p.maxMoveMm || core::rotationDistanceDeg(p.phi, start) > m_p.maxMoveDeg)
      return false;
    F = m_scorer.evaluate(frame, p.phi);
    return F >= minF;
  };
  // The lines and interior points hidden by something in front are looked for only where the
  // fitness finds part of the target hidden at the search's pose (lookForHiddenBelow): on a clear
  // view the stage is the one it always was (and pays nothing for it).
  const core::FitnessDetail seen = m_scorer.evaluateDetail(frame, searched.phi);
  double leastVisible = 1;
  for (int k = 0; k < seen.cameras; ++k)
    leastVisible = std::min(leastVisible, seen.counts[static_cast<std::size_t>(k)].visibleShare());
  const bool lookForHidden = leastVisible < m_p.lookForHiddenBelow;
  m_lookedForHidden = lookForHidden;
  const TrackResult &last = history.last();
  const bool haveLast = last.state == TrackState::Tracking && last.precise && last.phi.isValid();
  const bool near = haveLast && core::translationDistanceMm(searched.phi, predicted) <= m_p.restartMm &&
                    core::rotationDistanceDeg(searched.phi, predicted) <= m_p.restartDeg;
  Attempt a;
  precise::PreciseResult best;
  double bestF = 0;
  bool found = false;
  if (haveLast) {
    // The target moves little between frames: the stage starts where the last frames say it is now.
    const precise::PreciseResult fromLast = m_stage->refine(predicted, true, lookForHidden);
    a.result = fromLast;
    found = acceptable(fromLast, predicted, bestF);
    if (found)
      best = fromLast;
  }
  if (!near || !found) {
    const precise::PreciseResult fromSearch = m_stage->refine(searched.phi, false, lookForHidden);
    double F = 0;
    if (acceptable(fromSearch, searched.phi, F) && (!found || fromSearch.residualPx < best.residualPx)) {
      best = fromSearch;
      bestF = F;
      found = true;
    }
    if (!found)
      a.result = fromSearch;
  }
  if (!found)
    return a;
  a.result = best;
  if (m_range.active()) { // the pose reported is the stage's with its range as the pass measured it
    const core::Phi phi = m_range.corrected(best.phi);
    a.pose = ScoredPose{phi, m_scorer.evaluate(frame, phi)};
  } else {
    a.pose = ScoredPose{best.phi, bestF};
  }
  a.kept = true;
  return a;
}

std::optional<core::Phi> PreciseRefinement::settle(const core::Phi &start, const core::CameraImages &images)
{
  if (!m_stage)
    return std::nullopt;
  m_stage->setImages(images);
  const precise::PreciseResult r = m_stage->refine(start, false, false);
  return r.ok ? std::optional<core::Phi>(r.phi) : std::nullopt;
}

} // namespace pm::tracker
