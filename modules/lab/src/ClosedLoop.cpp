#include "pm/lab/ClosedLoop.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "pm/core/Error.h"
#include "pm/robot/ArmCatalog.h"
#include "pm/robot/SteppedArm.h"
#include "pm/robot/ViSPSimulatedArm.h"

namespace pm::lab {

namespace {
std::unique_ptr<robot::Arm> makeArm(const LoopParams &lp)
{
  if (lp.realTime)
    return std::make_unique<robot::ViSPSimulatedArm>(lp.arm, lp.eMh);
  return std::make_unique<robot::SteppedArm>(robot::makeArmModel(lp.arm), lp.eMh, lp.robotDt);
}
} // namespace

ClosedLoop::ClosedLoop(const core::CameraRig &rig, const sim::Scene &scene, const sim::SimulatedPhotoModel &model,
                       const tracker::TrackerParams &tp, const servo::ServoParams &sp, const LoopParams &lp,
                       const std::function<std::unique_ptr<sim::TcRobot>(const vpHomogeneousMatrix &)> &makeTc,
                       std::unique_ptr<robot::Arm> arm)
    : m_rig(rig), m_scene(scene), m_oMm(model.oMm), m_hdMo(sp.hdMo), m_lp(lp), m_tracker(rig, model.build.model, tp),
      m_arm(arm ? std::move(arm) : makeArm(lp)), m_guard(sp, lp, m_tracker, m_arm->model())
{
  if (!(lp.fps > 0 && lp.robotDt > 0 && lp.robotDt <= 1.0 / lp.fps))
    throw core::Error("closed loop: the frame rate must be positive and the robot step at most a frame");
  if (lp.graspApproach) {
    m_approach.emplace(lp.approach, sp.hdMo);
    if (!(lp.approach.toMm > tp.search.space.lo[2]))
      throw core::Error("closed loop: the grasp approach ends at " + std::to_string(static_cast<int>(lp.approach.toMm)) +
                        " mm, nearer than the tracker's search space reaches (z from " +
                        std::to_string(static_cast<int>(tp.search.space.lo[2])) + " mm): widen search.space");
    m_hdMo = m_approach->hdMo();
    m_guard.moveDesired(m_hdMo);
  }
  // The target starts at the desired pose in front of the hand.
  m_tc = makeTc(m_arm->fMh());
  if (!m_tc)
    throw core::Error("closed loop: no TC-robot");
  m_tracker.initialize(); // no initial pose
}

LoopFrame ClosedLoop::step()
{
  LoopFrame f;
  f.t = time();
  f.moving = m_tc->moving(f.t);
  const vpColVector q = m_arm->q();
  const vpHomogeneousMatrix fMh = m_arm->fMh(q);
  vpHomogeneousMatrix wMo = m_tc->wMo(f.t);
  if (m_faults.jumpFrame >= 0 && m_frame >= m_faults.jumpFrame)
    wMo = m_faults.wJump * wMo;
  const vpHomogeneousMatrix hMo = fMh.inverse() * wMo; // the toy in the hand frame
  f.hMmTrue = hMo * m_oMm;
  f.fault = m_faults.camera ? m_faults.camera(m_frame) : CameraFault::None;
  std::vector<vpImage<vpRGBa>> next;
  if (f.fault == CameraFault::Blank) {
    next.reserve(m_rig.size());
    for (const core::PinholeCamera &c : m_rig.cameras)
      next.emplace_back(c.height, c.width, vpRGBa(0, 0, 0, 255));
  } else if (f.fault == CameraFault::None || m_frame == 0) {
    // A still backdrop stays where it stood at the start while the target moves.
    const vpHomogeneousMatrix oMb = m_scene.params().stillBackdrop ? wMo.inverse() * m_tc->wMo(0) : vpHomogeneousMatrix();
    next = m_scene.renderRig(m_rig, hMo, static_cast<std::uint64_t>(m_frame), oMb);
  } else {
    next = m_images; // frozen: the last images again
  }
  f.frozen = m_frame > 0 && next.size() == m_images.size();
  for (std::size_t k = 0; k < next.size() && f.frozen; ++k)
    f.frozen = next[k] == m_images[k]; // ViSP 3.5's vpImage::operator== is not const
  m_images = std::move(next);
  // The tracker runs in both modes (its estimate is recorded); the oracle servos on the truth.
  f.track = m_tracker.track(core::CameraImages::of(m_images));
  const vpMatrix hJe = m_arm->hJe(q);
  const hand::GuardedCommand c = m_guard.step(f.track, f.frozen, q, fMh, hJe, 1.0 / m_lp.fps, m_lp.oracle ? &f.hMmTrue : nullptr);
  f.hMmUsed = c.hMoUsed;
  f.servoing = c.servoing;
  f.heldBy = c.heldBy;
  m_arm->setJointVelocity(c.qdot);
  f.qdot = m_arm->commanded(); // as clamped by the arm
  m_arm->advance(1.0 / m_lp.fps);
  f.q = m_arm->q();
  // Tell the tracker how the hand moved (the robot's odometry).
  const vpHomogeneousMatrix hNowMhPrev = m_arm->fMh(f.q).inverse() * fMh;
  m_tracker.applyHandMotion(hNowMhPrev);
  const vpHomogeneousMatrix e = m_hdMo.inverse() * f.hMmTrue;
  f.translationErrorMm = e.getTranslationVector().frobeniusNorm() * 1e3;
  f.rotationErrorDeg = e.getThetaUVector().getTheta() * 180 / M_PI;
  const core::Phi truth = core::fromHomogeneousMatrix(f.hMmTrue), used = core::fromHomogeneousMatrix(f.hMmUsed);
  f.estimateErrorMm = core::translationDistanceMm(f.track.phi, truth);
  f.estimateErrorDeg = core::rotationDistanceDeg(f.track.phi, truth);
  f.usedErrorMm = core::translationDistanceMm(used, truth);
  f.usedErrorDeg = core::rotationDistanceDeg(used, truth);
  if (m_approach) { // closes in for the next frame
    m_approach->advance(f.servoing, 1.0 / m_lp.fps);
    m_hdMo = m_approach->hdMo();
    m_guard.moveDesired(m_hdMo);
  }
  ++m_frame;
  return f;
}

} // namespace pm::lab
