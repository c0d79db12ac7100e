#pragma once
/*!
  \file RigComparison.h
  How far one stereo rig lies from another: a calibration against the rig that took the
  pictures (in the lab), or against the rig file it should replace. Frame-free: it compares the
  right camera's pose in the left one (cLMcR) and each camera's map from raw pixels to rays.

  \code
      const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, board);
      const pm::calib::CalibrationErrors e = pm::calib::compareRigs(c.rig, pm::io::loadRig("rig.json"));
      std::cout << e.baselineErrorMm << " mm, " << e.rotationErrorDeg << " deg" << std::endl;
  \endcode
*/
#include "pm/core/StereoRig.h"

namespace pm::calib {

//! How far an estimated rig lands from the true one (compareRigs()).
struct CalibrationErrors
{
  double baselineErrorMm = 0;      //!< |T| estimated minus true (mm)
  double translationErrorMm = 0;   //!< |T_est - T_true| (mm)
  double rotationErrorDeg = 0;     //!< between the estimated and true cLMcR rotations (deg)
  double reprojectionRmsPx[2] = {0, 0}; //!< each camera: rms distance, over a grid of the raw image, between where the estimated and the true camera see the same ray (px)
};

//! How far \e estimated is from \e truth (frame-free: cLMcR, and each camera's pixel-to-ray map).
CalibrationErrors compareRigs(const core::StereoRig &estimated, const core::StereoRig &truth);

//! How far one estimated camera lands from the true one (compareCameras()).
struct CameraErrors
{
  double reprojectionRmsPx = 0;  //!< rms distance, over a grid of the raw image, between where the two see the same ray (px)
  double translationErrorMm = 0; //!< between their poses on the hand, hMc (mm)
  double rotationErrorDeg = 0;   //!< between their hMc rotations (deg)
};

//! How far \e estimated is from \e truth: the pixel-to-ray map, and the pose on the hand.
CameraErrors compareCameras(const core::PinholeCamera &estimated, const core::PinholeCamera &truth);

} // namespace pm::calib
