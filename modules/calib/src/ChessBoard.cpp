#include "pm/calib/ChessBoard.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <visp3/core/vpImageConvert.h>

#include "pm/core/Error.h"

namespace pm::calib {

std::string ChessBoard::describe() const
{
  char buf[160];
  std::snprintf(buf, sizeof buf, "chessboard of %dx%d inner corners, %g mm squares", innerRows, innerCols, squareMm);
  return buf;
}

void ChessBoard::validate() const
{
  if (innerRows < 3 || innerCols < 3 || innerRows > 50 || innerCols > 50)
    throw core::Error("chessboard: 3 to 50 inner corners a side");
  if ((innerRows + innerCols) % 2 == 0)
    throw core::Error("chessboard: " + std::to_string(innerRows) + "x" + std::to_string(innerCols) +
                " inner corners look the same turned by 180 degrees; one count must be odd and the other even (e.g. 6x9)");
  if (!(squareMm > 0) || !(marginMm >= 0))
    throw core::Error("chessboard: the squares need a size and the margin cannot be negative");
}

vpPoint ChessBoard::corner(int r, int c) const
{
  return vpPoint((c - (innerCols - 1) / 2.0) * squareMm * 1e-3, (r - (innerRows - 1) / 2.0) * squareMm * 1e-3, 0);
}

vpImage<vpRGBa> ChessBoard::render(double pixelsPerMm) const
{
  validate();
  const unsigned w = static_cast<unsigned>(std::lround(widthMm() * pixelsPerMm));
  const unsigned h = static_cast<unsigned>(std::lround(heightMm() * pixelsPerMm));
  vpImage<vpRGBa> img(h, w, vpRGBa(255, 255, 255));
  for (unsigned v = 0; v < h; ++v)
    for (unsigned u = 0; u < w; ++u) {
      const double x = (u + 0.5) / pixelsPerMm - marginMm, y = (v + 0.5) / pixelsPerMm - marginMm; // from the squares' corner
      const double c = std::floor(x / squareMm), r = std::floor(y / squareMm);
      if (c >= 0 && r >= 0 && c <= innerCols && r <= innerRows && static_cast<long>(r + c) % 2 == 0)
        img[v][u] = vpRGBa(0, 0, 0, 255);
    }
  return img;
}

std::vector<vpImagePoint> ChessBoard::findCorners(const vpImage<vpRGBa> &I, const std::string &name) const
{
  validate();
  vpImage<unsigned char> grey;
  vpImageConvert::convert(I, grey);
  const cv::Mat g(static_cast<int>(grey.getHeight()), static_cast<int>(grey.getWidth()), CV_8UC1, grey.bitmap);
  std::vector<cv::Point2f> pts;
  const bool found = cv::findChessboardCorners(g, cv::Size(innerCols, innerRows), pts,
                                               cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE);
  if (!found || pts.size() != static_cast<std::size_t>(innerRows * innerCols))
    throw core::Error("chessboard: its " + std::to_string(innerRows) + "x" + std::to_string(innerCols) +
                " inner corners were not all found in the " + name + " image (is the whole board in view, sharp, and the size right?)");
  // Sub-pixel refinement in a window of about a third of a square.
  double spacing = 0;
  for (int r = 0; r < innerRows; ++r)
    for (int c = 0; c + 1 < innerCols; ++c)
      spacing += cv::norm(pts[static_cast<std::size_t>(r * innerCols + c + 1)] - pts[static_cast<std::size_t>(r * innerCols + c)]);
  spacing /= innerRows * (innerCols - 1);
  const int half = std::clamp(static_cast<int>(spacing / 3), 2, 11);
  cv::cornerSubPix(g, pts, cv::Size(half, half), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 40, 0.001));
  // OpenCV lists the corners row by row, starting next to the black corner square when the
  // board is not the same turned by 180 degrees (validate() requires that); the test
  // ChessBoard.PoseFoundWhicheverWayTheBoardIsTurned holds OpenCV to it.
  std::vector<vpImagePoint> out(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    out[i] = vpImagePoint(pts[i].y, pts[i].x);
  return out;
}

PatternDetection ChessBoard::detect(const vpImage<vpRGBa> &I, const std::string &name) const
{
  PatternDetection d;
  d.pixels = findCorners(I, name);
  for (int r = 0; r < innerRows; ++r)
    for (int c = 0; c < innerCols; ++c) {
      d.ids.push_back(r * innerCols + c);
      d.points.push_back(corner(r, c));
    }
  return d;
}

BoardView ChessBoard::find(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const std::string &name, bool whole) const
{
  return find(I, cam, core::LensDistortion(), name, whole);
}

BoardView ChessBoard::find(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const core::LensDistortion &distortion,
                           const std::string &name, bool) const
{
  const std::vector<vpImagePoint> raw = findCorners(I, name);
  const std::vector<vpImagePoint> ideal = distortion.undistort(cam, raw);
  CornerMatches matches;
  for (int r = 0; r < innerRows; ++r)
    for (int c = 0; c < innerCols; ++c)
      matches.add(corner(r, c), ideal[static_cast<std::size_t>(r * innerCols + c)], cam);
  BoardView view;
  view.features = static_cast<int>(matches.points.size());
  solveBoardPose(matches, cam, view);
  view.corners = raw;
  return view;
}

} // namespace pm::calib
