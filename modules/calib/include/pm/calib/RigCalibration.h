#pragma once
/*!
  \file RigCalibration.h
  Calibrating a stereo rig from image pairs of a chessboard or an AprilTag board: the pattern's
  features in each image (Pattern::detect: OpenCV's findChessboardCorners and cornerSubPix, or
  vpDetectorAprilTag's tag corners, numbered so that a board seen in part still pairs up), a
  sharpness check for a chessboard (estimateChessboardSharpness), cv::calibrateCamera for each camera (intrinsics and five
  distortion coefficients k1, k2, p1, p2, k3), then cv::stereoCalibrate with those intrinsics
  fixed for the pose of the right camera in the left one (on the features both cameras found). Each camera's intrinsics use every view
  where that camera sees the whole board sharply (a pair whose other image misses it still helps
  cover the image's edges, where the lens bends most); the stereo pose uses the pairs where both do. Nothing of the calibration is written
  by hand: this is the bookkeeping around OpenCV's, with every rejected view and its reason.

  The rig it returns has the project's hand frame (StereoRig.h): its origin midway between the
  optical centres and its axes turned halfway from the left camera's to the right one's (for a
  symmetric toed-in rig, z along the bisector), lengths in the board's unit taken as mm.
  A view is rejected when the whole board is not found in it or it is blurred (board edges wider
  than maxEdgeWidthPx), a pair when its images differ in size from the first pair's; fewer than
  minPairs pairs usable for the stereo pose (or views for a camera) is an error.

  \code
      // pairs: a std::vector<pm::calib::StereoImagePair>, raw images as the cameras give them
      pm::calib::ChessBoard board;
      board.innerRows = 6;
      board.innerCols = 9;
      board.squareMm = 25;
      const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, board);
      pm::io::saveRig(c.rig, "rig.json", "rig.xml"); // then pm-calib-baseline, pm-make-model, pm-track
  \endcode
*/
#include <string>
#include <vector>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/core/vpRGBa.h>
#include "pm/calib/ChessBoard.h"
#include "pm/calib/TagBoard.h"
#include "pm/core/StereoRig.h"

namespace pm::calib {

//! One stereo pair of raw images (as the cameras give them) of the pattern, for calibrateRig().
struct StereoImagePair
{
  std::string name;                   //!< for reports, e.g. "left01.jpg + right01.jpg"
  //! \var left
  //! The left camera's image.
  vpImage<vpRGBa> left, right;        //!< the right camera's image, taken at the same time
};

//! The limits calibrateRig() applies to the pairs.
struct RigCalibrationParams
{
  int minPairs = 5;             //!< usable pairs needed, and usable views of each camera (at least 3)
  double maxEdgeWidthPx = 5.0;  //!< chessboard blur limit (px): mean width of the board's edges (estimateChessboardSharpness)
  void validate() const;        //!< throws pm::core::Error for a value out of range
};

//! One pair's fate and, when used, its residuals. Arrays of two: [0] the left camera, [1] the right one.
struct PairReport
{
  std::string name;             //!< the pair's StereoImagePair::name
  bool used = false;            //!< for the stereo pose (both views usable)
  bool usedBy[2] = {false, false}; //!< for each camera's intrinsics
  std::string reason;           //!< why it was not used for the stereo pose ("" when used)
  double edgeWidthPx[2] = {0, 0}; //!< chessboard: mean width of the board's edges in each image (px; 0 when not measured)
  double rmsPx[2] = {0, 0};     //!< reprojection rms of each camera in the stereo calibration (used pairs)
  std::vector<vpImagePoint> corners[2];   //!< detected (raw image)
  std::vector<vpImagePoint> projected[2]; //!< the board's corners reprojected by the calibration
};

/*!
  What calibrateRig() returns: the rig, its residuals (pixels), and what became of every pair.
  Arrays of two: [0] the left camera, [1] the right one.
*/
struct RigCalibration
{
  core::StereoRig rig;                  //!< intrinsics with distortion, poses hMc in the hand frame (metres)
  //! \var rmsLeftPx
  //! RMS reprojection error of cv::calibrateCamera for the left camera (px).
  double rmsLeftPx = 0, rmsRightPx = 0; //!< the same for the right camera (px)
  double rmsStereoPx = 0;         //!< cv::stereoCalibrate (both cameras' corners)
  double baselineMm = 0;          //!< |T| in the board's unit
  double rotationDeg = 0;         //!< angle between the two cameras
  int pairsUsed = 0;              //!< for the stereo pose
  int viewsUsed[2] = {0, 0};      //!< for each camera's intrinsics
  bool k3Fixed[2] = {false, false}; //!< k3 held at 0: the five-coefficient model folded the image (too few views at its edges)
  std::vector<PairReport> pairs;  //!< every pair given, in order
};

/*!
  Calibrates the rig from \e pairs of images of \e board (see RigCalibration.h). Throws pm::core::Error
  for an invalid board or parameters, an empty list, or fewer than params.minPairs usable pairs
  or views of a camera (the message lists the rejected pairs and why).

  \code
#include <iostream>

#include "pm/calib/RigCalibration.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"

int main()
{
  std::vector<pm::calib::StereoImagePair> pairs;
  for (int k = 1; k <= 15; ++k) {
    const std::string n = std::to_string(k);
    pm::calib::StereoImagePair p;
    p.name = "left" + n + ".jpg + right" + n + ".jpg";
    p.left = pm::io::readColorImage("left" + n + ".jpg");
    p.right = pm::io::readColorImage("right" + n + ".jpg");
    pairs.push_back(p);
  }
  pm::calib::ChessBoard board;
  board.innerRows = 6;
  board.innerCols = 9;
  board.squareMm = 25;
  const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, board);
  std::cout << c.pairsUsed << " pairs, baseline " << c.baselineMm << " mm, stereo rms " << c.rmsStereoPx << " px"
            << std::endl;
  pm::io::saveRig(c.rig, "rig.json", "rig_cameras.xml", "calibrated from 15 pairs");
}
  \endcode
*/
RigCalibration calibrateRig(const std::vector<StereoImagePair> &pairs, const Pattern &board,
                            const RigCalibrationParams &params = RigCalibrationParams());

/*!
  The hand frame of a rig whose right camera sits at cLMcR in the left one: origin midway between
  the optical centres, axes halfway between the cameras' (theta-u halved). Returns hMcL, hMcR.
*/
void handFrameOf(const vpHomogeneousMatrix &cLMcR, vpHomogeneousMatrix &hMcL, vpHomogeneousMatrix &hMcR);

//! A picture of where the corners fell in each camera, with the residuals as arrows (x \e gain), side by side.
vpImage<vpRGBa> coverageImage(const RigCalibration &c, double gain = 20);

} // namespace pm::calib
