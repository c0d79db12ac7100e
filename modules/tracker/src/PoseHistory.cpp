#include "pm/tracker/PoseHistory.h"

namespace pm::tracker {

void PoseHistory::remember(const TrackResult &r)
{
  const bool bothTracked = m_last.state == TrackState::Tracking && r.state == TrackState::Tracking;
  m_beforeLast = m_last.phi;
  m_haveBeforeLast = bothTracked;
  if (r.precise && r.state == TrackState::Tracking) {
    m_precisePrev = m_preciseLast;
    m_preciseLast = r.phi;
    m_preciseCount = m_preciseCount >= 1 ? 2 : 1;
  } else {
    m_preciseCount = 0;
  }
  m_last = r;
}

core::Phi movedWithHand(const vpHomogeneousMatrix &hNowMhPrev, const core::Phi &p)
{
  const core::Phi q = core::fromHomogeneousMatrix(hNowMhPrev * core::toHomogeneousMatrix(p));
  return q.isValid() ? q : p;
}

void PoseHistory::transform(const vpHomogeneousMatrix &hNowMhPrev)
{
  if (m_haveBeforeLast)
    m_beforeLast = movedWithHand(hNowMhPrev, m_beforeLast);
  if (m_preciseCount > 0) {
    m_precisePrev = movedWithHand(hNowMhPrev, m_precisePrev);
    m_preciseLast = movedWithHand(hNowMhPrev, m_preciseLast);
  }
  m_last.hMo = hNowMhPrev * m_last.hMo;
  m_last.phi = core::fromHomogeneousMatrix(m_last.hMo);
}

void PoseHistory::reset(const TrackResult &start)
{
  m_last = start;
  m_haveBeforeLast = false;
  m_preciseCount = 0;
}

} // namespace pm::tracker
