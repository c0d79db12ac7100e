#include "pm/tracker/PoseSearch.h"

#include <algorithm>

#include <string>

#include "pm/core/Error.h"

namespace pm::tracker {

core::FitnessParams trackerFitnessDefaults()
{
  core::FitnessParams f;
  f.minSaturation = 0.1f;
  return f;
}

rmga::RmGaParams trackerGaDefaults()
{
  rmga::RmGaParams g;
  g.predictMotion = true;
  g.restartGenerations = 30;
  return g;
}

void SearchParams::validate() const
{
  space.validate();
  ga.validate();
  if (budgetEvaluations < 0 || !(budgetMs > 0)) // the wall-time budget must make sense even while the evaluations rule
    throw core::Error("tracker: the frame budget must be a positive number of evaluations or milliseconds (got " +
                      std::to_string(budgetEvaluations) + " evaluations, " + std::to_string(budgetMs) + " ms)");
  if (budgetEvaluations > 0 && budgetEvaluations < ga.population)
    throw core::Error("tracker: a frame budget of " + std::to_string(budgetEvaluations) +
                      " evaluations cannot even evaluate the population of " + std::to_string(ga.population));
  if (!(rejectMarginQ <= 1))
    throw core::Error("tracker: the early rejection margin must be at most 1 (negative: off)");
  if (avoidFrames < 0 || !(avoidMm > 0) || !(avoidDeg > 0))
    throw core::Error("tracker: a refused lock's avoided frames must be non-negative and its radii positive");
  if (!(initSpread >= 0 && initSpread <= 1))
    throw core::Error("tracker: the initial spread must lie in [0, 1]");
}

PoseSearch::PoseSearch(const SearchParams &params, const core::StereoScorer &scorer, const QualityScale &scale)
    : m_params(params), m_scorer(scorer), m_rejectMargin(params.rejectMarginQ < 0 ? -1.0 : scale.fitnessSpan(params.rejectMarginQ)),
      m_ga(params.space, params.ga)
{
}

void PoseSearch::initialize()
{
  m_ga.randomize();
  m_ga.clearAnchor();
}

void PoseSearch::initFromPose(const core::Phi &p)
{
  m_ga.seedAround(p, m_params.initSpread);
  m_ga.setAnchor(p);
}

void PoseSearch::transform(const std::function<core::Phi(const core::Phi &)> &moved) { m_ga.transform(moved); }

rmga::FrameResult PoseSearch::evolve(const core::HueFrame &frame, const rmga::FrameBudget &budget, Scoring scoring, Generations generations)
{
  const bool c = scoring == Scoring::Coarse && m_params.coarse;
  // Coarse: F estimated on a quarter of the points; else F, children that cannot survive rejected early.
  rmga::StereoObjective objective(m_scorer, frame, c ? rmga::StereoObjective::Score::Coarse : rmga::StereoObjective::Score::Fitness,
                                  c ? -1.0 : m_rejectMargin);
  rmga::FrameResult r = m_ga.evolve(objective, budget, generations == Generations::SameFrame);
  if (c) { // the estimate of the best, then F itself
    r.fitness = m_scorer.evaluate(frame, r.best);
    ++r.evaluations;
    ++r.candidates;
  }
  return r;
}

void PoseSearch::apply(const RmGaUpdate &u)
{
  if (u.reseed)
    m_ga.seedAround(u.reseed->pose, u.reseed->spread);
  if (u.inject)
    m_ga.inject(u.inject->pose, u.inject->fitness);
  if (u.restart == RmGaUpdate::Restart::AroundBest)
    m_ga.restart(1, m_params.ga.restartGenerations);
  else if (u.restart == RmGaUpdate::Restart::AwayFromBest) {
    if (m_params.avoidFrames > 0) // the refused pose's basin closed for a while
      m_ga.avoid(std::max_element(m_ga.population().begin(), m_ga.population().end(),
                                  [](const rmga::Individual &a, const rmga::Individual &b) { return a.fitness < b.fitness; })->phi,
                 m_params.avoidMm, m_params.avoidDeg, m_params.avoidFrames);
    m_ga.scatter(1, m_params.ga.restartGenerations);
  }
  if (u.anchor)
    m_ga.setAnchor(*u.anchor);
}

} // namespace pm::tracker
