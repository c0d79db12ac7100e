#include "pm/model/Silhouette.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"
#include "pm/core/Hue.h"

namespace pm::model {

void SilhouetteParams::validate() const
{
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw core::Error(std::string("silhouette parameter ") + what);
  };
  background.validate();
  check(cleanRadiusPx >= 0 && cleanRadiusPx <= 20, "clean radius must lie in [0, 20] px");
  check(minRegionFraction >= 0 && minRegionFraction <= 1, "minimum region fraction must lie in [0, 1]");
  check(maxImageFraction > 0 && maxImageFraction <= 1, "maximum image fraction must lie in (0, 1]");
  check(backdropHueTolDeg > 0 && backdropHueTolDeg < 180, "backdrop hue tolerance must lie in (0, 180) degrees");
  check(backdropMinSaturation >= 0 && backdropMinSaturation < 1, "backdrop minimum saturation must lie in [0, 1)");
  check(backdropMinValue >= 0 && backdropMinValue < 1, "backdrop minimum value must lie in [0, 1)");
}

namespace {

/*!
  The raw mask of target pixels cleaned as the header says (the image's frame checked first, on
  \e frameMask when given, else on \e mask; then opening and closing, the regions kept, their holes
  filled), as a vpImage; errors name \e name.
*/
vpImage<unsigned char> cleaned(cv::Mat &mask, const SilhouetteParams &p, SilhouetteStats *stats, const std::string &name,
                               const cv::Mat *frameMask = nullptr)
{
  const int h = mask.rows, w = mask.cols;
  // The image's frame (8 px along the borders) shows the backdrop whatever the view, but where the
  // target crosses it: when most of it changed, the background is not this photo's.
  {
    const cv::Mat &fm = frameMask ? *frameMask : mask;
    long frame = 0, changedFrame = 0;
    const int bw = std::min(8, std::min(w, h) / 4);
    for (int v = 0; v < h; ++v)
      for (int u = 0; u < w; ++u)
        if (u < bw || v < bw || u >= w - bw || v >= h - bw) {
          ++frame;
          changedFrame += fm.at<unsigned char>(v, u) != 0;
        }
    if (changedFrame > frame / 3)
      throw core::Error(name + ": " + std::to_string(100 * changedFrame / frame) +
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
    throw core::Error(name + ": no target found (the photo does not differ from its background)");
  if (n > p.maxImageFraction * w * h)
    throw core::Error(name + ": " + std::to_string(static_cast<int>(100.0 * n / (w * h))) +
                " % of the image differs from its background: the background does not match its photo");
  bool border = false;
  for (int u = 0; u < w && !border; ++u)
    border = out.at<unsigned char>(0, u) || out.at<unsigned char>(h - 1, u);
  for (int v = 0; v < h && !border; ++v)
    border = out.at<unsigned char>(v, 0) || out.at<unsigned char>(v, w - 1);
  if (stats) {
    stats->targetPx = n;
    stats->touchesBorder = border;
  }
  vpImage<unsigned char> r(static_cast<unsigned>(h), static_cast<unsigned>(w));
  std::copy(out.data, out.data + static_cast<std::size_t>(w) * static_cast<std::size_t>(h), r.bitmap);
  return r;
}

//! \e image with each pixel the mean of its 3 x 3 neighbours (OpenCV's box filter, the border reflected).
vpImage<vpRGBa> boxMean3(const vpImage<vpRGBa> &image)
{
  vpImage<vpRGBa> out(image.getHeight(), image.getWidth());
  const cv::Mat in(static_cast<int>(image.getHeight()), static_cast<int>(image.getWidth()), CV_8UC4, const_cast<vpRGBa *>(image.bitmap));
  cv::Mat o(in.rows, in.cols, CV_8UC4, out.bitmap);
  cv::blur(in, o, cv::Size(3, 3));
  return out;
}

} // namespace

vpImage<unsigned char> silhouette(const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> &background,
                                  const SilhouetteParams &p, SilhouetteStats *stats, const std::string &name)
{
  p.validate();
  if (photo.getWidth() != background.getWidth() || photo.getHeight() != background.getHeight() || photo.getSize() == 0)
    throw core::Error(name + " and its background differ in size");
  int shadow = 0;
  cv::Mat mask = subtractBackground(photo, background, p.background, &shadow);
  if (stats)
    stats->shadowPx = shadow;
  // The frame's test on the means of 3 x 3 pixels (a sensor's noise that grows with the signal flags
  // pixels one by one, and the mean of nine divides it by three; another view's background differs in
  // whole patches, mean or not), counting the shadows too: another view's sea bottom differs from this
  // one's mostly in brightness along the same blue, which a shadow's test takes for shadow.
  cv::Mat frame;
  (void)subtractBackground(boxMean3(photo), boxMean3(background), p.background, nullptr, &frame);
  return cleaned(mask, p, stats, name, &frame);
}

vpImage<unsigned char> silhouetteOnBackdrop(const vpImage<vpRGBa> &photo, double backdropHueDeg, const SilhouetteParams &p,
                                            SilhouetteStats *stats, const std::string &name)
{
  p.validate();
  if (!(backdropHueDeg >= 0 && backdropHueDeg < 360))
    throw core::Error("the backdrop's hue must lie in [0, 360) degrees");
  if (photo.getSize() == 0)
    throw core::Error(name + " is empty");
  const int h = static_cast<int>(photo.getHeight()), w = static_cast<int>(photo.getWidth());
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  for (int v = 0; v < h; ++v) {
    unsigned char *m = mask.ptr<unsigned char>(v);
    for (int u = 0; u < w; ++u) {
      const core::Hsv c = core::rgbToHsv(photo[static_cast<unsigned>(v)][static_cast<unsigned>(u)]);
      // Too pale or too dark for a hue: not the backdrop's colour, so the target (a missed target
      // pixel would carve the hull, a wrong one only widens it). A shadow keeps the backdrop's hue.
      const bool hasHue = c.s >= p.backdropMinSaturation && c.v >= p.backdropMinValue;
      if (!hasHue || core::hueDistance(c.h, static_cast<float>(backdropHueDeg)) > p.backdropHueTolDeg)
        m[u] = 255;
    }
  }
  // What lies beyond a finite backdrop (a wall, the room) has another hue too: regions touching the
  // image's border are dropped when a region inside the image remains (the target, which must not
  // touch the border); else they stay, and the cleaning says the target is cut.
  cv::Mat labels, st, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, st, centroids, 8);
  std::vector<bool> touches(static_cast<std::size_t>(n), false);
  bool inside = false;
  for (int l = 1; l < n; ++l) {
    const int x = st.at<int>(l, cv::CC_STAT_LEFT), y = st.at<int>(l, cv::CC_STAT_TOP);
    const int bw = st.at<int>(l, cv::CC_STAT_WIDTH), bh = st.at<int>(l, cv::CC_STAT_HEIGHT);
    touches[static_cast<std::size_t>(l)] = x == 0 || y == 0 || x + bw == w || y + bh == h;
    inside = inside || (!touches[static_cast<std::size_t>(l)] && st.at<int>(l, cv::CC_STAT_AREA) > 100);
  }
  if (inside)
    for (int v = 0; v < h; ++v)
      for (int u = 0; u < w; ++u)
        if (touches[static_cast<std::size_t>(labels.at<int>(v, u))])
          mask.at<unsigned char>(v, u) = 0;
  if (stats)
    stats->shadowPx = 0;
  return cleaned(mask, p, stats, name);
}

} // namespace pm::model
