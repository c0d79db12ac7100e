#pragma once
/*!
  \file PoseHistory.h
  The tracker's past, in one place: the last frame's result, the pose of the frame before it (when
  both were tracked: the steady windows' constant-velocity guess, SteadyFramePolicy::windows()),
  and the last two poses the precise stage made on frames tracked in a row (the motion the precise
  stage starts from, MotionPrediction). The tracker alone changes it: once at a frame's end
  (remember()), when the hand moves (transform()), on a new start (reset()) and when the lock
  verifier moves the tracker to another pose (forgetMotion()). The steps read it.

  Rules:
   - the pose before the last is kept only when the last frame and the one before were tracked;
   - a precise pose is kept only when the frame was tracked and its pose is the precise stage's;
     any other frame, and a jump to another pose, forget them;
   - every pose follows the hand: after transform() they are the target's poses seen from where the
     hand is now.

  \code
    pm::tracker::PoseHistory history;                 // nothing seen yet: last() is a searching frame
    for (;;) {
      const pm::tracker::TrackResult r = trackFrame(history); // the steps read history.last(), beforeLast(), ...
      history.remember(r);                            // at the frame's end
      history.transform(hNowMhPrev);                  // the hand moved
    }
  \endcode
*/
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/Pose.h"
#include "pm/tracker/TrackResult.h"

namespace pm::tracker {

/*!
  \e p seen from where the hand is now, after the hand moved by \e hNowMhPrev (through the pose's
  matrix); a pose that would leave the valid range (core::Phi::isValid()) stays \e p.
*/
core::Phi movedWithHand(const vpHomogeneousMatrix &hNowMhPrev, const core::Phi &p);

//! The tracker's past frames (see the file's description).
class PoseHistory
{
public:
  //! The last frame's result (a searching frame with no pose before the first).
  const TrackResult &last() const { return m_last; }
  //! The pose of the frame before the last when it and the last were both tracked, else null.
  const core::Phi *beforeLast() const { return m_haveBeforeLast ? &m_beforeLast : nullptr; }
  //! How many precise poses of frames tracked in a row are kept: 0, 1 or 2.
  int preciseCount() const { return m_preciseCount; }
  //! The latest of them; meaningful when preciseCount() >= 1.
  const core::Phi &preciseLast() const { return m_preciseLast; }
  //! The one before it; meaningful when preciseCount() == 2.
  const core::Phi &precisePrev() const { return m_precisePrev; }

  //! At a frame's end: \e r becomes the last frame, the last the one before, and \e r's pose joins the precise ones when the stage made it.
  void remember(const TrackResult &r);
  //! The tracker jumped to another pose (the lock verifier's switch): the precise poses are forgotten.
  void forgetMotion() { m_preciseCount = 0; }
  //! The hand moved by \e hNowMhPrev: every pose follows it.
  void transform(const vpHomogeneousMatrix &hNowMhPrev);
  //! A new start whose last frame is \e start (a searching one, or a pose given); nothing before it.
  void reset(const TrackResult &start);

private:
  TrackResult m_last;
  core::Phi m_beforeLast;
  bool m_haveBeforeLast = false;
  core::Phi m_precisePrev, m_preciseLast;
  int m_preciseCount = 0;
};

} // namespace pm::tracker
