#pragma once
/*!
  \file StereoObjective.h
  The stereo fitness as what RM-GA and the local simplex optimise: F (StereoFitness::evaluate, a
  batch on two cores) or its smooth score (StereoFitness::evaluateSmooth, one pose at a time).

      pm::StereoObjective f(fitness);                                     // F, for RM-GA
      pm::StereoObjective s(fitness, pm::StereoObjective::Score::Smooth); // for refineLocalSimplex
      const pm::FrameResult r = ga.evolve(f, pm::FrameBudget::evals(1900));
      const pm::LocalSimplexResult l = pm::refineLocalSimplex(s, r.best, pm::LocalSimplexParams());
*/
#include "pm/core/StereoFitness.h"
#include "pm/rmga/RmGa.h"

namespace pm {

class StereoObjective : public FitnessFunction
{
public:
  enum class Score { Fitness, Smooth };
  //! \e fitness must outlive the objective.
  explicit StereoObjective(const StereoFitness &fitness, Score score = Score::Fitness) : m_f(fitness), m_score(score) {}
  void evaluate(const Phi *poses, std::size_t n, double *fitness) override;

private:
  const StereoFitness &m_f;
  Score m_score;
};

} // namespace pm
