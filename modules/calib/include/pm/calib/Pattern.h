#pragma once
/*!
  \file Pattern.h
  A calibration pattern of known layout (an AprilTag board, a chessboard): it can be drawn, and
  found in an image, which gives its pose in the camera. Every pattern's frame has its origin at
  the pattern's centre, x right, y down, z into the board (as a camera looking at it).
*/
#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/core/vpPoint.h>
#include <visp3/core/vpRGBa.h>
#include "pm/core/LensDistortion.h"

namespace pm::calib {

//! The pattern seen by one camera.
struct BoardView
{
  vpHomogeneousMatrix cMb;              //!< pattern pose in the camera frame
  int features = 0;                     //!< tags (AprilTag board) or corners (chessboard) found
  double reprojectionRmsPx = 0;         //!< of the matched corners at cMb
  std::vector<vpImagePoint> corners;    //!< detected corners, for drawing
};

//! A pattern's features found in an image, without a camera model (what a calibration starts from).
struct PatternDetection
{
  std::vector<int> ids;             //!< each feature's number on the board (chessboard: corner r * cols + c; tags: 4 id + corner)
  std::vector<vpImagePoint> pixels; //!< where it was found
  std::vector<vpPoint> points;      //!< where it is on the board (metres, oX, oY, 0)
};

/*!
  A calibration pattern (see Pattern.h): its layout, its printed image, and finding it in an image.
  Implemented by TagBoard and ChessBoard; calibrateRig() takes either. Lengths of the layout
  are in mm, points on the board in metres.
*/
class Pattern
{
public:
  virtual ~Pattern() = default;
  //! One line for people, e.g. "3x3 AprilTag 36h11 board, 40 mm tags".
  virtual std::string describe() const = 0;
  //! Throws pm::core::Error for a layout that cannot be used.
  virtual void validate() const = 0;
  //! Width of the printed pattern, white margin included (mm).
  virtual double widthMm() const = 0;
  //! Height of the printed pattern, white margin included (mm).
  virtual double heightMm() const = 0;
  //! The printed pattern at \e pixelsPerMm, white margin included.
  virtual vpImage<vpRGBa> render(double pixelsPerMm) const = 0;
  /*!
    Finds the pattern in \e I seen by a camera of intrinsics \e cam. Throws pm::core::Error naming the
    image (\e name) when it is not found, or when \e whole is set and part of it is missing.
  */
  virtual BoardView find(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const std::string &name,
                         bool whole = false) const = 0;
  /*!
    The same in the raw image of a camera whose lens has \e distortion (cam: its pinhole part); the
    view's corners are raw pixels, its reprojection RMS in ideal pixels. Without distortion, the
    call above. This default undistorts the image (UndistortMap) and finds the pattern in it.
  */
  virtual BoardView find(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const core::LensDistortion &distortion,
                         const std::string &name, bool whole = false) const;
  /*!
    The pattern's features in \e I, numbered and placed on the board, with no camera model.
    Throws pm::core::Error naming the image (\e name) when too little of it is found (a chessboard: not
    whole; tags: fewer than the board's minimum).
  */
  virtual PatternDetection detect(const vpImage<vpRGBa> &I, const std::string &name) const = 0;
  //! True for a chessboard, whose edges tell how sharp a view is (cv::estimateChessboardSharpness).
  virtual bool isChessboard() const { return false; }
};

//! Pattern points (oX, oY, oZ, metres) matched with the pixels where they were found.
struct CornerMatches
{
  std::vector<vpPoint> points;      //!< with their measured normalized coordinates (x, y)
  std::vector<vpImagePoint> pixels; //!< the pixels they were found at, in the same order
  //! Appends \e model with the normalized coordinates (x, y) of pixel \e ip through \e cam (no distortion), and \e ip.
  void add(vpPoint model, const vpImagePoint &ip, const vpCameraParameters &cam);
};

/*!
  The pattern's pose from its matched corners: vpPose (Dementhon then virtual visual servoing)
  gives cMb; the reprojection RMS is in pixels of \e cam; the pixels become the view's corners.
  Throws pm::core::Error with fewer than 4 matches.
*/
void solveBoardPose(const CornerMatches &matches, const vpCameraParameters &cam, BoardView &view);

} // namespace pm::calib
