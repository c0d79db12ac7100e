#pragma once
/*!
  \file HandLoop.h
  The servo on a real arm: stereo pairs from the cameras on its hand (any
  pm::capture::StereoSource), the photo-model tracker, and the fail-safe servo (GuardedServo, the
  same as the lab's closed loop) commanding the arm's joint velocities (any pm::robot::Arm: a
  vpRobot through ViSPRobotArm). The cameras pace the loop: one command per pair. The arm's
  motion between two pairs is told to the tracker (its odometry).

  The arm stops when the estimate is not usable (a ramp at its acceleration limits), when the
  cameras end, when the loop is destroyed, and when the arm fails (it throws pm::core::Error, after
  stopping).
*/
#include <memory>

#include "pm/capture/StereoSource.h"
#include "pm/core/StereoRig.h"
#include "pm/hand/GuardedServo.h"
#include "pm/robot/Arm.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::hand {

//! What one HandLoop::step() did.
struct HandFrame
{
  long index = 0;          //!< the pair's number in the source
  double timeS = 0;        //!< its time (s)
  tracker::TrackResult track;       //!< the tracker's result
  bool frozen = false;     //!< the pair was the very same as the last one
  GuardedCommand command;  //!< what the servo decided (GuardedCommand::servoing, the joint velocity)
  vpColVector q;           //!< the joints when the pair was taken
  bool tookDesired = false; //!< this frame's estimate became the pose to keep (HandLoop::keepWhereFound)
};

/*!
  The servo of \e arm on the pairs of \e source (see HandLoop.h). \e rig, \e model, \e source and
  \e arm are kept by reference and must outlive it. The tracker starts searching, with no initial pose.
  \code
    pm::robot::ViSPRobotArm arm(myRobot, pm::robot::makeArmModel("viper850"), eMh);
    pm::capture::VideoCaptureSource cameras("0", "1");
    pm::servo::ServoParams sp;
    sp.hdMo = vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0); // keep the target 500 mm ahead
    pm::hand::HandLoop loop(rig, model, pm::tracker::TrackerParams(), sp, pm::hand::GuardParams(), cameras, arm);
    pm::hand::HandFrame f;
    while (loop.step(f))
      std::cout << f.index << (f.command.servoing ? " servoing" : " held") << std::endl;
  \endcode
*/
class HandLoop
{
public:
  //! Throws pm::core::Error for invalid parameters (see GuardedServo) or a non-positive \e fps.
  HandLoop(const core::StereoRig &rig, const core::PhotoModel &model, const tracker::TrackerParams &tp, const servo::ServoParams &sp,
           const GuardParams &gp, capture::StereoSource &source, robot::Arm &arm, double fps = 30);
  //! Stops the arm.
  ~HandLoop();
  HandLoop(const HandLoop &) = delete;
  HandLoop &operator=(const HandLoop &) = delete;
  /*!
    Takes the next pair, tracks it and commands the arm until the next one. False (and the arm
    stopped) when the source has ended. Throws pm::core::Error when the arm or the source fails (the arm
    stopped).
  */
  bool step(HandFrame &f);
  /*!
    Keep the target where it is first found: the first usable estimate becomes the pose to keep
    (ServoParams::hdMo is ignored); the arm is held until then. Call before the first step().
  */
  void keepWhereFound() { m_keepWhereFound = true; }
  //! The pose of the target in the hand frame the servo keeps.
  const vpHomogeneousMatrix &desired() const { return m_guard.desired(); }
  //! The photo-model tracker.
  const tracker::PhotoModelTracker &tracker() const { return m_tracker; }

private:
  capture::StereoSource &m_source;
  robot::Arm &m_arm;
  double m_dt;
  tracker::PhotoModelTracker m_tracker;
  GuardedServo m_guard;
  capture::StereoFrame m_last;
  vpHomogeneousMatrix m_fMhLast;
  bool m_started = false;
  bool m_keepWhereFound = false; //!< the desired pose is still to be taken from the first usable estimate
};

} // namespace pm::hand
