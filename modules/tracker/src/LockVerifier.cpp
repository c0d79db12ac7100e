#include "pm/tracker/LockVerifier.h"

#include <algorithm>
#include <string>

#include "pm/core/Error.h"

namespace pm::tracker {

void VerifierParams::validate() const
{
  if (reverifyAfterFrames < 0 || !(reverifyBelowConfidence >= 0 && reverifyBelowConfidence <= 1) || evaluations < 0 ||
      evaluations > 100000000 || !(budgetFraction > 0 && budgetFraction < 1) || !(margin >= 0) || !(switchMargin >= 0) ||
      !(farMm > 0) || !(farDeg > 0) || !(sameObjectMm >= 0))
    throw core::Error("tracker: the re-verification frames must be non-negative and its confidence lie in [0, 1], the "
                      "verification's evaluations lie in [0, 100000000], its budget fraction in (0, 1), its margins and "
                      "same-object distance be non-negative and its far distances positive");
}

namespace {
//! The challenger's RM-GA: the tracker's, with another seed and no motion prediction.
rmga::RmGaParams challengerParams(rmga::RmGaParams p)
{
  p.seed = p.seed * 0x9E3779B97F4A7C15ULL + 0x632BE59BD9B4E019ULL;
  p.predictMotion = false;
  return p;
}
} // namespace

LockVerifier::LockVerifier(const VerifierParams &params, const SearchParams &search, const core::StereoScorer &scorer,
                           const QualityScale &scale)
    : m_p(params), m_coarse(search.coarse), m_rejectMargin(search.rejectMarginQ < 0 ? -1.0 : scale.fitnessSpan(search.rejectMarginQ)),
      m_scorer(scorer), m_scale(scale), m_challenger(search.space, challengerParams(search.ga))
{
}

void LockVerifier::start(const core::Phi &lock, const rmga::RmGa &ga, bool again)
{
  m_lookingAgain = again;
  m_verified = m_p.evaluations == 0;
  m_left = m_p.evaluations;
  if (m_left == 0)
    return;
  // Every individual the lock, then all but it replaced by the restart's blocks; the lock does not
  // breed for the whole verification, so the others search on their own. The challenger searches
  // near the last trusted pose too (the search's anchor; no frame is trusted while it verifies, so
  // the anchor stays the same until it ends).
  if (ga.hasAnchor())
    m_challenger.setAnchor(ga.anchor());
  else
    m_challenger.clearAnchor();
  m_challenger.seedAround(lock, 0.0);
  m_challenger.restart(1, 1000000);
}

bool LockVerifier::onePeak(const core::Phi &challenger, const core::Phi &lock, const Settle &settle) const
{
  if (!settle)
    return false;
  const std::optional<core::Phi> a = settle(challenger);
  if (!a)
    return false;
  const std::optional<core::Phi> b = settle(lock);
  return b && core::translationDistanceMm(*a, *b) <= m_p.farMm / 2 && core::rotationDistanceDeg(*a, *b) <= m_p.farDeg / 2;
}

LockVerifier::Challenge LockVerifier::challenge(const core::HueFrame &frame, const rmga::FrameBudget &budget, const ScoredPose &tracked,
                                                const rmga::RmGa &ga, const Settle &settle)
{
  const core::Phi &pose = tracked.phi;
  rmga::StereoObjective objective(m_scorer, frame, m_coarse ? rmga::StereoObjective::Score::Coarse : rmga::StereoObjective::Score::Fitness,
                                  m_rejectMargin);
  rmga::FrameResult c = m_challenger.evolve(objective, budget);
  if (m_coarse) { // its best on every point, to compare with the tracker's F
    c.fitness = m_scorer.evaluate(frame, c.best);
    ++c.evaluations;
    ++c.candidates;
  }
  const double apartMm = core::translationDistanceMm(c.best, pose);
  const bool far = apartMm > m_p.farMm || core::rotationDistanceDeg(c.best, pose) > m_p.farDeg;
  const double qChallenger = m_scale.quality(c.fitness), q = m_scale.quality(tracked.fitness);
  if (far && qChallenger > q + m_p.switchMargin) { // a clearly better pose elsewhere: verified in turn
    start(c.best, ga);
    return Challenge{c, ScoredPose{c.best, c.fitness}};
  }
  // Another pose of the same object scores as well: ambiguous, look again, unless the second opinion
  // takes both to one peak.
  const bool asGood = far && apartMm < m_p.sameObjectMm && qChallenger > q - m_p.margin;
  Challenge r{c, std::nullopt};
  r.onePeak = asGood && onePeak(c.best, pose, settle);
  if (asGood && !r.onePeak)
    start(pose, ga, true);
  else if ((m_left -= std::min(m_left, c.evaluations)) == 0)
    m_verified = true;
  return r;
}

void LockVerifier::onState(TrackState prev, TrackState state, const core::Phi &pose, const rmga::RmGa &ga)
{
  if (state == TrackState::Tracking && prev != TrackState::Tracking)
    start(pose, ga);
  else if (state != TrackState::Tracking)
    m_verified = false, m_left = 0, m_lookingAgain = false;
}

void LockVerifier::afterJudgement(TrackState state, double confidence, const core::Phi &pose, const rmga::RmGa &ga)
{
  const bool doubtful = state == TrackState::Tracking && m_verified && confidence < m_p.reverifyBelowConfidence;
  m_doubtfulFrames = doubtful ? m_doubtfulFrames + 1 : 0;
  if (m_p.reverifyAfterFrames > 0 && m_doubtfulFrames >= m_p.reverifyAfterFrames) {
    m_doubtfulFrames = 0;
    start(pose, ga);
  }
}

void LockVerifier::transform(const std::function<core::Phi(const core::Phi &)> &moved)
{
  if (m_left > 0) // an idle challenger is started afresh from the next lock
    m_challenger.transform(moved);
}

void LockVerifier::reset(bool verified)
{
  m_left = 0;
  m_verified = verified;
  m_lookingAgain = false;
  m_doubtfulFrames = 0;
}

} // namespace pm::tracker
