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

struct ChessBoard : Pattern
{
  int innerRows = 6, innerCols = 9;
  double squareMm = 20;
  double marginMm = 20; //!< white around the squares (the corner finder needs a light border)

  std::string describe() const override;
  //! Throws pm::Error for fewer than 3 inner corners a side, or both counts of the same parity.
  void validate() const override;
  double widthMm() const override { return (innerCols + 1) * squareMm + 2 * marginMm; }
  double heightMm() const override { return (innerRows + 1) * squareMm + 2 * marginMm; }
  //! Inner corner (\e r, \e c) in the board frame (metres).
  vpPoint corner(int r, int c) const;
  vpImage<vpRGBa> render(double pixelsPerMm) const override;
  //! Throws pm::Error unless all the inner corners are found (\e whole changes nothing).
  BoardView find(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const std::string &name,
                 bool whole = false) const override;
  //! Finds the corners in the raw image and undistorts them before the pose (more exact than undistorting the image).
  BoardView find(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const LensDistortion &distortion,
                 const std::string &name, bool whole = false) const override;
  /*!
    The inner corners found in \e I (row by row, the first next to the black corner square),
    refined to sub-pixel. Throws pm::Error naming \e name unless all are found.
  */
  std::vector<vpImagePoint> findCorners(const vpImage<vpRGBa> &I, const std::string &name) const;
  PatternDetection detect(const vpImage<vpRGBa> &I, const std::string &name) const override;
  bool isChessboard() const override { return true; }
};

} // namespace pm::calib
