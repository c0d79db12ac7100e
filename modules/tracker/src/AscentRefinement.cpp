#include "pm/tracker/AscentRefinement.h"

#include "pm/core/Error.h"

namespace pm::tracker {

void AscentParams::validate() const
{
  if (climb.maxEvaluations != 0) // 0: off
    climb.validate();
  if (!(maxDrop >= 0))
    throw core::Error("tracker: the smooth ascent's fitness drop must be non-negative");
}

AscentRefinement::AscentRefinement(const AscentParams &params, const core::StereoScorer &scorer) : m_p(params), m_scorer(scorer)
{
}

AscentRefinement::Climb AscentRefinement::refine(const core::HueFrame &frame, const ScoredPose &start, const PoseHistory &history) const
{
  // The top of the smooth score near the frame's pose, or near the last frame's pose if that scores higher.
  const TrackResult &last = history.last();
  const core::Phi starts[2] = {start.phi, last.phi};
  const std::size_t n = last.state == TrackState::Tracking && last.phi.isValid() && m_p.climb.maxEvaluations > 1 ? 2 : 1;
  rmga::StereoObjective objective(m_scorer, frame); // the smooth score's gradient
  const rmga::SmoothAscentResult a = rmga::climbSmooth(objective, starts, n, m_p.climb);
  Climb c;
  c.evaluations = a.evaluations;
  c.pose = ScoredPose{a.best, m_scorer.evaluate(frame, a.best)};
  c.kept = c.pose.fitness >= start.fitness - m_p.maxDrop;
  return c;
}

} // namespace pm::tracker
