#pragma once
/*!
  \file GuardedServo.h
  From the tracker's estimate to a joint velocity an arm can take, in the lab's closed loop and on
  a real arm alike: the servo runs only on an estimate that is usable, and every command goes
  through pm::servo::SafeCommand.

  Usable: the tracker trusts it (TrackResult::trusted: tracking, its lock verified, its confidence
  over the threshold), its quality is not under the tracker's lost threshold nor far under its
  recent best (GuardParams::qualityDrop), its reported 1-sigma uncertainty is within
  GuardParams::maxSigmaMm and maxSigmaDeg, the pose lies in the search space, and the images are
  not the very same as the last ones (a frozen camera: real frames are never equal to the bit).
  Otherwise the arm is stopped: SafeCommand ramps it down at most at its acceleration limits, as it
  ramps the resumption when the estimate is usable again.
*/
#include <memory>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpMatrix.h>

#include "pm/robot/ArmModel.h"
#include "pm/servo/PbvsServo.h"
#include "pm/servo/PoseFilter.h"
#include "pm/servo/SafeCommand.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::hand {

//! When an estimate is used (GuardedServo) and how it is filtered.
struct GuardParams
{
  /*!
    Filter the estimate (alpha-beta, in the base frame) and feed its velocity forward: on or off,
    or Auto: on for a tracker without the precise stage (RM-GA's estimates wander over the hue
    fitness's plateau), off with it (its estimates are within a few tenths of a millimetre and degree,
    the filter's lag would cost more: measured in docs/precise-stage.md).
  */
  enum class Filter { Auto, On, Off };
  Filter filter = Filter::Auto;  //!< see Filter
  servo::PoseFilterParams filterParams; //!< the gains of that filter
  /*!
    Fail-safe on the quality q: the servo also stops when q falls more than this under its recent
    best (the best q of the servoed frames, forgotten at qualityMemoryPerS per second): after a
    loss the tracker may lock first on a wrong pose that still covers much of the target (q 0.86
    against 0.97), and servoing on it drives the hand away.
  */
  double qualityDrop = 0.08;
  double qualityMemoryPerS = 0.03; //!< how fast the recent best q is forgotten (q units per second, >= 0)
  /*!
    Fail-safe on the pose's reported uncertainty (TrackResult::uncertainty, 1-sigma per axis): the
    servo also stops when it is known and its largest sigma exceeds maxSigmaMm (mm) or maxSigmaDeg
    (deg). A frame without a known uncertainty (no precise stage: the flat and stereo models, or
    its pose not kept) is judged by the other checks alone. 0: no such check. The defaults, 2 mm and
    2 deg, are above every frame's in the lab's main jobs (C12 and R2: at most 1.49 mm and 1.51 deg,
    0.53 mm and 0.43 deg on the frames servoed) and above all but the most oblique of the random
    6-DoF run's (up to 0.92 mm and 2.33 deg; docs/trust.md): a wrong pose of 5 deg is then 2.5 sigma away.
  */
  double maxSigmaMm = 2;
  double maxSigmaDeg = 2; //!< see maxSigmaMm
};

//! What one GuardedServo::step() decided.
struct GuardedCommand
{
  bool servoing = false;      //!< the servo ran on the estimate (else the arm is being stopped)
  vpHomogeneousMatrix hMoUsed; //!< the pose the servo used: the (filtered) estimate, or the truth in oracle mode
  vpColVector qdot;           //!< the joint velocity to command for the next frame (after SafeCommand)
  const char *heldBy = nullptr; //!< why the arm was being stopped (GuardedServo::heldBy(); null while servoing)
};

/*!
  The fail-safe servo of an arm carrying the rig (see GuardedServo.h): one step() per camera frame.
  \code
    pm::hand::GuardedServo guard(servoParams, pm::hand::GuardParams(), tracker, arm.model());
    const pm::tracker::TrackResult r = tracker.track(left, right);
    const vpColVector q = arm.q();
    const pm::hand::GuardedCommand c = guard.step(r, false, q, arm.fMh(q), arm.hJe(q), 1.0 / 30);
    arm.setJointVelocity(c.qdot);
  \endcode
*/
class GuardedServo
{
public:
  /*!
    For the estimates of \e tracker (its lost threshold, search space and whether it has the precise
    stage are read here) and the joints of \e arm (its limits; the model must outlive this). Throws
    pm::core::Error for a quality drop that is not positive, a negative memory rate or sigma bound.
  */
  GuardedServo(const servo::ServoParams &sp, const GuardParams &gp, const tracker::PhotoModelTracker &tracker, const robot::ArmModel &arm);
  /*!
    The command for the next \e dt seconds from the estimate \e track of a frame (\e frozen: its
    images are the very same as the last ones) taken at joints \e q, hand pose \e fMh and hand
    Jacobian \e hJe. With \e oracle (the lab's), the servo uses that pose instead and always runs.
  */
  GuardedCommand step(const tracker::TrackResult &track, bool frozen, const vpColVector &q, const vpHomogeneousMatrix &fMh,
                      const vpMatrix &hJe, double dt, const vpHomogeneousMatrix *oracle = nullptr);
  //! From now on, keep the target at \e hdMo in the hand frame (ServoParams::hdMo; the servo starts afresh).
  void setDesired(const vpHomogeneousMatrix &hdMo);
  /*!
    Moves the pose the servo keeps to \e hdMo (a grasp approach closing in, a little every frame):
    the servo goes on, with its memory of the target's motion. Throws pm::core::Error unless
    \e hdMo is a rigid transformation.
  */
  void moveDesired(const vpHomogeneousMatrix &hdMo);
  //! The pose of the target in the hand frame the servo keeps.
  const vpHomogeneousMatrix &desired() const { return m_sp.hdMo; }
  //! Whether the estimate is filtered (GuardParams::filter, Auto resolved for the tracker).
  bool filtering() const { return m_filtering; }
  //! False when \e u is known and over GuardParams::maxSigmaMm or maxSigmaDeg (each when positive).
  bool certainEnough(const precise::PoseUncertainty &u) const { return uncertainAxis(u) == nullptr; }
  //! The name of the axis whose sigma is farthest over its bound ("sigma_x_mm" ... "sigma_rz_deg"), or null when none is.
  const char *uncertainAxis(const precise::PoseUncertainty &u) const;
  //! Whether \e track is usable (see GuardedServo.h) against the recent best quality as it stands.
  bool usable(const tracker::TrackResult &track, bool frozen) const { return heldBy(track, frozen) == nullptr; }
  /*!
    Why \e track is not usable (null: it is), a static string: the tracker's reason when it is not
    trusted (TrackResult::heldBy), else "frozen_images", "quality" (under the lost threshold),
    "quality_drop" (under the recent best by more than GuardParams::qualityDrop), "pose" (not valid),
    the axis whose sigma is over its bound ("sigma_x_mm" ... "sigma_rz_deg"), or "search_space".
  */
  const char *heldBy(const tracker::TrackResult &track, bool frozen) const;

private:
  servo::ServoParams m_sp;
  std::unique_ptr<servo::PbvsServo> m_servo; //!< not movable (vpServo keeps pointers into it)
  GuardParams m_gp;
  double m_lostQuality;
  rmga::SearchSpace m_space;
  bool m_filtering;
  const robot::ArmModel &m_arm;
  servo::SafeCommand m_safe;
  servo::PoseFilter m_filter;  //!< the target's estimated pose in the base frame
  double m_qRef = 0;    //!< the recent best quality (see GuardParams::qualityDrop)
};

} // namespace pm::hand
