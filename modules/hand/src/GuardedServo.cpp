#include "pm/hand/GuardedServo.h"

#include <algorithm>

#include "pm/core/Error.h"

namespace pm::hand {

GuardedServo::GuardedServo(const servo::ServoParams &sp, const GuardParams &gp, const tracker::PhotoModelTracker &tracker, const robot::ArmModel &arm)
    : m_sp(sp), m_servo(std::make_unique<servo::PbvsServo>(sp)), m_gp(gp), m_lostQuality(tracker.params().lock.lostQuality), m_space(tracker.params().search.space),
      m_filtering(gp.filter == GuardParams::Filter::On || (gp.filter == GuardParams::Filter::Auto && !tracker.hasPreciseStage())),
      m_arm(arm), m_safe(arm.speedLimits(), arm.accelerationLimits()), m_filter(gp.filterParams)
{
  if (!(gp.qualityDrop > 0 && gp.qualityMemoryPerS >= 0))
    throw core::Error("servo: the quality drop must be positive and its memory rate non-negative");
  if (!(gp.maxSigmaMm >= 0 && gp.maxSigmaDeg >= 0))
    throw core::Error("servo: the largest uncertainty allowed must be non-negative (0: no check)");
}

void GuardedServo::setDesired(const vpHomogeneousMatrix &hdMo)
{
  servo::ServoParams sp = m_sp;
  sp.hdMo = hdMo;
  m_servo = std::make_unique<servo::PbvsServo>(sp); // validates it
  m_sp = sp;
}

void GuardedServo::moveDesired(const vpHomogeneousMatrix &hdMo)
{
  m_servo->setDesired(hdMo);
  m_sp.hdMo = hdMo;
}

bool GuardedServo::certainEnough(const precise::PoseUncertainty &u) const
{
  return !u.known || ((m_gp.maxSigmaMm <= 0 || u.maxMm() <= m_gp.maxSigmaMm) && (m_gp.maxSigmaDeg <= 0 || u.maxDeg() <= m_gp.maxSigmaDeg));
}

bool GuardedServo::usable(const tracker::TrackResult &track, bool frozen) const
{
  return track.trusted && !frozen && track.quality >= m_lostQuality && track.quality >= m_qRef - m_gp.qualityDrop &&
         track.phi.isValid() && certainEnough(track.uncertainty) && m_space.contains(track.phi);
}

GuardedCommand GuardedServo::step(const tracker::TrackResult &track, bool frozen, const vpColVector &q, const vpHomogeneousMatrix &fMh,
                                  const vpMatrix &hJe, double dt, const vpHomogeneousMatrix *oracle)
{
  GuardedCommand c;
  m_qRef -= m_gp.qualityMemoryPerS * dt;
  const bool ok = oracle || usable(track, frozen);
  if (ok)
    m_qRef = std::max(m_qRef, track.quality);
  vpColVector twist;
  if (oracle) {
    c.hMoUsed = *oracle;
  } else if (ok && m_filtering) { // filtered in the base frame, where the target moves smoothly
    m_filter.update(fMh * track.hMo, dt);
    c.hMoUsed = fMh.inverse() * m_filter.pose();
    twist = m_filter.twist();
  } else {
    c.hMoUsed = track.hMo;
    if (!ok)
      m_filter.reset();
  }
  vpColVector wanted;
  c.servoing = ok;
  if (ok) {
    try {
      wanted = m_servo->computeJointVelocity(c.hMoUsed, fMh, hJe, q, m_arm.jointMin(), m_arm.jointMax(), dt,
                                            twist.size() == 6 ? &twist : nullptr);
    } catch (const core::Error &) { // a pose vpServo must not see
      c.servoing = false;
    }
  }
  if (!c.servoing)
    wanted = m_servo->stop(m_arm.dof()); // fail-safe: SafeCommand ramps down to it
  c.qdot = m_safe.next(wanted, dt);
  return c;
}

} // namespace pm::hand
