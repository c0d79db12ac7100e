#include "pm/hand/HandLoop.h"

#include "pm/core/Error.h"

namespace pm::hand {

HandLoop::HandLoop(const core::StereoRig &rig, const core::PhotoModel &model, const tracker::TrackerParams &tp, const servo::ServoParams &sp,
                   const GuardParams &gp, capture::StereoSource &source, robot::Arm &arm, double fps)
    : m_source(source), m_arm(arm), m_dt(fps > 0 ? 1.0 / fps : 0), m_tracker(rig, model, tp), m_guard(sp, gp, m_tracker, arm.model())
{
  if (!(fps > 0))
    throw core::Error("servo: the frame rate must be positive");
  m_tracker.initialize(); // no initial pose
}

HandLoop::~HandLoop()
{
  try {
    m_arm.stop();
  } catch (...) {
  }
}

bool HandLoop::step(HandFrame &f)
{
  capture::StereoFrame pair;
  bool more = false;
  try {
    more = m_source.next(pair);
  } catch (...) {
    m_arm.stop();
    throw;
  }
  if (!more) {
    m_arm.stop();
    return false;
  }
  f.q = m_arm.q();
  const vpHomogeneousMatrix fMh = m_arm.fMh(f.q);
  if (m_started) // the hand's motion since the last pair (the robot's odometry)
    m_tracker.applyHandMotion(fMh.inverse() * m_fMhLast);
  f.index = pair.index;
  f.timeS = pair.timeS;
  f.frozen = m_started && pair.left == m_last.left && pair.right == m_last.right;
  f.track = m_tracker.track(pair.left, pair.right);
  f.tookDesired = m_keepWhereFound && m_guard.usable(f.track, f.frozen);
  if (f.tookDesired) {
    m_guard.setDesired(f.track.hMo);
    m_keepWhereFound = false;
  }
  // Nothing to keep yet: held (as for a frozen pair).
  f.command = m_guard.step(f.track, f.frozen || m_keepWhereFound, f.q, fMh, m_arm.hJe(f.q), m_dt);
  m_arm.setJointVelocity(f.command.qdot);
  m_arm.advance(m_dt);
  m_last = std::move(pair);
  m_fMhLast = fMh;
  m_started = true;
  return true;
}

} // namespace pm::hand
