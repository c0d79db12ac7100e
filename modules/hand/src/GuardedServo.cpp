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

const char *GuardedServo::uncertainAxis(const precise::PoseUncertainty &u) const
{
  static const char *const kAxes[6] = {"sigma_x_mm", "sigma_y_mm", "sigma_z_mm", "sigma_rx_deg", "sigma_ry_deg", "sigma_rz_deg"};
  if (!u.known)
    return nullptr;
  const char *worst = nullptr;
  double over = 1;
  for (std::size_t a = 0; a < 6; ++a) {
    const double bound = a < 3 ? m_gp.maxSigmaMm : m_gp.maxSigmaDeg, s = a < 3 ? u.sigmaMm[a] : u.sigmaDeg[a - 3];
    if (bound > 0 && s / bound > over) {
      over = s / bound;
      worst = kAxes[a];
    }
  }
  return worst;
}

const char *GuardedServo::heldBy(const tracker::TrackResult &track, bool frozen) const
{
  if (!track.trusted)
    return track.heldBy ? track.heldBy : "confidence";
  if (frozen)
    return "frozen_images";
  if (track.quality < m_lostQuality)
    return "quality";
  if (track.quality < m_qRef - m_gp.qualityDrop)
    return "quality_drop";
  if (!track.phi.isValid())
    return "pose";
  if (const char *axis = uncertainAxis(track.uncertainty))
    return axis;
  if (!m_space.contains(track.phi))
    return "search_space";
  return nullptr;
}

GuardedCommand GuardedServo::step(const tracker::TrackResult &track, bool frozen, const vpColVector &q, const vpHomogeneousMatrix &fMh,
                                  const vpMatrix &hJe, double dt, const vpHomogeneousMatrix *oracle)
{
  GuardedCommand c;
  m_qRef -= m_gp.qualityMemoryPerS * dt;
  const char *held = oracle ? nullptr : heldBy(track, frozen);
  const bool ok = held == nullptr;
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
      held = "servo";
    }
  }
  c.heldBy = held;
  if (!c.servoing)
    wanted = m_servo->stop(m_arm.dof()); // fail-safe: SafeCommand ramps down to it
  c.qdot = m_safe.next(wanted, dt);
  return c;
}

} // namespace pm::hand
