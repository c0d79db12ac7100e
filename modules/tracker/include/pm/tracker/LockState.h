#pragma once
/*!
  \file LockState.h
  The tracker's state from frame to frame, from the normalised fitness q (QualityScale.h):
  - searching: after initialize(), until q >= quality (a lock);
  - tracking: a lock was reached; it stays while q >= lostQuality;
  - lost: q < lostQuality for lostFrames frames in a row; the search then restarts around its best
    (and near the last trusted pose) until a new lock.
  A lock is refused when its confidence as a first, unverified lock (Judgement::firstLockConfidence)
  is under \e confidence: a plainly wrong pose (a look-alike of similar hue, the toy turned over)
  keeps the search going, scattered away from it, instead of locking and waiting for a challenger.
  A lock made but never trusted whose confidence stays under \e confidence for dropAfterFrames
  judged frames in a row (onJudged()) is dropped the same way: a wrong first lock that got past the
  gate, which the lock's challenger did not overturn, gives way instead of holding the search. So is
  one whose confidence stays under \e doubtConfidence for doubtFrames judged frames in a row: a
  wrong lock a little over the gate (a head turned 20 deg, confidence 0.2 to 0.4) that would
  otherwise hold the arm for good; a right lock is trusted, or near it, long before.

  \code
    pm::tracker::LockState lock(params.lock);
    // refused: the first lock's confidence under params.lock.confidence (Judgement::firstLockConfidence)
    const bool refused = lock.wouldLock(q) && firstLockConfidence < params.lock.confidence;
    pm::tracker::RmGaUpdate update;
    update.restart = lock.update(q, refused); // search again around the best (lost) or away from it (refused)
    search.apply(update);
  \endcode
*/
#include "pm/tracker/RmGaUpdate.h"
#include "pm/tracker/TrackResult.h"

namespace pm::tracker {

//! The state machine's parameters (see LockState.h); validate() checks them.
struct LockParams
{
  double quality = 0.35;     //!< q at or above which the target is tracked ...
  double confidence = 0.2;   //!< ... when its confidence as a first, unverified lock reaches this (0: every pose over quality locks)
  double lostQuality = 0.2;  //!< q below which, for lostFrames frames, it is lost
  int lostFrames = 3;        //!< frames in a row under lostQuality that make a tracked target lost (>= 1)
  int dropAfterFrames = 10;  //!< judged frames in a row of a lock never trusted under \e confidence that drop it (0: never)
  double doubtConfidence = 0.5; //!< a lock never trusted under this confidence ...
  int doubtFrames = 45;      //!< ... for this many judged frames in a row is dropped too (0: never)

  //! Throws core::Error naming the first parameter out of range.
  void validate() const;
};

//! The state machine (see the file's description): the state, the frames under lostQuality, the frames tracked.
class LockState
{
public:
  //! Copies \e params; the state starts searching.
  explicit LockState(const LockParams &params) : m_p(params) {}

  //! \e q would make a new lock (the target is not tracked yet); its confidence then decides (LockParams::confidence).
  bool wouldLock(double q) const { return q >= m_p.quality && m_state != TrackState::Tracking; }
  /*!
    The state after a frame of quality \e q; \e refused: a new lock refused (its confidence). Returns
    what RM-GA must do: search again around its best (the target just lost) or away from it (the lock refused).
  */
  RmGaUpdate::Restart update(double q, bool refused);
  //! The frame's judgement: \e confidence and whether it was \e trusted (counts toward dropping a lock never trusted).
  void onJudged(double confidence, bool trusted);

  TrackState state() const { return m_state; }       //!< the state after the last frame
  int framesTracked() const { return m_framesTracked; } //!< frames in a row in the tracking state, the last one included
  //! A new start in \e state: no frame under lostQuality, none tracked.
  void reset(TrackState state);

private:
  LockParams m_p;
  TrackState m_state = TrackState::Searching;
  int m_lowFrames = 0;
  int m_framesTracked = 0;
  bool m_trusted = false; //!< the lock was trusted on a frame since it was made
  int m_wrongFrames = 0;  //!< judged frames in a row of a lock never trusted under LockParams::confidence
  int m_doubtFrames = 0;  //!< judged frames in a row of a lock never trusted under LockParams::doubtConfidence
};

} // namespace pm::tracker
