#pragma once
/*!
  \file ChessBoard.h
  A chessboard of \e innerRows x \e innerCols inner corners (squares \e squareMm wide), the
  pattern most labs already own. Its frame: origin at the centre of the inner corners, x along
  a row, y down the columns, z into the board; the top-left square is black.

  Finding it: OpenCV's findChessboardCorners and cornerSubPix, then one vpPose over all the
  inner corners. A chessboard looks the same turned by 180 degrees unless its squares are odd
  in one direction and even in the other; such a board is required (one inner-corner count odd,
  the other even, e.g. the usual 6 x 9): OpenCV then starts its list of corners next to the
  black corner square, which fixes the board's frame.
*/
#include "pm/calib/Pattern.h"

namespace pm::calib {

/*!
  A chessboard pattern (see ChessBoard.h for its frame and why one inner-corner count must be
  odd and the other even). Print render(), then find the board's pose in a camera's raw image:

  \code
#include <iostream>

#include "pm/calib/ChessBoard.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"

int main()
{
  pm::calib::ChessBoard board; // 6 x 9 inner corners
  board.squareMm = 25;
  board.validate();
  pm::io::writeImage(board.render(10.0), "chessboard.png"); // 10 px per mm: print it at 254 dpi

  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const vpImage<vpRGBa> I = pm::io::readColorImage("left01.png");
  const pm::calib::BoardView view = board.find(I, rig.left.cam, rig.left.distortion, "left01.png");
  std::cout << "cMb:\n" << view.cMb << "\n" << view.reprojectionRmsPx << " px rms" << std::endl;
}
  \endcode
*/
struct ChessBoard : Pattern
{
  //! \var innerRows
  //! Inner corners down a column (the number of rows of corners).
  int innerRows = 6, innerCols = 9; //!< inner corners along a row (the number of columns of corners)
  double squareMm = 20; //!< side of a square (mm)
  double marginMm = 20; //!< white around the squares (the corner finder needs a light border)

  //! One line, e.g. "chessboard of 6x9 inner corners, 20 mm squares".
  std::string describe() const override;
  //! Throws pm::core::Error unless each side has 3 to 50 inner corners, one count odd and the other even,
  //! the squares a size and the margin no negative width.
  void validate() const override;
  double widthMm() const override { return (innerCols + 1) * squareMm + 2 * marginMm; }
  double heightMm() const override { return (innerRows + 1) * squareMm + 2 * marginMm; }
  //! Inner corner (\e r, \e c) in the board frame (metres).
  vpPoint corner(int r, int c) const;
  vpImage<vpRGBa> render(double pixelsPerMm) const override;
  //! Throws pm::core::Error unless all the inner corners are found (\e whole changes nothing).
  BoardView find(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const std::string &name,
                 bool whole = false) const override;
  //! Finds the corners in the raw image and undistorts them before the pose (more exact than undistorting the image).
  BoardView find(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const core::LensDistortion &distortion,
                 const std::string &name, bool whole = false) const override;
  /*!
    The inner corners found in \e I (row by row, the first next to the black corner square),
    refined to sub-pixel. Throws pm::core::Error naming \e name unless all are found.
  */
  std::vector<vpImagePoint> findCorners(const vpImage<vpRGBa> &I, const std::string &name) const;
  PatternDetection detect(const vpImage<vpRGBa> &I, const std::string &name) const override;
  bool isChessboard() const override { return true; }
};

} // namespace pm::calib
