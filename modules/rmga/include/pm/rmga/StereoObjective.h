#pragma once
/*!
  \file StereoObjective.h
  The stereo fitness as what RM-GA and the smooth ascent optimise: F (StereoScorer::evaluate, a
  batch on two cores), or F estimated on a quarter of the model's points (a coarse search), and the
  smooth score with its gradient for climbSmooth (StereoScorer::evaluateSmoothGradient), on one
  frame: made for the frame it scores (a scorer and a HueFrame), or on a StereoFitness's last pair.

  \code
      pm::rmga::StereoObjective f(scorer, frame);                               // F on this frame, for RM-GA
      const pm::rmga::FrameResult r = ga.evolve(f, pm::rmga::FrameBudget::evals(1900));
      const pm::rmga::SmoothAscentResult a = pm::rmga::climbSmooth(f, &r.best, 1, pm::rmga::SmoothAscentParams());
  \endcode
*/
#include "pm/core/StereoFitness.h"
#include "pm/rmga/RmGa.h"
#include "pm/rmga/SmoothAscent.h"

namespace pm::rmga {

/*!
  The stereo fitness on one frame seen as a FitnessFunction (for RmGa) and as a SmoothFunction (for
  climbSmooth); see the file's description. It keeps references to the scorer and the frame it
  was made with: both must outlive it (made for one search, it is dropped with it).
*/
class StereoObjective : public FitnessFunction, public SmoothFunction
{
public:
  /*!
    Fitness: F. Coarse: F estimated from the first share of the model's points (an even sample,
    StereoScorer::kRejectStride; cost about a quarter), for a search that must look at many poses.
  */
  enum class Score { Fitness, Coarse };
  /*!
    \e frame scored by \e scorer, both outliving the objective. \e rejectMargin >= 0 (F's units): a
    pose is rejected early (evaluateOrReject) only when the estimate from its first share of points
    lies this far under the threshold (the estimate's own error); a negative margin: never (every
    pose scored exactly).
  */
  StereoObjective(const core::StereoScorer &scorer, const core::HueFrame &frame, Score score = Score::Fitness, double rejectMargin = -1)
    : m_scorer(scorer), m_frame(frame), m_score(score), m_rejectMargin(rejectMargin)
  {
  }
  //! The same on \e fitness's last pair (its frame as setImages() leaves it; \e fitness must outlive the objective).
  explicit StereoObjective(const core::StereoFitness &fitness, Score score = Score::Fitness, double rejectMargin = -1)
    : StereoObjective(fitness.scorer(), fitness.frame(), score, rejectMargin)
  {
  }
  //! The score chosen at construction for each pose (Coarse: the estimate from the first share of points).
  void evaluate(const core::Phi *poses, std::size_t n, double *fitness) override;
  /*!
    Fitness with a margin: F, a pose rejected early when its estimate lies under \e rejectBelow
    minus the margin. Coarse: every pose estimated (cost about a quarter). A negative margin or
    nothing to reject (\e rejectBelow -1e300): every pose scored exactly (cost 1).
  */
  void evaluateOrReject(const core::Phi *poses, std::size_t n, double rejectBelow, double *fitness, double *cost) override;
  //! StereoScorer::evaluateSmoothGradient, whatever the Score.
  double valueAndGradient(const core::Phi &phi, double grad[6], double *metric) override
  {
    return m_scorer.evaluateSmoothGradient(m_frame, phi, grad, metric);
  }

private:
  const core::StereoScorer &m_scorer;
  const core::HueFrame &m_frame;
  Score m_score;
  double m_rejectMargin;
};

} // namespace pm::rmga
