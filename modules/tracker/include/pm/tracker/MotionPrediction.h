#pragma once
/*!
  \file MotionPrediction.h
  Where the target will be on this frame, from where it was on the last two: the position moves on
  by the last frame's step and the rotation turns on by the last frame's turn (about the hand's axes,
  at the target's origin), both scaled by \e gain. The precise stage (PreciseRefinement.h) starts
  there, so that its few near-start iterations need not cover a turning target's whole turn (the
  lag they leave without it: docs/model-outline.md, "Moving").

  Only the frames whose pose the precise stage made (TrackResult::precise) are remembered, two in a
  row; any other frame forgets them (a search's pose is too rough to take a velocity from). A step
  larger than \e maxStepMm or \e maxStepDeg is a jump or too fast a motion: no prediction then.
  The remembered poses follow the hand when it moves (eye-in-hand), so the prediction is the
  target's own motion.

  \code
    pm::tracker::MotionPrediction motion;              // gain 1
    for (;;) {
      const pm::core::Phi start = motion.predict(last.phi); // last.phi moved on, or as it is
      pm::tracker::TrackResult r = trackFrom(start);
      motion.remember(r);                              // at the frame's end
      motion.transform(hNowMhPrev);                    // the hand moved
    }
  \endcode
*/
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/Pose.h"
#include "pm/tracker/TrackResult.h"

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
  //! Copies and checks \e params (throws pm::core::Error if invalid); nothing remembered yet.
  explicit MotionPrediction(const MotionPredictionParams &params = MotionPredictionParams());

  /*!
    This frame's predicted pose: \e last moved on by the step between the last two frames
    remembered when \e last is the latest of them, else \e last as it is.
  */
  core::Phi predict(const core::Phi &last) const;
  //! At a frame's end: \e r joins the remembered poses when the precise stage made it, else they are forgotten.
  void remember(const TrackResult &r);
  //! The hand moved by \e hNowMhPrev: the remembered poses follow it.
  void transform(const vpHomogeneousMatrix &hNowMhPrev);
  //! Forgets the past (a new start, a jump to another pose).
  void reset() { m_count = 0; }
  //! True when predict() moves the last pose (two poses remembered, the step not a jump).
  bool moving() const { return m_count >= 2 && m_params.enabled() && m_stepOk; }

private:
  void updateStep();

  MotionPredictionParams m_params;
  vpHomogeneousMatrix m_prev, m_last; //!< the poses of the last two frames remembered (hand frame, metres)
  int m_count = 0;                     //!< how many of them are known (0, 1, 2)
  vpTranslationVector m_dt;            //!< the last step, scaled by the gain (metres)
  vpRotationMatrix m_dR;               //!< the last turn about the hand's axes, scaled by the gain
  bool m_stepOk = false;               //!< the step is a motion, not a jump
};

} // namespace pm::tracker
