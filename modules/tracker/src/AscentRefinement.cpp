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

bool AscentRefinement::refine(const core::HueFrame &frame, TrackResult &r, const TrackResult &last)
{
  // The top of the smooth score near the frame's pose, or near the last frame's pose if that scores higher.
  const core::Phi starts[2] = {r.phi, last.phi};
  const std::size_t n = last.state == TrackState::Tracking && last.phi.isValid() && m_p.climb.maxEvaluations > 1 ? 2 : 1;
  rmga::StereoObjective objective(m_scorer, frame); // the smooth score's gradient
  const rmga::SmoothAscentResult a = rmga::climbSmooth(objective, starts, n, m_p.climb);
  r.ascentEvaluations = a.evaluations;
  const double F = m_scorer.evaluate(frame, a.best);
  if (!(F >= r.fitness - m_p.maxDrop))
    return false;
  r.phi = a.best;
  r.fitness = F;
  return true;
}

} // namespace pm::tracker
