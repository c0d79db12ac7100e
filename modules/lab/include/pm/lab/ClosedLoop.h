#pragma once
/*!
  \file ClosedLoop.h
  The simulated lab in closed loop: the TC-robot moves the target, the stereo rig on the PA-10's
  hand takes a pair every frame (30 fps), the photo-model tracker estimates the target's pose in
  the hand frame (or, in oracle mode, the true pose is used), and PBVS with vpServo commands the
  PA-10's joint velocities, integrated every 2 ms until the next frame.

  Fail-safe: when the tracker does not report "tracking", the arm is stopped (zero velocity; the
  PA-10's speed limits bound every command) and it resumes when tracking is regained.
*/
#include <functional>
#include <memory>

#include <visp3/core/vpColVector.h>

#include "pm/servo/PbvsServo.h"
#include "pm/servo/PoseFilter.h"
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
  vpColVector q0 = startJoints(); //!< initial joints (never empty: ViSP 3.5 copies an empty vpColVector with memcpy(nullptr))

  //! The PA-10 looking horizontally along the base's x axis, elbow and wrist well bent (away from their singularities): (0, -35, 0, 80, 0, 45, -90) deg.
  static vpColVector startJoints();
};

struct LoopFrame
{
  double t = 0;
  bool moving = false;
  vpHomogeneousMatrix hMmTrue;   //!< true pose of the model in the hand frame
  vpHomogeneousMatrix hMmUsed;   //!< the pose the servo used (the filtered estimate, or the truth in oracle mode)
  TrackResult track;             //!< the tracker's result (it runs in oracle mode too)
  bool servoing = false;         //!< a velocity was commanded (else the arm was stopped)
  vpColVector q, qdot;           //!< joints after the frame, and the velocity commanded
  double translationErrorMm = 0; //!< true relative pose against the desired one
  double rotationErrorDeg = 0;
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
  std::unique_ptr<sim::TcRobot> m_tc;
  sim::StereoImages m_images;
  long m_frame = 0;
  PoseFilter m_filter;           //!< the target's estimated pose in the base frame
};

} // namespace pm::lab
