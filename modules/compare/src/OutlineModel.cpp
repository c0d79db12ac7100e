#include "pm/compare/OutlineModel.h"

#include <array>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include <opencv2/imgproc.hpp>
#include <visp3/core/vpMeterPixelConversion.h>

#include "pm/core/Error.h"

namespace pm::compare {

std::vector<vpPoint> outlinePolygon(const vpImage<unsigned char> &region, const core::PhotoModel &model, double tolerancePx)
{
  if (region.getSize() == 0)
    throw core::Error("outline: the photo-model's region is empty");
  const cv::Mat mask(static_cast<int>(region.getHeight()), static_cast<int>(region.getWidth()), CV_8UC1,
                     const_cast<unsigned char *>(region.bitmap));
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  if (contours.empty())
    throw core::Error("outline: the photo-model's region is empty");
  const auto largest = std::max_element(contours.begin(), contours.end(), [](const auto &a, const auto &b) {
    return cv::contourArea(a) < cv::contourArea(b);
  });
  std::vector<cv::Point> poly;
  cv::approxPolyDP(*largest, poly, tolerancePx, true);
  if (poly.size() < 3)
    throw core::Error("outline: the photo-model's region has no area");
  // Image y points down: a contour that turns clockwise on the screen has a positive signed area
  // here. ViSP wants the vertices counter-clockwise as the camera sees them.
  if (cv::contourArea(poly, true) > 0)
    std::reverse(poly.begin(), poly.end());
  std::vector<vpPoint> out;
  const double d = model.distanceMm * 1e-3;
  for (const cv::Point &p : poly)
    out.emplace_back((p.x - model.centroidU) * d / model.px, (p.y - model.centroidV) * d / model.py, 0.0);
  return out;
}

std::string caoText(const std::vector<std::array<double, 3>> &pointsM, const std::vector<std::vector<std::size_t>> &faces,
                    const std::string &comment)
{
  std::ostringstream s;
  s << "V1\n# " << comment << "\n# 3D points\n" << pointsM.size() << "\n";
  char buf[96];
  for (const std::array<double, 3> &p : pointsM) {
    std::snprintf(buf, sizeof buf, "%.6f %.6f %.6f\n", p[0], p[1], p[2]);
    s << buf;
  }
  s << "# 3D lines\n0\n# Faces from 3D lines\n0\n# Faces from 3D points\n" << faces.size() << "\n";
  for (const std::vector<std::size_t> &f : faces) {
    s << f.size();
    for (std::size_t i : f)
      s << " " << i;
    s << "\n";
  }
  s << "# 3D cylinders\n0\n# 3D circles\n0\n";
  return s.str();
}

std::string caoText(const std::vector<vpPoint> &polygon, const std::string &comment)
{
  std::vector<std::array<double, 3>> pts;
  std::vector<std::vector<std::size_t>> faces(1);
  for (const vpPoint &p : polygon) {
    faces[0].push_back(pts.size());
    pts.push_back({p.get_oX(), p.get_oY(), p.get_oZ()});
  }
  return caoText(pts, faces, comment);
}

std::vector<std::pair<double, double>> projectPolygon(const std::vector<vpPoint> &polygon, const vpHomogeneousMatrix &cMm,
                                                      const vpCameraParameters &cam)
{
  std::vector<std::pair<double, double>> out;
  for (vpPoint p : polygon) {
    p.track(cMm);
    double u = 0, v = 0;
    vpMeterPixelConversion::convertPoint(cam, p.get_x(), p.get_y(), u, v);
    out.emplace_back(v, u);
  }
  return out;
}

} // namespace pm::compare
