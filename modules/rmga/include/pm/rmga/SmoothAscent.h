#pragma once
/*!
  \file SmoothAscent.h
  A local climb of a score that is continuous in the pose (StereoFitness::evaluateSmoothGradient,
  the fitness with each point's score interpolated between pixels), along its gradient. RM-GA's
  fitness F counts whole pixels: it is a staircase, flat over a degree or two of tilt, and the GA
  stops anywhere on the plateau (and stays there from frame to frame). This climb reaches the top
  of the smooth score near a start in a dozen evaluations.

  Each step moves the pose by d = M^-1 g (M the image-motion metric: a step in every direction is
  measured by how far it moves the model's points in the images), scaled to a step length in
  pixels (rms image motion) that grows by \e grow after a step that raised the score and shrinks by
  \e shrink after one that did not; it stops when the step length falls under \e minStepPx or the
  evaluations are spent. Allocates nothing.

  \code
      pm::rmga::StereoObjective f(fitness);
      const pm::core::Phi starts[2] = {gaBest, lastPose};
      const pm::rmga::SmoothAscentResult r = pm::rmga::climbSmooth(f, starts, 2, pm::rmga::SmoothAscentParams());
      use(r.best); // r.score >= the best start's
  \endcode
*/
#include <cstddef>

#include "pm/core/Pose.h"

namespace pm::rmga {

//! What climbSmooth climbs: a score continuous in the pose, with its gradient for a small motion of the pose (applyTwist).
class SmoothFunction
{
public:
  virtual ~SmoothFunction() = default;
  /*!
    The score at \e phi (a valid pose) and its gradient with respect to applyTwist's six components;
    when \e metric is not null, the 6x6 (row-major) mean image-motion metric at \e phi too (see
    StereoFitness::evaluateSmoothGradient).
  */
  virtual double valueAndGradient(const core::Phi &phi, double grad[6], double *metric) = 0;
};

/*!
  Parameters of climbSmooth(): the evaluation budget and the step lengths, as rms image motion
  (px). validate() checks them.
*/
struct SmoothAscentParams
{
  int maxEvaluations = 24;   //!< evaluations of the score and its gradient, the starts' included
  double firstStepPx = 0.5;  //!< rms image motion of the first step (px)
  double maxStepPx = 2.0;    //!< longest step (px)
  double minStepPx = 0.01;   //!< the climb stops when its step is shorter (px)
  double grow = 1.5;         //!< step length factor after a step that raised the score
  double shrink = 0.4;       //!< ... and after one that did not

  void validate() const; //!< throws pm::core::Error naming the parameter out of range
};

//! What climbSmooth() found.
struct SmoothAscentResult
{
  core::Phi best;              //!< the highest-scoring pose found (valid; the best start if no step raised the score)
  double score = 0;      //!< at best, never below the best start's
  double startScore = 0; //!< the best start's
  int evaluations = 0;   //!< evaluations of the score and its gradient, the starts' included
};

/*!
  Climbs \e f from the best of the \e n starts (each evaluated once). Throws pm::core::Error for invalid
  parameters, no start, an invalid start or more starts than evaluations.
*/
SmoothAscentResult climbSmooth(SmoothFunction &f, const core::Phi *starts, std::size_t n, const SmoothAscentParams &params);

} // namespace pm::rmga
