#include "pm/model/Silhouette.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"

namespace pm {

void SilhouetteParams::validate() const
{
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw Error(std::string("silhouette parameter ") + what);
  };
  check(chromaTol > 0 && chromaTol < 1, "chroma tolerance must lie in (0, 1)");
  check(darkRatio > 0 && darkRatio < 1, "dark ratio must lie in (0, 1)");
  check(brightRatio > 1 && brightRatio < 10, "bright ratio must lie in (1, 10)");
  check(minBrightness >= 0 && minBrightness < 255, "minimum brightness must lie in [0, 255)");
  check(cleanRadiusPx >= 0 && cleanRadiusPx <= 20, "clean radius must lie in [0, 20] px");
  check(minRegionFraction >= 0 && minRegionFraction <= 1, "minimum region fraction must lie in [0, 1]");
  check(maxImageFraction > 0 && maxImageFraction <= 1, "maximum image fraction must lie in (0, 1]");
}

vpImage<unsigned char> silhouette(const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> &background,
                                  const SilhouetteParams &p, SilhouetteStats *stats, const std::string &name)
{
  p.validate();
  if (photo.getWidth() != background.getWidth() || photo.getHeight() != background.getHeight() || photo.getSize() == 0)
    throw Error(name + " and its background differ in size");
  const int h = static_cast<int>(photo.getHeight()), w = static_cast<int>(photo.getWidth());
  // Both images as float RGBA, not smoothed: a blur widens the silhouette by a pixel all around (on R2 a
  // 393 px halo for 4 px without it); the opening removes the specks of sensor noise.
  cv::Mat a(h, w, CV_8UC4, const_cast<vpRGBa *>(photo.bitmap)), b(h, w, CV_8UC4, const_cast<vpRGBa *>(background.bitmap));
  cv::Mat af, bf;
  a.convertTo(af, CV_32FC4);
  b.convertTo(bf, CV_32FC4);
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  int shadow = 0;
  for (int v = 0; v < h; ++v) {
    const cv::Vec4f *pa = af.ptr<cv::Vec4f>(v), *pb = bf.ptr<cv::Vec4f>(v);
    unsigned char *m = mask.ptr<unsigned char>(v);
    for (int u = 0; u < w; ++u) {
      // vpRGBa is R, G, B, A in memory.
      const float sa = pa[u][0] + pa[u][1] + pa[u][2], sb = pb[u][0] + pb[u][1] + pb[u][2];
      const double ratio = (sa + 3.0) / (sb + 3.0);
      bool target = ratio < p.darkRatio || ratio > p.brightRatio;
      bool changed = target;
      if (!target && sa > 3 * p.minBrightness && sb > 3 * p.minBrightness) {
        const double dr = pa[u][0] / sa - pb[u][0] / sb, dg = pa[u][1] / sa - pb[u][1] / sb;
        target = std::max(std::fabs(dr), std::fabs(dg)) > p.chromaTol;
      }
      if (!target && ratio < 1.0 / p.brightRatio)
        changed = true; // darker with the same chromaticity: a shadow
      if (target)
        m[u] = 255;
      else if (changed)
        ++shadow;
    }
  }
  // The image's frame (8 px along the borders) shows the backdrop whatever the view, but where the
  // target crosses it: when most of it changed, the background is not this photo's.
  {
    long frame = 0, changedFrame = 0;
    const int bw = std::min(8, std::min(w, h) / 4);
    for (int v = 0; v < h; ++v)
      for (int u = 0; u < w; ++u)
        if (u < bw || v < bw || u >= w - bw || v >= h - bw) {
          ++frame;
          changedFrame += mask.at<unsigned char>(v, u) != 0;
        }
    if (changedFrame > frame / 3)
      throw Error(name + ": " + std::to_string(100 * changedFrame / frame) +
                  " % of the image's border differs from its background: the background does not match its photo");
  }
  if (p.cleanRadiusPx > 0) {
    const int k = 2 * p.cleanRadiusPx + 1;
    const cv::Mat se = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(k, k));
    cv::morphologyEx(mask, mask, cv::MORPH_OPEN, se);
    cv::morphologyEx(mask, mask, cv::MORPH_CLOSE, se);
  }
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  double largest = 0;
  for (const auto &c : contours)
    largest = std::max(largest, cv::contourArea(c));
  cv::Mat out(h, w, CV_8U, cv::Scalar(0));
  for (std::size_t i = 0; i < contours.size(); ++i)
    if (largest > 0 && cv::contourArea(contours[i]) >= p.minRegionFraction * largest)
      cv::drawContours(out, contours, static_cast<int>(i), cv::Scalar(255), cv::FILLED);
  const int n = cv::countNonZero(out);
  if (n == 0)
    throw Error(name + ": no target found (the photo does not differ from its background)");
  if (n > p.maxImageFraction * w * h)
    throw Error(name + ": " + std::to_string(static_cast<int>(100.0 * n / (w * h))) +
                " % of the image differs from its background: the background does not match its photo");
  bool border = false;
  for (int u = 0; u < w && !border; ++u)
    border = out.at<unsigned char>(0, u) || out.at<unsigned char>(h - 1, u);
  for (int v = 0; v < h && !border; ++v)
    border = out.at<unsigned char>(v, 0) || out.at<unsigned char>(v, w - 1);
  if (stats) {
    stats->targetPx = n;
    stats->shadowPx = shadow;
    stats->touchesBorder = border;
  }
  vpImage<unsigned char> r(static_cast<unsigned>(h), static_cast<unsigned>(w));
  std::copy(out.data, out.data + static_cast<std::size_t>(w) * static_cast<std::size_t>(h), r.bitmap);
  return r;
}

} // namespace pm
