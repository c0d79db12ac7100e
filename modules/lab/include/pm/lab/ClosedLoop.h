#pragma once
/*!
  \file ClosedLoop.h
  The simulated lab in closed loop: the TC-robot moves the target, the stereo rig on the PA-10's
  hand takes a pair every frame (30 fps), the photo-model tracker estimates the target's pose in
  the hand frame (or, in oracle mode, the true pose is used), and PBVS with vpServo commands the
  PA-10's joint velocities, integrated every 2 ms until the next frame.

  Fail-safe: the servo runs only on an estimate that is usable: the tracker trusts it
  (TrackResult::trusted: tracking, its lock verified, its confidence over the threshold), its quality is not under the lost threshold (no grace frames here) nor far under its recent best
  (LoopParams::qualityDrop), the pose lies in the search
  space, and the images are not the very same as the last ones (a frozen camera: real frames are
  never equal to the bit). Otherwise the arm is stopped. Every command goes through
  pm::SafeCommand with the PA-10's speed and acceleration limits, so a stop is a ramp of at most
  the acceleration limits, as is the resumption when the estimate is usable again. Faults can be
  injected (LoopFaults) to test this: blank frames, a frozen camera, a sudden jump of the target.
*/
#include <functional>
#include <memory>

#include <visp3/core/vpColVector.h>

#include "pm/servo/PbvsServo.h"
#include "pm/servo/PoseFilter.h"
#include "pm/servo/SafeCommand.h"
#include "pm/sim/RobotPA10.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TcRobot.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::lab {

struct LoopParams
{
  double fps = 30;          //!< camera rate, also the servo rate
  double robotDt = 0.002;   //!< integration step of the robot (its servo cycle)
  bool oracle = false;      //!< servo on the true pose instead of the estimate
  bool filter = true;       //!< filter the estimate (alpha-beta, in the base frame) and feed its velocity forward
  PoseFilterParams filterParams;
  /*!
    Fail-safe on the quality q: the servo also stops when q falls more than this under its recent
    best (the best q of the servoed frames, forgotten at qualityMemoryPerS per second): after a
    loss the tracker may lock first on a wrong pose that still covers much of the target (q 0.86
    against 0.97), and servoing on it drives the hand away.
  */
  double qualityDrop = 0.08;
  double qualityMemoryPerS = 0.03;
  vpColVector q0 = startJoints(); //!< initial joints (never empty: ViSP 3.5 copies an empty vpColVector with memcpy(nullptr))

  //! The PA-10 looking horizontally along the base's x axis, elbow and wrist well bent (away from their singularities): (0, -35, 0, 80, 0, 45, -90) deg.
  static vpColVector startJoints();
};

enum class CameraFault
{
  None,
  Blank,  //!< the camera delivers black frames
  Frozen  //!< the camera delivers its last pair again
};

//! Faults injected into the loop (for tests and demonstrations).
struct LoopFaults
{
  std::function<CameraFault(long frame)> camera; //!< what the camera does at each frame (empty: no fault)
  long jumpFrame = -1;       //!< from this frame on, the target is moved at once by \e wJump (in the world)
  vpHomogeneousMatrix wJump;
};

struct LoopFrame
{
  double t = 0;
  bool moving = false;
  vpHomogeneousMatrix hMmTrue;   //!< true pose of the model in the hand frame
  vpHomogeneousMatrix hMmUsed;   //!< the pose the servo used (the filtered estimate, or the truth in oracle mode)
  TrackResult track;             //!< the tracker's result (it runs in oracle mode too)
  CameraFault fault = CameraFault::None; //!< the fault injected at this frame
  bool frozen = false;           //!< the images were the very same as the last ones
  bool servoing = false;         //!< the servo ran on the estimate (else the arm was being stopped)
  vpColVector q, qdot;           //!< joints after the frame, and the velocity commanded (after SafeCommand)
  double translationErrorMm = 0; //!< true relative pose against the desired one
  double rotationErrorDeg = 0;
  double estimateErrorMm = 0;    //!< the tracker's estimate against the true pose (mm) ...
  double estimateErrorDeg = 0;   //!< ... and (deg)
  double usedErrorMm = 0;        //!< the pose the servo used (hMmUsed, the filtered estimate) against the true pose (mm) ...
  double usedErrorDeg = 0;       //!< ... and (deg)
  //! The tracker's estimate is wrong: more than kWrongMm or kWrongDeg off the truth.
  bool wrongEstimate() const { return estimateErrorMm > kWrongMm || estimateErrorDeg > kWrongDeg; }
  //! The pose the servo used is wrong (the same bounds).
  bool wrongUsed() const { return usedErrorMm > kWrongMm || usedErrorDeg > kWrongDeg; }
  static constexpr double kWrongMm = 20, kWrongDeg = 5;
};

class ClosedLoop
{
public:
  /*!
    \e wMo0: where the target starts in the world is derived: the desired pose in front of the
    hand at q0. Throws pm::Error for invalid parameters.
  */
  ClosedLoop(const StereoRig &rig, const sim::Scene &scene, const sim::SimulatedPhotoModel &model, const TrackerParams &tp,
             const ServoParams &sp, const LoopParams &lp, const std::function<std::unique_ptr<sim::TcRobot>(const vpHomogeneousMatrix &wMh0)> &makeTc);

  //! One frame: images, estimate, command, integration to the next frame.
  LoopFrame step();
  void setFaults(const LoopFaults &faults) { m_faults = faults; }
  const sim::StereoImages &images() const { return m_images; }
  const PhotoModelTracker &tracker() const { return m_tracker; }
  const sim::RobotPA10 &robot() const { return m_robot; }
  const sim::TcRobot &tc() const { return *m_tc; }
  double time() const { return static_cast<double>(m_frame) / m_lp.fps; }

private:
  const StereoRig &m_rig;
  const sim::Scene &m_scene;
  vpHomogeneousMatrix m_oMm, m_hdMo;
  LoopParams m_lp;
  PhotoModelTracker m_tracker;
  PbvsServo m_servo;
  sim::RobotPA10 m_robot;
  SafeCommand m_safe;            //!< after m_robot: made from its limits
  LoopFaults m_faults;
  std::unique_ptr<sim::TcRobot> m_tc;
  sim::StereoImages m_images;
  long m_frame = 0;
  double m_qRef = 0;             //!< the recent best quality (see LoopParams::qualityDrop)
  PoseFilter m_filter;           //!< the target's estimated pose in the base frame
};

} // namespace pm::lab
