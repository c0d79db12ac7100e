#include "pm/lab/ClosedLoop.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::lab {

vpColVector LoopParams::startJoints()
{
  const double deg[7] = {0, -35, 0, 80, 0, 45, -90};
  vpColVector q(7);
  for (unsigned i = 0; i < 7; ++i)
    q[i] = deg[i] * M_PI / 180;
  return q;
}

ClosedLoop::ClosedLoop(const StereoRig &rig, const sim::Scene &scene, const sim::SimulatedPhotoModel &model,
                       const TrackerParams &tp, const ServoParams &sp, const LoopParams &lp,
                       const std::function<std::unique_ptr<sim::TcRobot>(const vpHomogeneousMatrix &)> &makeTc)
    : m_rig(rig), m_scene(scene), m_oMm(model.oMm), m_hdMo(sp.hdMo), m_lp(lp), m_tracker(rig, model.build.model, tp),
      m_servo(sp), m_filter(lp.filterParams)
{
  if (!(lp.fps > 0 && lp.robotDt > 0 && lp.robotDt <= 1.0 / lp.fps))
    throw Error("closed loop: the frame rate must be positive and the robot step at most a frame");
  m_robot.setPosition(vpRobot::JOINT_STATE, lp.q0);
  m_robot.setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
  // The target starts at the desired pose in front of the hand.
  m_tc = makeTc(m_robot.fMe());
  if (!m_tc)
    throw Error("closed loop: no TC-robot");
  m_tracker.initialize(); // no initial pose
}

LoopFrame ClosedLoop::step()
{
  LoopFrame f;
  f.t = time();
  f.moving = m_tc->moving(f.t);
  const vpHomogeneousMatrix fMh = m_robot.fMe();
  const vpHomogeneousMatrix hMo = fMh.inverse() * m_tc->wMo(f.t); // the toy in the hand frame
  f.hMmTrue = hMo * m_oMm;
  m_images = m_scene.renderStereo(m_rig, hMo, static_cast<std::uint64_t>(m_frame));
  // The tracker runs in both modes (its estimate is recorded); the oracle servos on the truth.
  f.track = m_tracker.track(m_images.left, m_images.right);
  const bool usable = m_lp.oracle || f.track.state == TrackState::Tracking;
  vpColVector twist;
  if (m_lp.oracle) {
    f.hMmUsed = f.hMmTrue;
  } else if (usable && m_lp.filter) { // filtered in the base frame, where the target moves smoothly
    m_filter.update(fMh * f.track.hMo, 1.0 / m_lp.fps);
    f.hMmUsed = fMh.inverse() * m_filter.pose();
    twist = m_filter.twist();
  } else {
    f.hMmUsed = f.track.hMo;
    if (!usable)
      m_filter.reset();
  }
  vpMatrix eJe;
  m_robot.get_eJe(eJe);
  vpColVector qdot;
  if (usable) {
    qdot = m_servo.computeJointVelocity(f.hMmUsed, fMh, eJe, m_robot.q(), m_robot.jointMin(), m_robot.jointMax(),
                                        1.0 / m_lp.fps, twist.size() == 6 ? &twist : nullptr);
    f.servoing = true;
  } else {
    qdot = m_servo.stop(sim::RobotPA10::kDof); // fail-safe
  }
  m_robot.setVelocity(vpRobot::JOINT_STATE, qdot);
  f.qdot = m_robot.qdot(); // as clamped to the speed limits
  const int n = std::max(1, static_cast<int>(std::lround(1.0 / m_lp.fps / m_lp.robotDt)));
  for (int i = 0; i < n; ++i)
    m_robot.step(1.0 / m_lp.fps / n);
  f.q = m_robot.q();
  // Tell the tracker how the hand moved (the robot's odometry).
  const vpHomogeneousMatrix hNowMhPrev = m_robot.fMe().inverse() * fMh;
  m_tracker.applyHandMotion(hNowMhPrev);
  const vpHomogeneousMatrix e = m_hdMo.inverse() * f.hMmTrue;
  f.translationErrorMm = e.getTranslationVector().frobeniusNorm() * 1e3;
  f.rotationErrorDeg = e.getThetaUVector().getTheta() * 180 / M_PI;
  ++m_frame;
  return f;
}

} // namespace pm::lab
