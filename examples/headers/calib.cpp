// The usage examples of pm::calib's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/calib/BaselineCheck.h"
#include "pm/calib/ChessBoard.h"
#include "pm/calib/RigCalibration.h"
#include "pm/calib/StereoBaseline.h"
#include "pm/calib/TagBoard.h"

#include <iostream>
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/calib/RigComparison.h"
#include "pm/calib/CameraCalibration.h"
#include "pm/calib/HandEye.h"
#include <visp3/core/vpPoseVector.h>
namespace pm_examples {

// BaselineCheck.h
void exampleBaselineCheck()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const pm::calib::TagBoard board;
  pm::calib::BaselineCheck check(rig, board);
  for (int k = 0; k < 10; ++k)
    check.add(pm::io::readColorImage("L_" + std::to_string(k) + ".png"),
              pm::io::readColorImage("R_" + std::to_string(k) + ".png"), "pair " + std::to_string(k));
  const pm::calib::BaselineResult r = check.result();
  std::cout << r.baselineMm << " mm, " << r.rotationErrorDeg << " deg from the rig file" << std::endl;
}

// RigCalibration.h
void exampleRigCalibration(const std::vector<pm::calib::StereoImagePair> &pairs)
{
  // pairs: a std::vector<pm::calib::StereoImagePair>, raw images as the cameras give them
  pm::calib::ChessBoard board;
  board.innerRows = 6;
  board.innerCols = 9;
  board.squareMm = 25;
  const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, board);
  pm::io::saveRig(c.rig, "rig.json", "rig.xml"); // then pm-calib-baseline, pm-make-model, pm-track
}

// RigComparison.h
void exampleRigComparison(const std::vector<pm::calib::StereoImagePair> &pairs, const pm::calib::Pattern &board)
{
  const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, board);
  const pm::calib::CalibrationErrors e = pm::calib::compareRigs(c.rig, pm::io::loadRig("rig.json"));
  std::cout << e.baselineErrorMm << " mm, " << e.rotationErrorDeg << " deg" << std::endl;
}

// CameraCalibration.h
void exampleCameraCalibration(const std::vector<pm::calib::CalibrationView> &views)
{
  // views: a std::vector<pm::calib::CalibrationView>, raw images as the camera gives them
  pm::calib::ChessBoard board;
  board.innerRows = 6;
  board.innerCols = 9;
  board.squareMm = 25;
  const pm::calib::CameraCalibration c = pm::calib::calibrateCamera(views, board);
  std::cout << c.viewsUsed << " views, rms " << c.rmsPx << " px, " << c.camera.distortion.describe() << "\n";
}

// HandEye.h
void exampleHandEye(const std::vector<vpHomogeneousMatrix> &cMo, const std::vector<vpHomogeneousMatrix> &fMh)
{
  // cMo: the board in the camera at each view (e.g. CameraCalibration's ViewReport::cMo)
  // fMh: the hand in the robot's base frame at the same views (the robot's forward kinematics)
  const pm::calib::HandEyeFit fit = pm::calib::solveHandEye(cMo, fMh);
  std::cout << "hMc " << vpPoseVector(fit.hMc).t() << ", board spread " << fit.spreadMm << " mm\n";
}

} // namespace pm_examples
