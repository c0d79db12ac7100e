#include "pm/report/HeatMap.h"
#include "pm/report/PlotUtil.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <opencv2/imgproc.hpp>

namespace pm::report {


vpImage<vpRGBa> drawHeatMap(const Grid2D &g, const std::string &title, const std::vector<Marker> &markers)
{
  const int plot = 480, left = 70, top = 40, barW = 18, right = 90, bottom = 62;
  const int W = left + plot + 20 + barW + right, H = top + plot + bottom;
  cv::Mat img(H, W, CV_8UC3, cv::Scalar(255, 255, 255));
  double lo = *std::min_element(g.values.begin(), g.values.end());
  double hi = *std::max_element(g.values.begin(), g.values.end());
  if (hi <= lo)
    hi = lo + 1;
  // The map, y growing upward.
  cv::Mat gray(g.ny, g.nx, CV_8U);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      gray.at<unsigned char>(g.ny - 1 - j, i) = static_cast<unsigned char>(std::lround(255 * (g.at(i, j) - lo) / (hi - lo)));
  cv::Mat colored, scaled;
  cv::applyColorMap(gray, colored, cv::COLORMAP_VIRIDIS);
  cv::resize(colored, scaled, cv::Size(plot, plot), 0, 0, cv::INTER_NEAREST);
  scaled.copyTo(img(cv::Rect(left, top, plot, plot)));
  cv::rectangle(img, cv::Rect(left - 1, top - 1, plot + 2, plot + 2), cv::Scalar(0, 0, 0));
  const double xMin = g.x0 - g.dx / 2, xMax = g.x0 + (g.nx - 0.5) * g.dx;
  const double yMin = g.y0 - g.dy / 2, yMax = g.y0 + (g.ny - 0.5) * g.dy;
  auto px = [&](double x) { return left + static_cast<int>(std::lround((x - xMin) / (xMax - xMin) * plot)); };
  auto py = [&](double y) { return top + plot - static_cast<int>(std::lround((y - yMin) / (yMax - yMin) * plot)); };
  for (double t : niceTicks(xMin, xMax)) {
    cv::line(img, {px(t), top + plot}, {px(t), top + plot + 5}, cv::Scalar(0, 0, 0));
    putLabel(img, tickLabel(t), {px(t), top + plot + 20}, 0.42, 1);
  }
  for (double t : niceTicks(yMin, yMax)) {
    cv::line(img, {left - 5, py(t)}, {left, py(t)}, cv::Scalar(0, 0, 0));
    putLabel(img, tickLabel(t), {left - 8, py(t) + 5}, 0.42, 2);
  }
  putLabel(img, g.xName, {left + plot / 2, H - 12}, 0.5, 1);
  cv::Mat ylabel(24, 200, CV_8UC3, cv::Scalar(255, 255, 255));
  putLabel(ylabel, g.yName, {100, 17}, 0.5, 1);
  cv::Mat yrot;
  cv::rotate(ylabel, yrot, cv::ROTATE_90_COUNTERCLOCKWISE);
  yrot.copyTo(img(cv::Rect(4, top + plot / 2 - 100, 24, 200)));
  putLabel(img, title, {left + plot / 2, 25}, 0.55, 1);
  // Colour bar.
  const int bx = left + plot + 20;
  for (int y = 0; y < plot; ++y) {
    cv::Mat c(1, 1, CV_8U, cv::Scalar(255 - y * 255 / (plot - 1))), cc;
    cv::applyColorMap(c, cc, cv::COLORMAP_VIRIDIS);
    cv::line(img, {bx, top + y}, {bx + barW, top + y}, cv::Scalar(cc.at<cv::Vec3b>(0, 0)));
  }
  cv::rectangle(img, cv::Rect(bx - 1, top - 1, barW + 2, plot + 2), cv::Scalar(0, 0, 0));
  for (double t : niceTicks(lo, hi)) {
    const int y = top + plot - static_cast<int>(std::lround((t - lo) / (hi - lo) * plot));
    cv::line(img, {bx + barW, y}, {bx + barW + 4, y}, cv::Scalar(0, 0, 0));
    putLabel(img, tickLabel(t), {bx + barW + 7, y + 5}, 0.42);
  }
  putLabel(img, "F", {bx + barW / 2, top - 8}, 0.5, 1);
  // Markers, and their legend under the colour bar.
  int ly = top + plot + 22;
  for (const auto &m : markers) {
    const cv::Scalar c(m.color.B, m.color.G, m.color.R);
    auto mark = [&](cv::Point p, int size) {
      if (m.cross) {
        cv::drawMarker(img, p, cv::Scalar(255, 255, 255), cv::MARKER_CROSS, size + 2, 4);
        cv::drawMarker(img, p, c, cv::MARKER_CROSS, size, 2);
      } else {
        cv::circle(img, p, size / 2, cv::Scalar(255, 255, 255), 3, cv::LINE_AA);
        cv::circle(img, p, size / 2, c, 2, cv::LINE_AA);
      }
    };
    mark({px(m.x), py(m.y)}, 20);
    cv::rectangle(img, cv::Rect(bx - 4, ly - 10, 14, 14), cv::Scalar(128, 128, 128), cv::FILLED);
    mark({bx + 3, ly - 3}, 10);
    putLabel(img, m.label, {bx + 16, ly + 2}, 0.42);
    ly += 18;
  }
  return toVisp(img);
}

} // namespace pm::report
