#include "pm/model/PhotoModelBuilder.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"
#include "pm/core/Hue.h"
#include "pm/model/BackgroundSubtraction.h"

namespace pm::model {

void PhotoModelParams::validate() const
{
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw core::Error(std::string("photo-model parameter ") + what);
  };
  check(minSaturation >= 0 && minSaturation < 1, "minimum saturation must lie in [0, 1)");
  check(minValue >= 0 && minValue < 1, "minimum value must lie in [0, 1)");
  check(minHueFromBackgroundDeg >= 0 && minHueFromBackgroundDeg < 180, "minimum hue distance from the background must lie in [0, 180)");
  check(cleanRadiusPx >= 0 && cleanRadiusPx <= 50, "clean radius must lie in [0, 50] px");
  check(stepPx >= 1 && stepPx <= 200, "sampling step must lie in [1, 200] px");
  check(stripGapPx >= 1 && stripGapPx <= 200, "strip gap must lie in [1, 200] px");
  check(stripWidthPx >= 0 && stripWidthPx <= 200, "strip width must lie in [0, 200] px");
  check(stripRows >= 1 && stripRows <= 20, "strip rows must lie in [1, 20]");
  check(maxHoleAreaPx >= 0, "maximum hole area must be non-negative");
  background.validate();
}

namespace {

cv::Mat regionMask(const vpImage<vpRGBa> &bg, const vpImage<vpRGBa> &tg, const PhotoModelParams &p)
{
  const int h = static_cast<int>(tg.getHeight()), w = static_cast<int>(tg.getWidth());
  cv::Mat m = subtractBackground(tg, bg, p.background); // the target's pixels, shadows left out
  if (p.cleanRadiusPx > 0) {
    const int k = 2 * p.cleanRadiusPx + 1;
    const cv::Mat se = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(k, k));
    cv::morphologyEx(m, m, cv::MORPH_OPEN, se);
    cv::morphologyEx(m, m, cv::MORPH_CLOSE, se);
  }
  // Keep the largest region; fill its small holes (spots of a background-like hue on the target),
  // keep the large ones (background seen between legs or arms).
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(m, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  cv::Mat out(h, w, CV_8U, cv::Scalar(0));
  if (contours.empty())
    return out;
  std::size_t best = 0;
  double bestArea = -1;
  for (std::size_t i = 0; i < contours.size(); ++i) {
    const double a = cv::contourArea(contours[i]);
    if (a > bestArea) {
      bestArea = a;
      best = i;
    }
  }
  cv::drawContours(out, contours, static_cast<int>(best), cv::Scalar(255), cv::FILLED);
  cv::Mat holes = out & ~m, labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(holes, labels, stats, centroids, 4);
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      const int l = labels.at<int>(v, u);
      if (l > 0 && l < n && stats.at<int>(l, cv::CC_STAT_AREA) > p.maxHoleAreaPx)
        out.at<unsigned char>(v, u) = 0;
    }
  return out;
}

} // namespace

