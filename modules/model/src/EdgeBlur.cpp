#include "pm/model/EdgeBlur.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"
#include "pm/model/BilinearColour.h"

namespace pm::model {

namespace {


//! Where \e share first rises through \e level from index 0 (fractional index); -1 when it does not.
double crossing(const std::vector<double> &share, double level)
{
  for (std::size_t i = 1; i < share.size(); ++i)
    if (share[i - 1] < level && share[i] >= level)
      return static_cast<double>(i - 1) + (level - share[i - 1]) / (share[i] - share[i - 1]);
  return -1;
}

constexpr double kReachPx = 3.5; //!< where the pure colours are read, either side of the outline
constexpr double kStepPx = 0.125;

//! The 25-75 % rise at border point (\e x, \e y) with inward normal (\e nx, \e ny); < 0 when not read.
double riseAt(const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> *background, double x, double y, double nx, double ny, double minContrast)
{
  // Both ends on the image (each with a pixel to its right and below), so is every reading between.
  const double w = photo.getWidth(), h = photo.getHeight();
  for (double s : {-kReachPx, kReachPx}) {
    const double u = x + s * nx, v = y + s * ny;
    if (!(u >= 0 && v >= 0 && u < w - 1 && v < h - 1))
      return -1;
  }
  const std::array<double, 3> target = bilinearColour(photo, x + kReachPx * nx, y + kReachPx * ny),
                              outside = bilinearColour(photo, x - kReachPx * nx, y - kReachPx * ny);
  std::vector<double> share;
  for (double t = -kReachPx; t <= kReachPx + 1e-9; t += kStepPx) {
    const std::array<double, 3> c = bilinearColour(photo, x + t * nx, y + t * ny);
    const std::array<double, 3> b = background ? bilinearColour(*background, x + t * nx, y + t * ny) : outside;
    double d[3], n2 = 0, dot = 0;
    for (int k = 0; k < 3; ++k) {
      d[k] = target[k] - b[k];
      n2 += d[k] * d[k];
      dot += (c[k] - b[k]) * d[k];
    }
    if (n2 < minContrast * minContrast)
      return -1;
    share.push_back(dot / n2);
  }
  const double a = crossing(share, 0.25), b = crossing(share, 0.75);
  return a < 0 || b < a ? -1 : (b - a) * kStepPx;
}

} // namespace

EdgeWidth edgeWidth(const vpImage<unsigned char> &mask, const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> *background,
                    std::size_t maxSamples, double minContrast)
{
  if (photo.getWidth() != mask.getWidth() || photo.getHeight() != mask.getHeight() ||
      (background && (background->getWidth() != mask.getWidth() || background->getHeight() != mask.getHeight())))
    throw core::Error("edge width: the mask, the photo and the background must be of one size");
  EdgeWidth out;
  const int w = static_cast<int>(mask.getWidth()), h = static_cast<int>(mask.getHeight());
  if (w < 3 || h < 3 || maxSamples == 0)
    return out;
  // The outline's inward normal: the gradient of the mask smoothed over a few pixels.
  cv::Mat m(h, w, CV_32F), gx, gy;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      m.at<float>(y, x) = mask[y][x] ? 1.f : 0.f;
  cv::GaussianBlur(m, m, cv::Size(0, 0), 2.0);
  cv::Sobel(m, gx, CV_32F, 1, 0);
  cv::Sobel(m, gy, CV_32F, 0, 1);
  std::vector<cv::Point> border;
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x)
      if (mask[y][x] && (!mask[y - 1][x] || !mask[y + 1][x] || !mask[y][x - 1] || !mask[y][x + 1]))
        border.emplace_back(x, y);
  if (border.empty())
    return out;
  const std::size_t stride = std::max<std::size_t>(1, border.size() / maxSamples);
  std::vector<double> widths;
  for (std::size_t i = 0; i < border.size(); i += stride) {
    const cv::Point &p = border[i];
    const double nx = gx.at<float>(p), ny = gy.at<float>(p), n = std::hypot(nx, ny);
    if (!(n > 1e-6))
      continue;
    const double r = riseAt(photo, background, p.x, p.y, nx / n, ny / n, minContrast);
    if (r >= 0)
      widths.push_back(r);
  }
  out.samples = widths.size();
  if (!widths.empty()) {
    std::nth_element(widths.begin(), widths.begin() + static_cast<long>(widths.size() / 2), widths.end());
    out.widthPx = widths[widths.size() / 2];
  }
  return out;
}

} // namespace pm::model
