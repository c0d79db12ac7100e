#pragma once
/*!
  \file AscentRefinement.h
  The refinement chain's second stage, for the frames the precise stage did not end: the top of F's
  plateau. RM-GA's F counts whole pixels, a staircase flat over a degree or two of tilt, and the
  GA's best wanders over the plateau from frame to frame; a climb of the smooth score along its
  gradient (rmga::climbSmooth, core::StereoScorer::evaluateSmoothGradient) from the frame's pose or
  the last frame's, whichever scores higher, reaches its top in a dozen evaluations, on top of the
  frame budget.

  Its acceptance rule: the climb's pose is kept unless F there is under the frame's F by more than
  maxDrop (F's units).

  \code
    pm::tracker::AscentRefinement ascent(params.refinement.ascent, scorer);
    if (ascent.active()) {
      const pm::tracker::AscentRefinement::Climb c = ascent.refine(frame, searched, history);
      if (c.kept)
        pose = c.pose;                 // the climb's pose and F
    }
  \endcode
*/
#include "pm/core/StereoScorer.h"
#include "pm/rmga/SmoothAscent.h"
#include "pm/rmga/StereoObjective.h"
#include "pm/tracker/FrameSteps.h"
#include "pm/tracker/PoseHistory.h"

namespace pm::tracker {

//! The climb's parameters and its acceptance rule (see AscentRefinement.h).
struct AscentParams
{
  rmga::SmoothAscentParams climb; //!< the climb (its maxEvaluations 0: the stage is off)
  double maxDrop = 0.02;          //!< the climb's pose is kept unless F there is this much under the frame's (F's units)

  //! Throws core::Error naming the first parameter out of range.
  void validate() const;
};

//! The chain's smooth ascent (see the file's description). Keeps a reference to the fitness: it must outlive the stage.
class AscentRefinement
{
public:
  //! Copies \e params; \e scorer scores the climb on the frame given to refine() (it must outlive the stage).
  AscentRefinement(const AscentParams &params, const core::StereoScorer &scorer);

  //! What a climb made.
  struct Climb
  {
    ScoredPose pose;     //!< the climb's top and its F
    int evaluations = 0; //!< evaluations of the smooth score and its gradient
    bool kept = false;   //!< the acceptance rule keeps the climb's pose
  };

  bool active() const { return m_p.climb.maxEvaluations > 0; } //!< the stage runs
  //! Climbs on \e frame from \e start and, when the last frame (\e history.last()) was tracked, from its pose.
  Climb refine(const core::HueFrame &frame, const ScoredPose &start, const PoseHistory &history) const;

private:
  AscentParams m_p;
  const core::StereoScorer &m_scorer;
};

} // namespace pm::tracker
