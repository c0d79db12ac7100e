#pragma once
/*!
  \file MotionPrediction.h
  Where the target will be on this frame, from where it was on the last two: the position moves on
  by the last frame's step and the rotation turns on by the last frame's turn (about the hand's axes,
  at the target's origin), both scaled by \e gain. The precise stage (PreciseRefinement.h) starts
  there, so that its few near-start iterations need not cover a turning target's whole turn (the
  lag they leave without it: docs/model-outline.md, "Moving").

  The poses it reads are the tracker's past (PoseHistory.h): the last two frames' poses that the
  precise stage made, on frames tracked in a row (a search's pose is too rough to take a velocity
  from). They follow the hand when it moves (eye-in-hand), so the prediction is the target's own
  motion. A step larger than \e maxStepMm or \e maxStepDeg is a jump or too fast a motion: no
  prediction then. The prediction keeps no state of its own and allocates nothing (quaternions,
  Quaternion.h).

  \code
    const pm::tracker::MotionPrediction motion;        // gain 1
    pm::tracker::PoseHistory history;
    for (;;) {
      const pm::core::Phi start = motion.predict(history); // the last pose moved on, or as it is
      const pm::tracker::TrackResult r = trackFrom(start);
      history.remember(r);                             // at the frame's end
      history.transform(hNowMhPrev);                   // the hand moved
    }
  \endcode
*/
#include "pm/core/Pose.h"
#include "pm/core/Quaternion.h"
#include "pm/tracker/PoseHistory.h"

namespace pm::tracker {

//! MotionPrediction's gain and largest step; validate() checks them.
struct MotionPredictionParams
{
  double gain = 1.0;        //!< share of the last frame's step and turn carried on (0: off, the last pose as it is)
  /*!
    A last step longer than this (mm) or a turn larger than maxStepDeg is not carried on: a jump, or
    a motion too fast to extrapolate (the limits chosen, with their figures: docs/model-outline.md).
  */
  double maxStepMm = 10;
  double maxStepDeg = 3;    //!< see maxStepMm (deg)

  bool enabled() const { return gain > 0; } //!< false: predict() returns the last pose
  void validate() const; //!< throws pm::core::Error unless 0 <= gain <= 1.5 and both steps are positive
};

//! The constant-velocity prediction of the target's pose (see the file's description).
class MotionPrediction
{
public:
  //! Copies and checks \e params (throws pm::core::Error if invalid).
  explicit MotionPrediction(const MotionPredictionParams &params = MotionPredictionParams());

  /*!
    This frame's predicted pose: the last frame's pose (\e history.last()) moved on by the step
    between the last two precise poses when the last frame's pose is the latest of them and the
    step is not a jump; else the last frame's pose as it is.
  */
  core::Phi predict(const PoseHistory &history) const;
  //! True when predict() moves the last pose: two precise poses kept, the step not a jump, the gain not 0.
  bool moving(const PoseHistory &history) const;

private:
  //! The step from \e prev to \e last scaled by the gain (\e dtMm, and the turn \e dR about the hand's axes), when it is no jump.
  bool step(const core::Phi &prev, const core::Phi &last, double dtMm[3], core::Quaternion &dR) const;

  MotionPredictionParams m_params;
};

} // namespace pm::tracker
