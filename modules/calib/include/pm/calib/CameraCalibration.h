#pragma once
/*!
  \file CameraCalibration.h
  Calibrating one camera from images of a chessboard or an AprilTag board: the pattern's features
  in each image (Pattern::detect), the chessboard's sharpness check (estimateChessboardSharpness),
  then cv::calibrateCamera for the intrinsics and five distortion coefficients k1, k2, p1, p2, k3
  (k3 held at 0 when the five-coefficient model folds the image). It is the one-camera half of
  RigCalibration.h, and calibrateRig() calls the same steps for each of its two cameras. Every
  view's board pose (cMo) comes back with it, for the hand-eye calibration (HandEye.h) of a
  camera on the hand.

  A view is left out when the board is not found in it, is blurred (its edges wider than
  maxEdgeWidthPx) or is not the first view's size; fewer than minViews usable views is an error
  that lists the views left out and why.

  \code
      // views: a std::vector<pm::calib::CalibrationView>, raw images as the camera gives them
      pm::calib::ChessBoard board;
      board.innerRows = 6;
      board.innerCols = 9;
      board.squareMm = 25;
      const pm::calib::CameraCalibration c = pm::calib::calibrateCamera(views, board);
      std::cout << c.viewsUsed << " views, rms " << c.rmsPx << " px, " << c.camera.distortion.describe() << "\n";
  \endcode
*/
#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/core/vpRGBa.h>

#include "pm/calib/Pattern.h"
#include "pm/core/PinholeCamera.h"

namespace pm::calib {

//! One raw image (as the camera gives it) of the pattern, for calibrateCamera().
struct CalibrationView
{
  std::string name;      //!< for reports, e.g. "left01.jpg"
  vpImage<vpRGBa> image; //!< the camera's image
};

//! The limits calibrateCamera() applies to the views.
struct CameraCalibrationParams
{
  int minViews = 5;            //!< usable views needed (at least 3)
  double maxEdgeWidthPx = 5.0; //!< chessboard blur limit (px): mean width of the board's edges (estimateChessboardSharpness)
  void validate() const;       //!< throws pm::core::Error for a value out of range
};

//! One view's fate and, when used, its residuals and the board's pose in it.
struct ViewReport
{
  std::string name;                   //!< the view's CalibrationView::name
  bool used = false;                  //!< for the intrinsics
  std::string reason;                 //!< why it was not used ("" when used)
  double edgeWidthPx = 0;             //!< chessboard: mean width of the board's edges (px; 0 when not measured)
  double rmsPx = 0;                   //!< reprojection rms at the calibration (used views)
  vpHomogeneousMatrix cMo;            //!< the board's pose in the camera (metres; used views)
  std::vector<vpImagePoint> corners;  //!< detected (raw image)
  std::vector<vpImagePoint> projected;//!< the board's corners reprojected by the calibration
};

//! What calibrateCamera() returns: the camera (its hMc the identity), its residual and every view's fate.
struct CameraCalibration
{
  core::PinholeCamera camera;     //!< intrinsics with distortion and image size; hMc is left to the hand-eye step
  double rmsPx = 0;               //!< cv::calibrateCamera's reprojection rms (px)
  int viewsUsed = 0;              //!< views in the calibration
  bool k3Fixed = false;           //!< k3 held at 0: the five-coefficient model folded the image (too few views at its edges)
  std::vector<ViewReport> views;  //!< every view given, in order
};

/*!
  Calibrates one camera named \e name from \e views of \e board (see CameraCalibration.h). Throws
  pm::core::Error for an invalid board or parameters, no view, or fewer than params.minViews
  usable views (the message lists the views left out and why).

  \code
#include <iostream>

#include "pm/calib/CameraCalibration.h"
#include "pm/calib/ChessBoard.h"
#include "pm/io/ImageFile.h"

int main()
{
  std::vector<pm::calib::CalibrationView> views;
  for (int k = 1; k <= 14; ++k) {
    pm::calib::CalibrationView v;
    v.name = "left" + std::to_string(k) + ".jpg";
    v.image = pm::io::readColorImage(v.name);
    views.push_back(v);
  }
  pm::calib::ChessBoard board;
  board.innerRows = 6;
  board.innerCols = 9;
  board.squareMm = 25;
  const pm::calib::CameraCalibration c = pm::calib::calibrateCamera(views, board);
  std::cout << c.viewsUsed << " views, rms " << c.rmsPx << " px" << std::endl;
}
  \endcode
*/
CameraCalibration calibrateCamera(const std::vector<CalibrationView> &views, const Pattern &board,
                                  const CameraCalibrationParams &params = CameraCalibrationParams(),
                                  const std::string &name = "camera");

/*!
  The board's features in one raw image \e image of camera \e who ("left", "camera"), checked:
  the image \e w x \e h, at least 6 features, and a chessboard's edges no wider than
  \e maxEdgeWidthPx (their width into \e edgeWidthPx). Throws pm::core::Error with the reason.
*/
PatternDetection detectCalibrationBoard(const vpImage<vpRGBa> &image, const std::string &who, const Pattern &board,
                                        double maxEdgeWidthPx, unsigned w, unsigned h, double &edgeWidthPx);

//! A picture of where the corners fell in the camera, with the residuals as arrows (x \e gain).
vpImage<vpRGBa> coverageImage(const CameraCalibration &c, double gain = 20);

} // namespace pm::calib
