#pragma once
/*!
  \file CalibrationOutputs.h
  What pm-calibrate-rig writes of a stereo rig calibration, or of one camera's (the same files, one
  camera in the rig, its pose on the hand from a hand-eye calibration or given): the rig (rig.json, cameras.xml and,
  for a lens ViSP's model cannot hold, rig_left.yml / rig_right.yml), coverage.png (every corner
  found, residuals as red arrows) and summary.json (the residuals, the baseline, every pair's
  fate and, in the lab, the errors to the rig that took the pictures); what pm-calib-baseline
  writes of a rig file's check: detections.png (the corners found in the first pair) and
  summary.json (the baseline, its differences to the rig file and the verdict); and what they
  print.
*/
#include <optional>
#include <string>

#include "pm/calib/BaselineCheck.h"
#include "pm/calib/CameraCalibration.h"
#include "pm/calib/HandEye.h"
#include "pm/calib/RigCalibration.h"
#include "pm/calib/RigComparison.h"

namespace pm::report {

//! A calibration and what it is measured against.
struct RigCalibrationOutputs
{
  std::string source;                //!< the pairs, in words ("13 image pairs")
  std::string board;                 //!< the pattern, in words (calib::Pattern::describe())
  calib::RigCalibration calibration; //!< what calib::calibrateRig() found
  std::optional<core::StereoRig> truth;    //!< the rig that took the pictures, when known (the lab)
  double arrowGain = 20;             //!< coverage.png: residual arrows drawn this many times longer
};

/*!
  Writes the rig, coverage.png and summary.json into \e dir (created if missing); returns
  summary.json's text. Throws pm::core::Error; on an error nothing new is left in \e dir.

  \code
    pm::report::RigCalibrationOutputs o;
    o.source = std::to_string(pairs.size()) + " image pairs";
    o.board = board.describe();
    o.calibration = pm::calib::calibrateRig(pairs, board);
    pm::report::writeRigCalibration("rig", o);
    std::cout << pm::report::describeRigCalibration(o, "rig");
  \endcode
*/
std::string writeRigCalibration(const std::string &dir, const RigCalibrationOutputs &o);
//! What pm-calibrate-rig prints of it (written to \e dir): residuals, baseline, lenses, the pairs left out and why.
std::string describeRigCalibration(const RigCalibrationOutputs &o, const std::string &dir);

//! A one-camera calibration (pm-calibrate-rig --camera-images) and what it is measured against.
struct CameraCalibrationOutputs
{
  std::string source;                   //!< the images, in words ("14 images")
  std::string board;                    //!< the pattern, in words (calib::Pattern::describe())
  calib::CameraCalibration calibration; //!< what calib::calibrateCamera() found; its camera's hMc is the one written
  std::string poseOnHand;               //!< where hMc comes from, in words ("hand-eye from 20 hand poses", "given")
  std::optional<calib::HandEyeFit> handEye; //!< the hand-eye fit, when hand poses were given
  std::optional<core::PinholeCamera> truth; //!< the camera that took the pictures, when known (the lab)
  double arrowGain = 20;                //!< coverage.png: residual arrows drawn this many times longer
};

/*!
  Writes the one-camera rig (rig.json, cameras.xml and, for a lens ViSP's model cannot hold,
  rig_camera.yml), coverage.png and summary.json into \e dir (created if missing); returns
  summary.json's text. Throws pm::core::Error; on an error nothing new is left in \e dir.

  \code
    pm::report::CameraCalibrationOutputs o;
    o.source = std::to_string(views.size()) + " images";
    o.board = board.describe();
    o.calibration = pm::calib::calibrateCamera(views, board);
    o.handEye = pm::calib::solveHandEye(cMo, fMh); // cMo from o.calibration.views, fMh from the robot
    o.calibration.camera.hMc = o.handEye->hMc;
    o.poseOnHand = "hand-eye from " + std::to_string(fMh.size()) + " hand poses";
    pm::report::writeCameraCalibration("rig", o);
    std::cout << pm::report::describeCameraCalibration(o, "rig");
  \endcode
*/
std::string writeCameraCalibration(const std::string &dir, const CameraCalibrationOutputs &o);
//! What pm-calibrate-rig prints of it (written to \e dir): residual, lens, pose on the hand, the views left out and why.
std::string describeCameraCalibration(const CameraCalibrationOutputs &o, const std::string &dir);

//! A camera's hand-eye calibration against the rig file (pm-calib-baseline --hand-eye).
struct HandEyeAgreement
{
  double translationErrorMm = 0; //!< hMc's distance from the rig file's (mm)
  double rotationErrorDeg = 0;   //!< the angle between them (deg)
};

//! A rig file's check, its tolerances, and what it is drawn on.
struct BaselineCheckOutputs
{
  std::string source;          //!< the pairs, in words
  std::string pattern;         //!< the pattern, in words (calib::Pattern::describe())
  std::string rigPath;         //!< the rig file checked
  calib::BaselineResult result; //!< calib::BaselineCheck::result()
  double toleranceMm = 1.0;    //!< largest acceptable baseline / translation difference (mm)
  double toleranceDeg = 0.3;   //!< largest acceptable rotation difference (deg)
  //! \name The first pair and the corners found in it (detections.png)
  //! @{
  vpImage<vpRGBa> left;                    //!< its left image
  vpImage<vpRGBa> right;                   //!< its right image
  std::vector<vpImagePoint> cornersLeft;   //!< the corners found in the left image (px)
  std::vector<vpImagePoint> cornersRight;  //!< in the right image (px)
  //! @}
  //! \name The hand-eye check, when made (handEyePoses > 0)
  //! @{
  std::size_t handEyePoses = 0;         //!< arm poses used
  HandEyeAgreement handEye[2];          //!< the left and the right camera
  double handEyeToleranceMm = 3.0;      //!< largest acceptable hMc translation difference (mm)
  double handEyeToleranceDeg = 0.5;     //!< largest acceptable hMc rotation difference (deg)
  //! @}

  bool agrees() const;         //!< the baseline and rotation within the tolerances
  bool handEyeAgrees() const;  //!< both hMc within theirs (true without a hand-eye check)
};

/*!
  Writes detections.png and summary.json into \e dir (created if missing); returns summary.json's
  text. Throws pm::core::Error; on an error nothing is left in \e dir.

  \code
    pm::calib::BaselineCheck check(rig, board);
    // ... check.add(left, right, name) for every pair
    pm::report::BaselineCheckOutputs o;
    o.source = "10 pairs";
    o.pattern = board.describe();
    o.rigPath = "rig.json";
    o.result = check.result();
    o.left = check.firstLeft();
    o.right = check.firstRight();
    pm::report::writeBaselineCheck("check", o);
    std::cout << pm::report::describeBaselineCheck(o);
  \endcode
*/
std::string writeBaselineCheck(const std::string &dir, const BaselineCheckOutputs &o);
//! What pm-calib-baseline prints of it: the baseline, the differences, the verdict, the hand-eye check.
std::string describeBaselineCheck(const BaselineCheckOutputs &o);

} // namespace pm::report
