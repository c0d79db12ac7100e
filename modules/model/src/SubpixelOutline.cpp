#include "pm/model/SubpixelOutline.h"
#include "pm/model/BilinearColour.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"
#include "pm/model/HullGeometry.h"

namespace pm::model::hull {
namespace {

using Rgb = std::array<double, 3>;

Rgb colourAt(const vpImage<vpRGBa> &im, double u, double v) { return bilinearColour(im, u, v); }

double dot3(const Rgb &a, const Rgb &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Rgb minus3(const Rgb &a, const Rgb &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

//! \e c without its component along the unit colour \e along.
Rgb across(const Rgb &c, const Rgb &along)
{
  const double k = dot3(c, along);
  return {c[0] - k * along[0], c[1] - k * along[1], c[2] - k * along[2]};
}

//! The share of target colour \e t in \e pixel over background \e b; < 0 when the colours are too close to tell.
double targetShare(const Rgb &pixel, const Rgb &t, const Rgb &b)
{
  constexpr double kMinContrast = 12.0; // grey levels: below, the sensor's noise would decide
  const double nb = std::sqrt(dot3(b, b));
  if (nb > kMinContrast) {
    // Across the background's colour: a shadow (the background scaled) has none of it.
    const Rgb bh{b[0] / nb, b[1] / nb, b[2] / nb};
    const Rgb tp = across(t, bh), pp = across(pixel, bh);
    const double tt = dot3(tp, tp);
    if (tt > kMinContrast * kMinContrast)
      return std::clamp(dot3(pp, tp) / tt, 0.0, 1.0);
  }
  const Rgb tb = minus3(t, b);
  const double tt = dot3(tb, tb);
  if (tt > kMinContrast * kMinContrast)
    return std::clamp(dot3(minus3(pixel, b), tb) / tt, 0.0, 1.0);
  return -1;
}

} // namespace

double edgeDistanceFromCoverage(double alpha, double nx, double ny)
{
  const double n = std::hypot(nx, ny);
  if (!(n > 0))
    return std::clamp(alpha, 0.0, 1.0) - 0.5; // no direction: as if across a column
  double gx = std::fabs(nx) / n, gy = std::fabs(ny) / n;
  if (gy > gx)
    std::swap(gx, gy);
  alpha = std::clamp(alpha, 0.0, 1.0);
  if (gy < 1e-9)
    return alpha - 0.5;
  // The inside {x : n.x <= d} of the unit square centred on the pixel: a corner triangle while
  // alpha < gy / (2 gx), a band growing by 1 / gx per unit of d, then the other corner.
  const double a1 = gy / (2 * gx);
  if (alpha < a1)
    return std::sqrt(2 * gx * gy * alpha) - 0.5 * (gx + gy);
  if (alpha > 1 - a1)
    return 0.5 * (gx + gy) - std::sqrt(2 * gx * gy * (1 - alpha));
  return (alpha - 0.5) * gx;
}

cv::Mat subpixelSignedDistance(const vpImage<unsigned char> &mask, const vpImage<vpRGBa> &photo,
                               const vpImage<vpRGBa> *background)
{
  const cv::Mat binary = signedDistance(mask);
  const int h = binary.rows, w = binary.cols;
  if (photo.getWidth() != static_cast<unsigned>(w) || photo.getHeight() != static_cast<unsigned>(h) ||
      (background && (background->getWidth() != photo.getWidth() || background->getHeight() != photo.getHeight())))
    throw core::Error("sub-pixel outline: the mask, the photo and the background must have one size");
  cv::Mat gx, gy;
  cv::Sobel(binary, gx, CV_32F, 1, 0, 3);
  cv::Sobel(binary, gy, CV_32F, 0, 1, 3);
  // Away from the border the mask's distance, less the half pixel between its border pixels' centres and the border.
  cv::Mat out(h, w, CV_32F);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float s = binary.at<float>(y, x);
      out.at<float>(y, x) = s - (s > 0 ? 0.5f : -0.5f);
    }
  // The pixels next to the border: where the outline crosses each one that mixes the two colours.
  cv::Mat mixed(h, w, CV_32F, cv::Scalar(NAN));
  cv::Mat nOut(h, w, CV_32FC2, cv::Scalar(0, 0));
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      const float s = binary.at<float>(y, x);
      if (std::fabs(s) > 1.5f)
        continue;
      double nx = -gx.at<float>(y, x), ny = -gy.at<float>(y, x);
      const double nn = std::hypot(nx, ny);
      if (!(nn > 1e-6))
        continue;
      nx /= nn, ny /= nn;
      nOut.at<cv::Vec2f>(y, x) = cv::Vec2f(static_cast<float>(nx), static_cast<float>(ny));
      const double inside = s - (s > 0 ? 0.5 : -0.5); // about how far inside the outline the centre is
      const double ti = 1.5 - inside, bo = 2.0 + inside;
      const Rgb t1 = colourAt(photo, x - ti * nx, y - ti * ny), t2 = colourAt(photo, x - (ti + 1) * nx, y - (ti + 1) * ny);
      // Toward its outline a rounded target turns from the light: its colour at the outline is the
      // one inside darkened as much again as from two pixels in to one and a half.
      const double n1 = std::sqrt(dot3(t1, t1)), n2 = std::sqrt(dot3(t2, t2));
      const double k = n2 > 1 ? std::clamp(n1 / n2, 0.8, 1.25) : 1.0;
      const Rgb t{std::min(255.0, k * t1[0]), std::min(255.0, k * t1[1]), std::min(255.0, k * t1[2])};
      const Rgb b = background ? colourAt(*background, x, y) : colourAt(photo, x + bo * nx, y + bo * ny);
      const double a = targetShare(colourAt(photo, x, y), t, b);
      if (a > 0.02 && a < 0.98)
        mixed.at<float>(y, x) = static_cast<float>(edgeDistanceFromCoverage(a, nx, ny));
    }
  // Each pixel near the border placed from the mixed pixels around it (the outline through them, extended).
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      if (std::fabs(binary.at<float>(y, x)) > 2.5f)
        continue;
      const float own = mixed.at<float>(y, x);
      if (!std::isnan(own)) {
        out.at<float>(y, x) = own;
        continue;
      }
      double sum = 0;
      int n = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const float d = mixed.at<float>(y + dy, x + dx);
          if (std::isnan(d))
            continue;
          const cv::Vec2f nq = nOut.at<cv::Vec2f>(y + dy, x + dx);
          sum += d + (static_cast<double>(nq[0]) * dx + static_cast<double>(nq[1]) * dy); // the line at q: sd(p) = d_q - n.(p - q), p - q = -(dx, dy)
          ++n;
        }
      if (n > 0)
        out.at<float>(y, x) = static_cast<float>(sum / n);
    }
  return out;
}

} // namespace pm::model::hull
