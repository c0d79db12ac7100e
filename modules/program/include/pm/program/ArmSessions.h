#pragma once
/*!
  \file ArmSessions.h
  The two sessions of runArmProgram on an arm: the pass (views folder) and the servo, with the
  cameras given (live, VideoCaptureSource) or the lab's renderer in their place (--simulate).
*/
#include <ostream>
#include <string>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/robot/Arm.h"

namespace pm::program {

//! Where the pairs come from, and the rig.
struct CameraOptions
{
  std::string rig;             //!< the stereo rig file (pm-make-rig, pm-calibrate-rig)
  std::string left;            //!< the left live camera (OpenCV VideoCapture: index, device, file, pipeline)
  std::string right;           //!< the right one
  std::string simulate;        //!< or the lab's renderer, this target ahead of the hand
  double fps = 30;             //!< the cameras' rate
  double distanceMm = 500;     //!< the target's distance ahead of the hand at the start (the pass's pivot; --simulate places it there)
};

//! The pass: views, how many pairs are dropped at each stop, backgrounds.
struct PassOptions
{
  std::string views;           //!< the views folder to write
  int count = 16;              //!< hand poses of the pass
  int settlePairs = 4;         //!< pairs dropped at each stop
  bool backgrounds = true;     //!< a second round with the target removed
  bool quiet = false;          //!< no progress
};

//! The servo: the model, how long, the pose to keep.
struct ServoOptions
{
  std::string model;           //!< the photo-model file (pm-make-model's model.json)
  std::string desired;         //!< the pose of the target to keep in the hand frame (vpPoseVector YAML; empty: where it is first found)
  double durationS = 0;        //!< stop after this long (s; 0: when the cameras end, or Ctrl-C)
  bool quiet = false;          //!< no line per second
};

//! Makes the pass with \e arm (see pm::hand::recordPass) and writes the views folder; reports on \e out.
void runPassSession(robot::Arm &arm, const CameraOptions &cameras, const PassOptions &pass, std::ostream &out);
//! Servos \e arm on the model (see pm::hand::HandLoop); reports on \e out. Returns at the end or on Ctrl-C.
void runServoSession(robot::Arm &arm, const CameraOptions &cameras, const ServoOptions &servo, std::ostream &out);

} // namespace pm::program
