#pragma once
/*!
  \file TagBoard.h
  A board of AprilTags (family 36h11, drawn with libapriltag) of known layout: rows x cols tags,
  ids from \e firstId row by row, each tag's black square \e tagSizeMm wide, centres \e pitchMm
  apart. The board frame has its origin at the board's centre, x right, y down, z into the board
  (like a camera looking at it), which is the frame ViSP's detector gives a tag with
  setZAlignedWithCameraAxis(true). A single tag (1 x 1) is a board too.

  Finding it: ViSP's vpDetectorAprilTag (36h11) finds the tags; each detected corner is matched
  with the board corner that the tag's own pose projects nearest, and one vpPose over all the
  matched corners gives the board's pose.
*/
#include <array>

#include "pm/calib/Pattern.h"

namespace pm::calib {

struct TagBoard : Pattern
{
  int rows = 3, cols = 3, firstId = 0;
  double tagSizeMm = 40, pitchMm = 55, marginMm = 10;
  //! Tags needed for a pose unless the whole board is asked for (at most rows x cols).
  int minTags = 2;

  std::string describe() const override;
  //! Throws pm::Error for a layout whose tags overlap or have no size.
  void validate() const override;
  double widthMm() const override { return cols * pitchMm + 2 * marginMm; }
  double heightMm() const override { return rows * pitchMm + 2 * marginMm; }
  bool hasId(int id) const { return id >= firstId && id < firstId + rows * cols; }
  //! The 4 corners of tag \e id in the board frame (metres), in the order of the tag frame's
  //! (-x,-y), (+x,-y), (+x,+y), (-x,+y).
  std::array<vpPoint, 4> corners(int id) const;
  //! Centre of tag \e id in the board frame (metres).
  vpPoint centre(int id) const;
  //! The printed board at \e pixelsPerMm (white background).
  vpImage<vpRGBa> render(double pixelsPerMm) const override;
  //! Throws pm::Error if fewer than minTags (all with \e whole) of its tags are found.
  BoardView find(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const std::string &name,
                 bool whole = false) const override;
  using Pattern::find; // the raw image of a lens with distortion: undistorted first
  /*!
    Each tag found (of this board's ids) gives its 4 corners, numbered 4 id + k with k the tag
    frame's corner (see corners()): vpDetectorAprilTag lists a tag's corners in the reverse of that order.
  */
  PatternDetection detect(const vpImage<vpRGBa> &I, const std::string &name) const override;
};

} // namespace pm::calib
