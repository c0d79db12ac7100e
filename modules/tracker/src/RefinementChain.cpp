#include "pm/tracker/RefinementChain.h"

namespace pm::tracker {

void RefinementParams::validate() const
{
  precise.validate();
  motion.validate();
  ascent.validate();
  tiltFilter.validate();
  tiltFilterAllAround.validate();
}

RefinementChain::RefinementChain(const RefinementParams &params, const core::CameraRig &rig, const core::PhotoModel &model,
                                 const core::StereoScorer &scorer, const QualityScale &scale)
    : m_precise(params.precise, rig, model, scorer, scale), m_ascent(params.ascent, scorer),
      m_tiltParams(model.isAllAround() ? params.tiltFilterAllAround : params.tiltFilter), m_tilt(m_tiltParams), m_motion(params.motion), m_scorer(scorer)
{
}

RefinedPose RefinementChain::refine(const core::HueFrame &frame, const ScoredPose &searched, const PoseHistory &history, const core::CameraImages &images,
                                    bool locked)
{
  RefinedPose r;
  r.pose = searched;
  // 1. The precise stage: a pose it keeps is final.
  if (locked && m_precise.active()) {
    const PreciseRefinement::Attempt a = m_precise.refine(frame, searched, history, m_motion.predict(history), images);
    r.preciseResult = a.result;
    if (a.kept) {
      r.precise = true;
      r.pose = a.pose;
      m_tilt.reset();
      return r;
    }
  }
  // 2. The smooth ascent.
  if (locked && m_ascent.active()) {
    const AscentRefinement::Climb c = m_ascent.refine(frame, r.pose, history);
    r.ascentEvaluations = c.evaluations;
    if (c.kept)
      r.pose = c.pose;
  }
  // 3. The tilt filter, on frames tracked in a row.
  if (!m_tiltParams.passesThrough()) {
    if (locked && history.last().state == TrackState::Tracking) {
      r.pose.phi = m_tilt.update(r.pose.phi);
      r.pose.fitness = m_scorer.evaluate(frame, r.pose.phi);
    } else {
      m_tilt.reset();
    }
  }
  return r;
}

void RefinementChain::learn(const RefinedPose &refined, const Verdict &verdict, const LockStanding &lock)
{
  if (!lock.tracking || lock.lookingAgain) { // the lock lost, or another pose scores as well: not known right
    m_precise.dropColoursLearntAside();
    return;
  }
  const core::Phi &phi = refined.preciseResult.phi; // where the stage itself put the outline
  if (refined.precise && verdict.trusted)           // the scene's colours along the outline, where the pose is trusted
    m_precise.learnColours(phi);
  else if (refined.precise && !verdict.verified) // a new lock awaiting its verification
    m_precise.learnColoursAside(phi, verdict.confidence);
  if (lock.verified) // accepted: its verification's colours are the scene's
    m_precise.takeColoursLearntAside();
}

} // namespace pm::tracker
