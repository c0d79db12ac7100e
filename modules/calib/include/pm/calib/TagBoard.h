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

/*!
  A board of AprilTags 36h11 (see TagBoard.h for its layout and frame). Print render(), then find
  the board's pose in an image; a board seen in part is found as long as minTags of its tags are:

  \code
#include <iostream>

#include "pm/calib/TagBoard.h"
#include "pm/io/ImageFile.h"

int main()
{
  pm::calib::TagBoard board;
  board.rows = 4;
  board.cols = 6;
  board.tagSizeMm = 30;
  board.pitchMm = 40; // at least 1.25 x tagSizeMm
  board.validate();
  std::cout << board.describe() << std::endl;
  pm::io::writeImage(board.render(10.0), "tags.png"); // 10 px per mm: print it at 254 dpi

  const vpCameraParameters cam(800, 800, 320, 240); // px, py, u0, v0 of a pinhole camera
  const pm::calib::BoardView view = board.find(pm::io::readColorImage("photo.png"), cam, "photo.png");
  std::cout << view.features << " tags, cMb:\n" << view.cMb << std::endl;
}
  \endcode
*/
struct TagBoard : Pattern
{
  //! \var rows
  //! Rows of tags.
  //! \var cols
  //! Columns of tags.
  int rows = 3, cols = 3, firstId = 0; //!< id of the top-left tag; the others follow row by row (36h11 ids 0 to 586)
  //! \var tagSizeMm
  //! Side of a tag's black square (mm).
  //! \var pitchMm
  //! Distance between neighbouring tags' centres (mm), at least 1.25 x tagSizeMm (the tags' white borders).
  double tagSizeMm = 40, pitchMm = 55, marginMm = 10; //!< white around the tags' pitch cells (mm)
  //! Tags needed for a pose unless the whole board is asked for (at most rows x cols).
  int minTags = 2;

  //! One line, e.g. "3x3 AprilTag 36h11 board (ids 0..8), 40 mm tags, 55 mm apart".
  std::string describe() const override;
  //! Throws pm::core::Error for a layout whose tags overlap or have no size (pitch under 1.25 x tag size),
  //! over 100 tags, ids outside 36h11's 0..586, a negative margin, or minTags under 1.
  void validate() const override;
  double widthMm() const override { return cols * pitchMm + 2 * marginMm; }
  double heightMm() const override { return rows * pitchMm + 2 * marginMm; }
  //! True if tag \e id belongs to this board (firstId to firstId + rows x cols - 1).
  bool hasId(int id) const { return id >= firstId && id < firstId + rows * cols; }
  //! The 4 corners of tag \e id in the board frame (metres), in the order of the tag frame's
  //! (-x,-y), (+x,-y), (+x,+y), (-x,+y).
  std::array<vpPoint, 4> corners(int id) const;
  //! Centre of tag \e id in the board frame (metres).
  vpPoint centre(int id) const;
  //! The printed board at \e pixelsPerMm (white background).
  vpImage<vpRGBa> render(double pixelsPerMm) const override;
  //! Throws pm::core::Error if fewer than minTags (all with \e whole) of its tags are found.
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
