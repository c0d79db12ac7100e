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
}

RmGaUpdate::Restart LockState::update(double q, bool refused)
{
  const TrackState prev = m_state;
  if (q >= m_p.quality && !refused) {
    m_state = TrackState::Tracking;
    m_lowFrames = 0;
  } else if (prev == TrackState::Tracking) {
    m_lowFrames = q < m_p.lostQuality ? m_lowFrames + 1 : 0;
    m_state = m_lowFrames >= m_p.lostFrames ? TrackState::Lost : TrackState::Tracking;
  } // else searching or lost, until locked
  m_framesTracked = m_state == TrackState::Tracking ? m_framesTracked + 1 : 0;
  if (refused) // the search converged on a plainly wrong pose: everywhere again, that pose kept apart
    return RmGaUpdate::Restart::AwayFromBest;
  if (m_state == TrackState::Lost && prev != TrackState::Lost) // again, the best guess kept apart (and near the last trusted pose)
    return RmGaUpdate::Restart::AroundBest;
  return RmGaUpdate::Restart::None;
}

void LockState::reset(TrackState state)
{
  m_state = state;
  m_lowFrames = 0;
  m_framesTracked = 0;
}

} // namespace pm::tracker
