#include "pm/report/PlotUtil.h"

#include <cmath>
#include <cstdio>

#include <opencv2/imgproc.hpp>

namespace pm::report {

std::string tickLabel(double v)
{
  char b[32];
  if (std::fabs(v) >= 100 || v == std::floor(v))
    std::snprintf(b, sizeof b, "%.0f", v);
  else if (std::fabs(v) >= 0.1)
    std::snprintf(b, sizeof b, "%.2f", v);
  else // small ticks keep their digits (0.005, not 0.00)
    std::snprintf(b, sizeof b, "%.2g", v);
  return b;
}

std::vector<double> niceTicks(double a, double b, int n)
{
  const double span = b - a;
  if (!(span > 0))
    return {a};
  const double raw = span / n, mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  std::vector<double> t;
  for (double v = std::ceil(a / step - 1e-9) * step; v <= b + 1e-9 * span; v += step)
    t.push_back(std::fabs(v) < 1e-12 * span ? 0.0 : v);
  return t;
}

void putLabel(cv::Mat &m, const std::string &s, cv::Point p, double scale, int align, cv::Scalar color)
{
  int base = 0;
  const cv::Size sz = cv::getTextSize(s, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &base);
  if (align == 1)
    p.x -= sz.width / 2;
  else if (align == 2)
    p.x -= sz.width;
  cv::putText(m, s, p, cv::FONT_HERSHEY_SIMPLEX, scale, color, 1, cv::LINE_AA);
}

vpImage<vpRGBa> toVisp(const cv::Mat &img)
{
  vpImage<vpRGBa> out(static_cast<unsigned>(img.rows), static_cast<unsigned>(img.cols));
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const cv::Vec3b &b = img.at<cv::Vec3b>(y, x);
      out[static_cast<unsigned>(y)][static_cast<unsigned>(x)] = vpRGBa(b[2], b[1], b[0]);
    }
  return out;
}

} // namespace pm::report
