#pragma once
/*!
  \file PoseSearch.h
  The tracker's search: RM-GA's population carried from frame to frame and evolved on each frame
  within the frame's budget (FramePlan), coarse while the target is not tracked (candidates scored
  on a quarter of the model's points, the best then on all), with early rejection of children that
  cannot survive. It owns the population: the other parts' wishes come back to it as an RmGaUpdate,
  applied in one place (apply()).

  \code
    pm::tracker::PoseSearch search(params.search, scorer, scale);
    search.initialize();                                   // a random population
    const pm::rmga::FrameResult r = search.evolve(frame, plan.main, pm::tracker::PoseSearch::Scoring::Exact); // tracked: every point
    pm::tracker::RmGaUpdate u;
    u.anchor = r.best;                                     // trusted
    search.apply(u);
  \endcode
*/
#include <functional>

#include "pm/core/StereoScorer.h"
#include "pm/rmga/RmGa.h"
#include "pm/rmga/StereoObjective.h"
#include "pm/tracker/QualityScale.h"
#include "pm/tracker/RmGaUpdate.h"

namespace pm::tracker {

//! The fitness the tracker uses: the paper's, except that image pixels less saturated than 0.1
//! have no hue (a blank, grey or black frame would otherwise have hue 0, red, and match a red target).
core::FitnessParams trackerFitnessDefaults();

//! RM-GA as the tracker runs it: motion prediction, restarts after 30 generations without gain (chosen: docs/rmga-tracker.md).
rmga::RmGaParams trackerGaDefaults();

/*!
  The search's parameters: where and how RM-GA searches, and the frame budget (800 evaluations;
  chosen: docs/rmga-tracker.md). validate() checks them.
*/
struct SearchParams
{
  rmga::SearchSpace space;                   //!< where phi is searched
  rmga::RmGaParams ga = trackerGaDefaults(); //!< RM-GA (population, operators, options, seed)
  long budgetEvaluations = 800; //!< per-frame budget: evaluations (deterministic; a pose rejected early counts its share) ...
  double budgetMs = 24.0;       //!< ... or wall time, used when budgetEvaluations is 0 (the paper: 24 ms)
  /*!
    Early rejection: RM-GA's children that cannot survive (under the worst parent) are scored on
    the first quarter of the model's points only (core::StereoScorer::evaluate with a threshold),
    when that share's estimate of q lies this much under the threshold's q; otherwise on every
    point. Negative: never (every child scored exactly).
  */
  double rejectMarginQ = 0.15;
  /*!
    Coarse search: while searching or lost, and in the verification's challenger, candidates are
    scored on the first quarter of the model's points (rmga::StereoObjective::Score::Coarse: about
    four times as many poses for the same work); the frame's best is then scored on every point.
  */
  bool coarse = true;
  double initSpread = 0.02;     //!< initFromPose: population spread, fraction of each range
  /*!
    A lock refused as plainly wrong, or dropped as such (LockState; RmGaUpdate::Restart::AwayFromBest),
    is avoided (rmga::RmGa::avoid) for avoidFrames frames: a
    candidate within avoidMm and avoidDeg of it is not scored, so that the scattered population
    cannot fall back into its basin (0 frames: never).
  */
  int avoidFrames = 15;
  double avoidMm = 20;  //!< the avoided pose's radius in position (mm)
  double avoidDeg = 20; //!< ... and in orientation (deg)

  //! The whole frame budget: budgetEvaluations evaluations when positive, else budgetMs milliseconds.
  rmga::FrameBudget budget() const
  {
    return budgetEvaluations > 0 ? rmga::FrameBudget::evals(budgetEvaluations) : rmga::FrameBudget::ms(budgetMs);
  }
  //! Throws core::Error naming the first parameter out of range.
  void validate() const;
};

//! The search on the frame (see the file's description). Keeps a reference to the scorer: it must outlive the search.
class PoseSearch
{
public:
  //! \e scorer scores the poses on the frame given to evolve(); \e scale turns the rejection margin into F's units.
  PoseSearch(const SearchParams &params, const core::StereoScorer &scorer, const QualityScale &scale);

  void initialize();                     //!< a random population, no anchor
  void initFromPose(const core::Phi &p); //!< a population around \e p, which is the anchor
  //! Moves the population (and its anchor and motion history) by \e moved: the hand moved.
  void transform(const std::function<core::Phi(const core::Phi &)> &moved);
  //! How evolve() scores the candidates.
  enum class Scoring
  {
    Coarse, //!< on the first quarter of the model's points (when SearchParams::coarse), the frame's best then on every point
    Exact   //!< on every point
  };
  //! Which frame evolve() searches.
  enum class Generations
  {
    NewFrame,  //!< a new frame (rmga::RmGa::evolve's first call on it)
    SameFrame  //!< more generations on the frame of the last call
  };
  //! RM-GA on \e frame within \e budget, scored as \e scoring says.
  rmga::FrameResult evolve(const core::HueFrame &frame, const rmga::FrameBudget &budget, Scoring scoring,
                           Generations generations = Generations::NewFrame);
  //! The frame's changes, in their order: reseed, inject, restart or scatter, anchor.
  void apply(const RmGaUpdate &update);

  const rmga::RmGa &ga() const { return m_ga; } //!< the population and its anchor

private:
  SearchParams m_params;
  const core::StereoScorer &m_scorer;
  double m_rejectMargin; //!< children that cannot survive by this much (F's units) rejected early (negative: never)
  rmga::RmGa m_ga;
};

} // namespace pm::tracker
