#include "pm/tracker/PhotoModelTracker.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "pm/core/Error.h"

namespace pm {

const char *toString(TrackState s)
{
  switch (s) {
  case TrackState::Searching: return "searching";
  case TrackState::Tracking: return "tracking";
  case TrackState::Lost: return "lost";
  }
  return "?";
}

void TrackerParams::validate() const
{
  space.validate();
  ga.validate();
  fitness.validate();
  if (budgetEvaluations < 0 || (budgetEvaluations == 0 && !(budgetMs > 0)))
    throw Error("tracker: the frame budget must be a positive number of evaluations or milliseconds (got " +
                std::to_string(budgetEvaluations) + " evaluations, " + std::to_string(budgetMs) + " ms)");
  if (budgetEvaluations > 0 && budgetEvaluations < ga.population)
    throw Error("tracker: a frame budget of " + std::to_string(budgetEvaluations) +
                " evaluations cannot even evaluate the population of " + std::to_string(ga.population));
  if (!(lockQuality > lostQuality) || !(lostQuality > -1) || !(lockQuality < 1))
    throw Error("tracker: the qualities must satisfy -1 < lost < lock < 1");
  if (lostFrames < 1)
    throw Error("tracker: lost frames must be at least 1");
  if (smoothRefineEvaluations < 0 || smoothRefineEvaluations > 1000000 || !(smoothRefineMaxDrop >= 0))
    throw Error("tracker: the smooth refinement's evaluations must lie in [0, 1000000] and its fitness drop be non-negative");
  if (smoothRefineEvaluations > 0) {
    LocalSimplexParams sp = smoothRefine;
    sp.maxEvaluations = smoothRefineEvaluations;
    sp.validate();
  }
  if (!(initSpread >= 0 && initSpread <= 1))
    throw Error("tracker: the initial spread must lie in [0, 1]");
  if (!(steadyBudgetFraction > 0 && steadyBudgetFraction <= 1) || steadyAfterFrames < 1 || !(steadyQualityDrop >= 0 && steadyQualityDrop < 1))
    throw Error("tracker: the steady budget fraction must lie in (0, 1], the steady frames be at least 1 and the steady "
                "quality drop lie in [0, 1)");
}

FrameBudget TrackerParams::steadyBudget() const
{
  if (budgetEvaluations > 0)
    return FrameBudget::evals(std::max<long>(ga.population, std::lround(steadyBudgetFraction * static_cast<double>(budgetEvaluations))));
  return FrameBudget::ms(steadyBudgetFraction * budgetMs);
}

PhotoModelTracker::PhotoModelTracker(const StereoRig &rig, const PhotoModel &model, const TrackerParams &params)
    : m_params((params.validate(), params)), m_fitness(rig, model, params.fitness), m_ga(params.space, params.ga)
{
  const FitnessParams &f = params.fitness;
  const double n = static_cast<double>(model.size());
  const double nIn = static_cast<double>(model.inner.size()), nOut = static_cast<double>(model.outer.size());
  m_fBackground = (f.inBackground * nIn + f.outBackground * nOut) / n;
  m_fMax = (f.inMatch * nIn + f.outBackground * nOut) / n;
  if (!(m_fMax > m_fBackground))
    throw Error("tracker: with these scores a perfect match does not score above the background");
  // The model must fit the rig: at the centre of the search space most of it is in both images.
  Phi centre;
  for (std::size_t i = 0; i < 6; ++i)
    centre[i] = 0.5 * (params.space.lo[i] + params.space.hi[i]);
  for (int cam = 0; cam < 2; ++cam) {
    const double visible = m_fitness.visibleFraction(centre, cam);
    if (visible < 0.5)
      throw Error("the photo-model does not fit the rig: at the centre of the search space " + centre.toString() +
                  " only " + std::to_string(static_cast<int>(100 * visible)) + " % of its points fall in the " +
                  (cam ? "right" : "left") + " image (a model too large for the cameras, or made at another scale?)");
  }
  initialize();
}

void PhotoModelTracker::resetCounters()
{
  m_lowFrames = 0;
  m_steadyFrames = 0;
  m_recentBestQ = 0;
}

void PhotoModelTracker::initialize()
{
  m_ga.randomize();
  m_last = TrackResult();
  m_last.state = TrackState::Searching;
  resetCounters();
}

void PhotoModelTracker::initFromPose(const vpHomogeneousMatrix &hMo)
{
  const Phi p = fromHomogeneousMatrix(hMo);
  m_ga.seedAround(p, m_params.initSpread);
  m_last = TrackResult();
  m_last.hMo = hMo;
  m_last.phi = p;
  m_last.state = TrackState::Tracking;
  resetCounters();
}

void PhotoModelTracker::applyHandMotion(const vpHomogeneousMatrix &hNowMhPrev)
{
  if (!hNowMhPrev.isAnHomogeneousMatrix())
    throw Error("tracker: the hand motion is not a rigid transformation");
  m_ga.transform([&](const Phi &p) {
    const Phi q = fromHomogeneousMatrix(hNowMhPrev * toHomogeneousMatrix(p));
    return q.isValid() ? q : p;
  });
  m_last.hMo = hNowMhPrev * m_last.hMo;
  m_last.phi = fromHomogeneousMatrix(m_last.hMo);
}

TrackResult PhotoModelTracker::track(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right)
{
  const auto t0 = std::chrono::steady_clock::now();
  m_fitness.setImages(left, right);
  StereoObjective objective(m_fitness);
  const bool steady = m_steadyFrames >= m_params.steadyAfterFrames;
  FrameBudget budget = steady ? m_params.steadyBudget() : m_params.budget();
  if (budget.milliseconds > 0) // the hue planes are part of the frame's time
    budget.milliseconds = std::max(0.05, budget.milliseconds - std::chrono::duration<double, std::milli>(
                                                                    std::chrono::steady_clock::now() - t0).count());
  const FrameResult fr = m_ga.evolve(objective, budget);
  TrackResult r;
  r.phi = fr.best;
  r.fitness = fr.fitness;
  if (m_params.smoothRefineEvaluations > 0 && quality(fr.fitness) >= m_params.lockQuality) {
    // The top of F's plateau: a continuous search of the smooth score from RM-GA's best.
    StereoObjective smooth(m_fitness, StereoObjective::Score::Smooth);
    LocalSimplexParams sp = m_params.smoothRefine;
    sp.maxEvaluations = m_params.smoothRefineEvaluations;
    const LocalSimplexResult lr = refineLocalSimplex(smooth, fr.best, sp);
    r.smoothEvaluations = lr.evaluations;
    const double f = m_fitness.evaluate(lr.best);
    if (f >= fr.fitness - m_params.smoothRefineMaxDrop) {
      r.phi = lr.best;
      r.fitness = f;
    }
  }
  r.hMo = toHomogeneousMatrix(r.phi);
  r.quality = quality(r.fitness);
  r.evaluations = fr.evaluations;
  r.generations = fr.generations;
  // The state machine.
  const TrackState prev = m_last.state;
  if (r.quality >= m_params.lockQuality) {
    r.state = TrackState::Tracking;
    m_lowFrames = 0;
  } else if (prev == TrackState::Tracking) {
    m_lowFrames = r.quality < m_params.lostQuality ? m_lowFrames + 1 : 0;
    r.state = m_lowFrames >= m_params.lostFrames ? TrackState::Lost : TrackState::Tracking;
  } else {
    r.state = prev; // searching or lost, until locked
  }
  if (r.state == TrackState::Lost && prev != TrackState::Lost)
    m_ga.restart(1, m_params.ga.restartGenerations); // search again, keeping the best guess apart
  // Steadiness for the next frame's budget.
  r.steady = steady;
  // The recent best is remembered through a loss, so that a relock on a wrong pose (lower q) is
  // not taken for steady and keeps the whole budget to find the true one.
  m_recentBestQ = std::max(r.state == TrackState::Tracking ? r.quality : 0.0, m_recentBestQ - 0.001);
  m_steadyFrames = r.state == TrackState::Tracking && r.quality >= m_recentBestQ - m_params.steadyQualityDrop ? m_steadyFrames + 1 : 0;
  r.computeMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  m_last = r;
  return r;
}

} // namespace pm
