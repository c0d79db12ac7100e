#pragma once
/*!
  \file ClosedLoop.h
  The simulated lab in closed loop: the TC-robot moves the target, the stereo rig on the arm's
  hand (the PA-10 by default, or any pm::robot::Arm: ViSP's Viper850 and Afma6) takes a pair
  every frame (30 fps), the photo-model tracker estimates the target's pose in the hand frame
  (or, in oracle mode, the true pose is used), and PBVS with vpServo commands the arm's joint
  velocities, integrated every 2 ms until the next frame (SteppedArm) or sent to a vpRobot that
  moves in real time (ViSPRobotArm).

  Fail-safe: the servo runs only on an estimate that is usable, through pm::hand::GuardedServo,
  the same as on a real arm (pm::hand::HandLoop): see GuardedServo.h. Faults can be injected
  (LoopFaults) to test this: blank frames, a frozen camera, a sudden jump of the target.
*/
#include <functional>
#include <memory>
#include <string>

#include <visp3/core/vpColVector.h>

#include <optional>

#include "pm/hand/GraspApproach.h"
#include "pm/hand/GuardedServo.h"
#include "pm/robot/Arm.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TcRobot.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::lab {

//! Settings of ClosedLoop: rates, oracle mode, the fail-safe and filter (hand::GuardParams), the arm.
struct LoopParams : hand::GuardParams
{
  double fps = 30;          //!< camera rate, also the servo rate (frames per second)
  double robotDt = 0.002;   //!< integration step of the robot (its servo cycle, s; at most 1 / fps)
  bool oracle = false;      //!< servo on the true pose instead of the estimate
  /*!
    The arm that carries the rig when ClosedLoop is not given one: a pm::robot::SteppedArm of
    pm::robot::makeArmModel(arm) at its rest joints, stepped every robotDt ("pa10", "viper850", "afma6").
  */
  std::string arm = "pa10";
  /*!
    Drive ViSP's threaded simulator of that arm instead (pm::robot::ViSPSimulatedArm: viper850 or
    afma6), in real time, exactly as a real vpRobot would be driven: a run takes the motion's real
    duration and does not repeat frame for frame.
  */
  bool realTime = false;
  vpHomogeneousMatrix eMh; //!< the rig's hand frame on that arm's flange (identity: the rig looks along the flange's z axis)
  /*!
    A grasp approach (hand::GraspApproach): while servoed, the hand closes in on the target from
    approach.fromMm to approach.toMm; the desired pose, and the errors against it, follow it. The
    tracker's search space must reach approach.toMm.
  */
  bool graspApproach = false;
  hand::GraspApproachParams approach; //!< its distances and speed
};

//! What the camera does at a frame (LoopFaults::camera).
enum class CameraFault
{
  None,   //!< no fault: the scene rendered as it is
  Blank,  //!< the camera delivers black frames
  Frozen  //!< the camera delivers its last pair again
};

//! Faults injected into the loop (for tests and demonstrations).
struct LoopFaults
{
  std::function<CameraFault(long frame)> camera; //!< what the camera does at each frame (empty: no fault)
  long jumpFrame = -1;       //!< from this frame on, the target is moved at once by \e wJump (in the world; -1: never)
  vpHomogeneousMatrix wJump; //!< the jump, applied on the left of the target's world pose: wMo becomes wJump * wMo
};

//! What one ClosedLoop::step() did: the true and used poses, the tracker's result, the command, the errors.
struct LoopFrame
{
  double t = 0;                  //!< time of the frame (s, frame index / fps)
  bool moving = false;           //!< the TC-robot moves the target at t
  vpHomogeneousMatrix hMmTrue;   //!< true pose of the model in the hand frame
  vpHomogeneousMatrix hMmUsed;   //!< the pose the servo used (the filtered estimate, or the truth in oracle mode)
  tracker::TrackResult track;             //!< the tracker's result (it runs in oracle mode too)
  CameraFault fault = CameraFault::None; //!< the fault injected at this frame
  bool frozen = false;           //!< the images were the very same as the last ones
  bool servoing = false;         //!< the servo ran on the estimate (else the arm was being stopped)
  const char *heldBy = nullptr;  //!< why it was stopped (hand::GuardedServo::heldBy(): the tracker's cue, the state, the uncertainty...; null while servoing)
  //! The arm's joints after the frame (rad or m).
  vpColVector q, qdot;           //!< the joint velocity commanded during the frame (rad/s or m/s, after SafeCommand and the arm's clamp)
  double translationErrorMm = 0; //!< true relative pose against the desired one: translation (mm) ...
  double rotationErrorDeg = 0;   //!< ... and rotation (deg)
  double estimateErrorMm = 0;    //!< the tracker's estimate against the true pose (mm) ...
  double estimateErrorDeg = 0;   //!< ... and (deg)
  double usedErrorMm = 0;        //!< the pose the servo used (hMmUsed, the filtered estimate) against the true pose (mm) ...
  double usedErrorDeg = 0;       //!< ... and (deg)
  //! The tracker's estimate is wrong: more than kWrongMm or kWrongDeg off the truth.
  bool wrongEstimate() const { return estimateErrorMm > kWrongMm || estimateErrorDeg > kWrongDeg; }
  //! The pose the servo used is wrong (the same bounds).
  bool wrongUsed() const { return usedErrorMm > kWrongMm || usedErrorDeg > kWrongDeg; }
  //! An estimate is wrong beyond this translation error (mm) ...
  static constexpr double kWrongMm = 20, kWrongDeg = 5; //!< ... or this rotation error (deg)
};