PhotoModelBuild buildPhotoModel(const vpImage<vpRGBa> &background, const vpImage<vpRGBa> &withTarget,
                                const vpCameraParameters &cam, double distanceMm, const PhotoModelParams &params)
{
  params.validate();
  if (background.getSize() == 0 || withTarget.getSize() == 0)
    throw core::Error("photo-model: a photo is empty");
  if (background.getWidth() != withTarget.getWidth() || background.getHeight() != withTarget.getHeight())
    throw core::Error("photo-model: the background photo is " + std::to_string(background.getWidth()) + "x" +
                std::to_string(background.getHeight()) + " but the target photo is " +
                std::to_string(withTarget.getWidth()) + "x" + std::to_string(withTarget.getHeight()) +
                "; both must come from the same camera at the same size");
  if (!(distanceMm > 0) || !std::isfinite(distanceMm))
    throw core::Error("photo-model: the photo distance must be positive, got " + std::to_string(distanceMm) + " mm");
  if (!(cam.get_px() > 0 && cam.get_py() > 0))
    throw core::Error("photo-model: the camera focal lengths px, py must be positive");

  const int h = static_cast<int>(withTarget.getHeight()), w = static_cast<int>(withTarget.getWidth());
  PhotoModelBuild out;
  core::PhotoModel &m = out.model;
  m.distanceMm = distanceMm;
  m.px = cam.get_px();
  m.py = cam.get_py();
  m.u0 = cam.get_u0();
  m.v0 = cam.get_v0();
  m.photoWidth = withTarget.getWidth();
  m.photoHeight = withTarget.getHeight();

  std::vector<float> hues;
  hues.reserve(background.getSize());
  for (unsigned i = 0; i < background.getSize(); ++i)
    hues.push_back(core::hueDeg(background.bitmap[i]));
  m.backgroundHue = core::circularMeanHue(hues);

  const cv::Mat region = regionMask(background, withTarget, params);
  const cv::Moments mo = cv::moments(region, true);
  if (mo.m00 < 1)
    throw core::Error("photo-model: no pixel of the target photo differs in colour from the background photo (by more than " +
                      std::to_string(params.background.colourTolGrey) + " grey levels off the background's own colour, or in "
                      "brightness): S_in would be empty (is the target in the photo, and of another colour than the background?)");
  m.centroidU = mo.m10 / mo.m00;
  m.centroidV = mo.m01 / mo.m00;
  const double sx = distanceMm / m.px, sy = distanceMm / m.py;
  auto toModel = [&](double u, double v, float hue) {
    core::ModelPoint p;
    p.x = static_cast<float>((u - m.centroidU) * sx);
    p.y = static_cast<float>((v - m.centroidV) * sy);
    p.z = 0.f;
    p.hue = hue;
    p.u = static_cast<float>(u);
    p.v = static_cast<float>(v);
    return p;
  };

  // S_in: grid aligned on the centroid.
  const double step = params.stepPx;
  const double uStart = m.centroidU - std::floor(m.centroidU / step) * step;
  const double vStart = m.centroidV - std::floor(m.centroidV / step) * step;
  std::vector<float> inHues;
  for (double v = vStart; v < h; v += step)
    for (double u = uStart; u < w; u += step) {
      const int iu = static_cast<int>(std::lround(u)), iv = static_cast<int>(std::lround(v));
      if (iu < 0 || iv < 0 || iu >= w || iv >= h || !region.at<unsigned char>(iv, iu))
        continue;
      const core::Hsv c = core::rgbToHsv(withTarget[static_cast<unsigned>(iv)][static_cast<unsigned>(iu)]);
      if (c.s < params.minSaturation || c.v < params.minValue ||
          core::hueDistance(c.h, m.backgroundHue) <= params.minHueFromBackgroundDeg)
        continue;
      m.inner.push_back(toModel(iu, iv, c.h));
      inHues.push_back(c.h);
    }
  if (m.inner.empty())
    throw core::Error("photo-model: S_in is empty: no saturated point of the target region differs in hue from the "
                "background (" + std::to_string(static_cast<int>(m.backgroundHue)) + " deg) by more than " +
                std::to_string(static_cast<int>(params.minHueFromBackgroundDeg)) +
                " deg (a target of the background's colour cannot be told from it by hue)");
  m.targetHue = core::circularMeanHue(inHues);

  // S_out: offset outlines of the region, sampled along their length.
  cv::Mat outside, dist;
  cv::bitwise_not(region, outside);
  cv::distanceTransform(outside, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  for (int r = 0; r < params.stripRows; ++r) {
    const double off = params.stripGapPx +
                       (params.stripRows > 1 ? params.stripWidthPx * r / (params.stripRows - 1) : 0.0);
    cv::Mat grown = dist <= off;
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(grown, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
    for (const auto &c : contours) {
      double run = step; // emit the first point of each outline
      for (std::size_t i = 0; i < c.size(); ++i) {
        const cv::Point &a = c[i], &b = c[(i + 1) % c.size()];
        if (run >= step) {
          run = 0;
          if (a.x >= 0 && a.y >= 0 && a.x < w && a.y < h)
            m.outer.push_back(toModel(a.x, a.y, core::hueDeg(background[static_cast<unsigned>(a.y)][static_cast<unsigned>(a.x)])));
        }
        run += std::hypot(b.x - a.x, b.y - a.y);
      }
    }
  }

  out.region.resize(static_cast<unsigned>(h), static_cast<unsigned>(w));
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u)
      out.region[static_cast<unsigned>(v)][static_cast<unsigned>(u)] = region.at<unsigned char>(v, u);
  return out;
}

} // namespace pm::model
