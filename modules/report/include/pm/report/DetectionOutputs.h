#pragma once
/*!
  \file DetectionOutputs.h
  What pm-detect writes of a static detection (the paper's Table 1): detection.png (the model at
  the pose found, on both images) and summary.json (the pose, its fitness, time and work, and,
  with a truth, the errors to it and to the fitness peak nearest it); and the lines of Table 1.
*/
#include <string>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/tracker/StaticDetection.h"

namespace pm::report {

//! The errors of a pose against another, as Table 1 reports them.
struct PoseErrors
{
  double positionMm = 0;   //!< distance between the positions (mm)
  double orientation = 0;  //!< largest |d eps| of the quaternion vectors
  double rotationDeg = 0;  //!< angle of the rotation between them (deg)
};

//! The errors of \e a against \e b.
PoseErrors poseErrors(const core::Phi &a, const core::Phi &b);

//! A detection and what it is measured against.
struct DetectionOutputs
{
  std::string source;      //!< the pair and the model, in words
  tracker::Detection detection;     //!< what detectStatic() found
  std::string budget;      //!< the tracker's budget per frame, in words
  bool haveTruth = false;  //!< whether \e truth holds the pair's true pose
  core::Phi truth{};             //!< the model's true pose (mm, quaternion vector)
  core::Phi peak{};              //!< the fitness peak nearest the truth (nearestFitnessPeak)
  double fitnessAtPeak = 0; //!< F there
};

/*!
  Writes detection.png (\e fitness's points at the pose found, on each camera's image of \e images) and
  summary.json into \e dir; returns summary.json's text. Throws pm::core::Error; on an error nothing
  is left in \e dir.

  \code
    pm::tracker::PhotoModelTracker tracker(rig, model);
    tracker.initialize();
    pm::report::DetectionOutputs o;
    o.source = "my pair";
    o.detection = pm::tracker::detectStatic(tracker, {left, right}, pm::tracker::DetectionParams());
    pm::report::writeDetection("detect", o, tracker.fitness(), {left, right});
    std::cout << pm::report::describeDetection(o, "detect");
  \endcode
*/
std::string writeDetection(const std::string &dir, const DetectionOutputs &o, const core::StereoFitness &fitness,
                           const core::CameraImages &images);
//! What pm-detect prints of it (written to \e dir).
std::string describeDetection(const DetectionOutputs &o, const std::string &dir);

} // namespace pm::report
