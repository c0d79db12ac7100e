#include "pm/tracker/LockState.h"

#include "pm/core/Error.h"

namespace pm::tracker {

void LockParams::validate() const
{
  if (!(quality > lostQuality) || !(lostQuality > -1) || !(quality < 1))
    throw core::Error("tracker: the qualities must satisfy -1 < lost < lock < 1");
  if (lostFrames < 1)
    throw core::Error("tracker: lost frames must be at least 1");
  if (!(confidence >= 0 && confidence < 1))
    throw core::Error("tracker: the lock confidence must lie in [0, 1)");
  if (dropAfterFrames < 0 || doubtFrames < 0)
    throw core::Error("tracker: the frames that drop a lock never trusted must be non-negative");
  if (!(doubtConfidence >= confidence && doubtConfidence < 1))
    throw core::Error("tracker: the doubtful lock's confidence must lie in [the lock confidence, 1)");
}

RmGaUpdate::Restart LockState::update(double q, bool refused)
{
  const TrackState prev = m_state;
  const bool wrongLong = m_p.dropAfterFrames > 0 && m_wrongFrames >= m_p.dropAfterFrames;
  const bool doubtfulLong = m_p.doubtFrames > 0 && m_doubtFrames >= m_p.doubtFrames;
  if (m_state == TrackState::Tracking && (wrongLong || doubtfulLong)) {
    m_state = TrackState::Searching; // a lock never trusted, plainly wrong or doubtful for long: refused after all
    refused = true;
  } else if (q >= m_p.quality && !refused) {
    m_state = TrackState::Tracking;
    m_lowFrames = 0;
  } else if (prev == TrackState::Tracking) {
    m_lowFrames = q < m_p.lostQuality ? m_lowFrames + 1 : 0;
    m_state = m_lowFrames >= m_p.lostFrames ? TrackState::Lost : TrackState::Tracking;
  } // else searching or lost, until locked
  m_framesTracked = m_state == TrackState::Tracking ? m_framesTracked + 1 : 0;
  if (m_state != TrackState::Tracking || prev != TrackState::Tracking) { // a new lock, or none
    m_trusted = false;
    m_wrongFrames = 0;
    m_doubtFrames = 0;
  }
  if (refused) // the search converged on a plainly wrong pose: everywhere again, that pose avoided for a while
    return RmGaUpdate::Restart::AwayFromBest;
  if (m_state == TrackState::Lost && prev != TrackState::Lost) // again, the best guess kept apart (and near the last trusted pose)
    return RmGaUpdate::Restart::AroundBest;
  return RmGaUpdate::Restart::None;
}

void LockState::onJudged(double confidence, bool trusted)
{
  if (m_state != TrackState::Tracking)
    return;
  m_trusted = m_trusted || trusted;
  m_wrongFrames = !m_trusted && confidence < m_p.confidence ? m_wrongFrames + 1 : 0;
  m_doubtFrames = !m_trusted && confidence < m_p.doubtConfidence ? m_doubtFrames + 1 : 0;
}

void LockState::reset(TrackState state)
{
  m_state = state;
  m_lowFrames = 0;
  m_framesTracked = 0;
  m_trusted = state == TrackState::Tracking; // a pose given (initFromPose) is taken as right
  m_wrongFrames = 0;
  m_doubtFrames = 0;
}

} // namespace pm::tracker