/*!
  The simulated lab in closed loop, one camera frame per step() (see ClosedLoop.h), with a rig of
  any number of cameras. It copies \e rig, keeps \e scene by reference (they must outlive it) and owns the tracker, the servo, the arm and
  the TC-robot.

  \code
    pm::sim::Scene scene(pm::sim::makeTarget("C12"));
    const pm::core::StereoRig rig = pm::io::loadRig("data/rig/pa10_stereo.json");
    const pm::sim::SimulatedPhotoModel sm = pm::sim::makeSimulatedStereoPhotoModel(scene, rig);
    const std::vector<pm::core::Phi> steps{{0, 0, 500, 0, 0, 0}, {50, 0, 500, 0, 0, 0}}; // mm, quaternion vector, in h0
    auto makeTc = [&](const vpHomogeneousMatrix &wMh0) {
      return std::make_unique<pm::sim::TcRobot>(wMh0, pm::sim::Trajectory(steps, 1.5, 2.0));
    };
    pm::lab::ClosedLoop loop(rig, scene, sm, pm::tracker::TrackerParams(), pm::servo::ServoParams(), pm::lab::LoopParams(), makeTc);
    for (int k = 0; k < 150; ++k) {
      const pm::lab::LoopFrame f = loop.step();
      std::cout << f.t << " s: " << f.translationErrorMm << " mm, " << (f.servoing ? "servoing" : "held") << std::endl;
    }
  \endcode
*/
class ClosedLoop
{
public:
  /*!
    \e makeTc makes the TC-robot from wMh0, the hand's pose in the world (the arm's base frame)
    at the start; the target's motion is given in that hand frame h0. \e arm drives the rig
    from where it is (null: LoopParams::arm stepped in our loop, from its rest joints). \e model's
    build.model is tracked and its oMm gives the truth. The tracker starts searching, with no
    initial pose. Throws pm::core::Error for invalid parameters or if \e makeTc gives no TC-robot.
  */
  ClosedLoop(const core::CameraRig &rig, const sim::Scene &scene, const sim::SimulatedPhotoModel &model, const tracker::TrackerParams &tp,
             const servo::ServoParams &sp, const LoopParams &lp, const std::function<std::unique_ptr<sim::TcRobot>(const vpHomogeneousMatrix &wMh0)> &makeTc,
             std::unique_ptr<robot::Arm> arm = nullptr);

  //! One frame: images, estimate, command, integration to the next frame.
  LoopFrame step();
  //! The faults to inject from the next step() on (they replace the previous ones).
  void setFaults(const LoopFaults &faults) { m_faults = faults; }
  //! The images of the last step(), camera k's at [k].
  const std::vector<vpImage<vpRGBa>> &images() const { return m_images; }
  //! The rig (a copy of the one given).
  const core::CameraRig &rig() const { return m_rig; }
  //! The photo-model tracker.
  const tracker::PhotoModelTracker &tracker() const { return m_tracker; }
  //! Whether the estimate is filtered (LoopParams::filter, Auto resolved for this tracker).
  bool filtering() const { return m_guard.filtering(); }
  //! False when \e u is known and over LoopParams::maxSigmaMm or maxSigmaDeg (each when positive).
  bool certainEnough(const precise::PoseUncertainty &u) const { return m_guard.certainEnough(u); }
  //! The arm that carries the rig.
  const robot::Arm &arm() const { return *m_arm; }
  //! The TC-robot that moves the target.
  const sim::TcRobot &tc() const { return *m_tc; }
  //! The time of the next step()'s frame (s).
  double time() const { return static_cast<double>(m_frame) / m_lp.fps; }

private:
  core::CameraRig m_rig;
  const sim::Scene &m_scene;
  vpHomogeneousMatrix m_oMm, m_hdMo;
  LoopParams m_lp;
  tracker::PhotoModelTracker m_tracker;
  std::unique_ptr<robot::Arm> m_arm;
  hand::GuardedServo m_guard;    //!< after m_tracker and m_arm: made from them
  std::optional<hand::GraspApproach> m_approach; //!< LoopParams::graspApproach
  LoopFaults m_faults;
  std::unique_ptr<sim::TcRobot> m_tc;
  std::vector<vpImage<vpRGBa>> m_images; //!< camera k's at [k]
  long m_frame = 0;
};

} // namespace pm::lab
