#pragma once
/*!
  \file HandPass.h
  The pass of the hand around the target on a real arm (or any pm::robot::Arm): the arm moves view
  by view along pm::robot::planArmPass's plan (checked reachable, within the joint limits, before it
  moves at all), a stereo pair is taken at each stop, then (optionally) the same stops again with
  the target removed for the backgrounds, and the arm goes back to where it started. The views are
  what pm::io::saveViewsFolder writes and pm-make-model --views reads.
*/
#include <functional>
#include <string>
#include <vector>

#include "pm/capture/StereoSource.h"
#include "pm/model/PassPlanner.h"
#include "pm/model/PassView.h"
#include "pm/robot/Arm.h"

namespace pm::hand {

//! How recordPass() takes its pairs.
struct PassRecording
{
  /*!
    Pairs read and dropped at each stop before the one kept: what the cameras buffered while the
    arm moved, and the arm's settling (a live source at 30 fps: 4 pairs, about 0.13 s).
  */
  int settlePairs = 4;
  bool backgrounds = true; //!< a second round with the target removed (not needed on a plain backdrop of known hue)
  /*!
    Called once between the two rounds with what to do ("remove the target ..."); it returns when
    that is done (a program waits for Enter). Empty with backgrounds: pm::core::Error before the arm moves.
  */
  std::function<void(const std::string &)> ask;
  std::function<void(std::size_t done, std::size_t total)> progress; //!< after each pair kept (may be empty)
  //! Told, before the arm moves, of each outer-ring view the arm cannot reach and the pass leaves out (may be empty).
  std::function<void(const std::string &)> note;
};

/*!
  Makes the pass of \e plan with \e arm from where it is, the plan's pivot \e plan.distanceMm ahead
  of the hand, and takes the pairs from \e source (see HandPass.h). Outer-ring views out of the arm's
  reach are left out (PassRecording::note). Throws pm::core::Error naming the first innermost-ring
  view out of reach and the joint in the way (before any motion), when the source ends, or when
  the arm fails (the arm is then stopped).
  \code
    pm::robot::ViSPRobotArm arm(myRobot, pm::robot::makeArmModel("viper850"), eMh);
    pm::capture::VideoCaptureSource cameras("0", "1");
    pm::model::PassPlan plan;
    plan.distanceMm = 500;   // the target this far ahead of the hand, on its z axis
    pm::hand::PassRecording rec;
    rec.ask = [](const std::string &what) { std::cout << what << std::endl; std::cin.get(); };
    pm::io::saveViewsFolder(pm::hand::recordPass(arm, cameras, plan, rec), "views");
  \endcode
*/
std::vector<model::PassView> recordPass(robot::Arm &arm, capture::StereoSource &source, const model::PassPlan &plan,
                                 const PassRecording &recording = PassRecording());

} // namespace pm::hand
