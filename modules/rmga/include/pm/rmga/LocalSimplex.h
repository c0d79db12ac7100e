#pragma once
/*!
  \file LocalSimplex.h
  A local continuous search of the six pose variables (the Nelder-Mead simplex: reflection,
  expansion, contraction, shrink), started at a pose and bounded in evaluations. RM-GA's own
  refinement steps along the 12-bit genes and compares the staircase fitness F; this one moves
  freely and is meant for a smooth score (StereoFitness::evaluateSmooth), where it climbs to the
  top of the broad, flat maximum that F only knows as a plateau.

  Invalid poses (|eps| > 1) score -infinity and are never returned. Allocates nothing.

      pm::rmga::StereoObjective smooth(fitness, pm::rmga::StereoObjective::Score::Smooth);
      const pm::rmga::LocalSimplexResult r = pm::rmga::refineLocalSimplex(smooth, gaBest, pm::rmga::LocalSimplexParams());
      use(r.best); // r.fitness >= the start's
*/
#include "pm/core/Pose.h"
#include "pm/rmga/RmGa.h"

namespace pm::rmga {

/*!
  Parameters of refineLocalSimplex(): the size of the first simplex, the evaluation budget and
  when to stop early. validate() checks them.
*/
struct LocalSimplexParams
{
  //! The first simplex: the start plus these steps, one variable at a time (mm, mm, mm, eps, eps, eps).
  double step[6] = {1.0, 1.0, 2.0, 0.004, 0.004, 0.004};
  int maxEvaluations = 120; //!< at most this many evaluations, including the first simplex's seven (>= 7)
  //! Stops early when every vertex lies within this fraction of the first steps of the best ([0, 1)).
  double tolerance = 0.02;

  void validate() const; //!< throws pm::core::Error naming the parameter out of range
};

//! What refineLocalSimplex() found.
struct LocalSimplexResult
{
  core::Phi best;            //!< the best pose found (valid; the start if nothing scored higher)
  double fitness = 0;  //!< the score at best (never below the start's)
  double startFitness = 0; //!< the score at the start
  int evaluations = 0; //!< poses tried, the start included (an invalid one counts, unscored); at most maxEvaluations
};

/*!
  Maximises \e f from \e start, one pose per call of FitnessFunction::evaluate (no early
  rejection). Throws pm::core::Error for invalid parameters or an invalid start.
*/
LocalSimplexResult refineLocalSimplex(FitnessFunction &f, const core::Phi &start, const LocalSimplexParams &params);

} // namespace pm::rmga
