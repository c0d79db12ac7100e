#pragma once
/*!
  \file TagBoard.h
  A board of AprilTags (family 36h11, drawn with libapriltag) of known layout: rows x cols tags,
  ids from \e firstId row by row, each tag's black square \e tagSizeMm wide, centres \e pitchMm
  apart. The board frame has its origin at the board's centre, x right, y down, z into the board
  (like a camera looking at it), which is the frame ViSP's detector gives a tag with
  setZAlignedWithCameraAxis(true).
*/
#include <array>
#include <map>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpPoint.h>
#include <visp3/core/vpRGBa.h>

namespace pm::calib {

struct TagBoard
{
  int rows = 3, cols = 3, firstId = 0;
  double tagSizeMm = 40, pitchMm = 55, marginMm = 10;

  //! Throws pm::Error for a layout whose tags overlap or have no size.
  void validate() const;
  double widthMm() const { return cols * pitchMm + 2 * marginMm; }
  double heightMm() const { return rows * pitchMm + 2 * marginMm; }
  bool hasId(int id) const { return id >= firstId && id < firstId + rows * cols; }
  //! The 4 corners of tag \e id in the board frame (metres), in the order of the tag frame's
  //! (-x,-y), (+x,-y), (+x,+y), (-x,+y).
  std::array<vpPoint, 4> corners(int id) const;
  //! Centre of tag \e id in the board frame (metres).
  vpPoint centre(int id) const;
  //! The printed board at \e pixelsPerMm (white background).
  vpImage<vpRGBa> render(double pixelsPerMm) const;
};

} // namespace pm::calib
