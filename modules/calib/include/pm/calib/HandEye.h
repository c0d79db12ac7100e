#pragma once
/*!
  \file HandEye.h
  A camera's pose on the hand (hMc) from views of a board fixed in the world, each taken at a hand
  pose the robot knows: ViSP's vpHandEyeCalibration solves the AX = XB problem, and the answer is
  checked by what it implies, the board's pose in the robot's base frame from every view
  (fMo = fMh hMc cMo), which must be one pose. Its spread is the calibration's own error bar: a
  hand pose read late, a board that moved, or a wrong pose file shows there.

  \code
      // cMo: the board in the camera at each view (e.g. CameraCalibration's ViewReport::cMo)
      // fMh: the hand in the robot's base frame at the same views (the robot's forward kinematics)
      const pm::calib::HandEyeFit fit = pm::calib::solveHandEye(cMo, fMh);
      std::cout << "hMc " << vpPoseVector(fit.hMc).t() << ", board spread " << fit.spreadMm << " mm\n";
  \endcode
*/
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

namespace pm::calib {

//! What solveHandEye() finds: the camera on the hand, and how well the views agree with it.
struct HandEyeFit
{
  vpHomogeneousMatrix hMc;    //!< the camera's pose in the hand frame (metres)
  vpHomogeneousMatrix fMo;    //!< the board's pose in the base frame, the mean over the views
  double spreadMm = 0;        //!< rms distance of each view's fMo from their mean (mm)
  double spreadDeg = 0;       //!< rms angle of each view's fMo from their mean (deg)
  std::size_t views = 0;      //!< views used
};

/*!
  hMc from \e cMo (the board in the camera) and \e fMh (the hand in the base frame) at the same
  views, through vpHandEyeCalibration (its report on stdout silenced). Throws pm::core::Error when
  the lists differ in length, hold fewer than 3 views, or ViSP's calibration fails (the hand's
  rotations too alike).
*/
HandEyeFit solveHandEye(const std::vector<vpHomogeneousMatrix> &cMo, const std::vector<vpHomogeneousMatrix> &fMh);

} // namespace pm::calib
