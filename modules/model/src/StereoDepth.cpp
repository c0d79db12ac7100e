#include "pm/model/StereoDepth.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"

namespace pm::model::stereo {

cv::Mat toBgr(const vpImage<vpRGBa> &im)
{
  cv::Mat m(static_cast<int>(im.getHeight()), static_cast<int>(im.getWidth()), CV_8UC3);
  for (int v = 0; v < m.rows; ++v)
    for (int u = 0; u < m.cols; ++u) {
      const vpRGBa &p = im[static_cast<unsigned>(v)][static_cast<unsigned>(u)];
      m.at<cv::Vec3b>(v, u) = cv::Vec3b(p.B, p.G, p.R);
    }
  return m;
}

cv::Matx33d intrinsics(const vpCameraParameters &c)
{
  return cv::Matx33d(c.get_px(), 0, c.get_u0(), 0, c.get_py(), c.get_v0(), 0, 0, 1);
}

cv::Mat disparity(const cv::Mat &L, const cv::Mat &R, int dMin, int n, int blockPx, int uniquenessPercent, bool fast)
{
  const int cn = L.channels(), b = blockPx;
  cv::Ptr<cv::StereoSGBM> sgbm = cv::StereoSGBM::create(dMin, n, b, 8 * cn * b * b, 32 * cn * b * b, 1, 31,
                                                        uniquenessPercent, 100, 2,
                                                        fast ? cv::StereoSGBM::MODE_SGBM_3WAY : cv::StereoSGBM::MODE_HH);
  // SGBM leaves the first minDisparity + numDisparities columns without a match, and a toed-in rig's
  // disparities are large: both images are padded on the left (and on the right for negative
  // disparities) so that every pixel of the original images can be matched over the whole range.
  const int padL = std::max(0, dMin + n), padR = std::max(0, -dMin);
  cv::Mat Lp, Rp, d16p;
  cv::copyMakeBorder(L, Lp, 0, 0, padL, padR, cv::BORDER_CONSTANT, cv::Scalar::all(0));
  cv::copyMakeBorder(R, Rp, 0, 0, padL, padR, cv::BORDER_CONSTANT, cv::Scalar::all(0));
  sgbm->compute(Lp, Rp, d16p);
  const cv::Mat d16 = d16p.colRange(padL, padL + L.cols);
  cv::Mat d(d16.size(), CV_32F);
  const short invalid = static_cast<short>((dMin - 1) * 16);
  for (int v = 0; v < d.rows; ++v)
    for (int u = 0; u < d.cols; ++u) {
      const short s = d16.at<short>(v, u);
      d.at<float>(v, u) = s <= invalid ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(s) / 16.f;
    }
  return d;
}

float sampleDisparity(const cv::Mat &d, float x, float y, double spread)
{
  const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
  if (i < 0 || j < 0 || i + 1 >= d.cols || j + 1 >= d.rows)
    return std::numeric_limits<float>::quiet_NaN();
  const float a = d.at<float>(j, i), b = d.at<float>(j, i + 1), c = d.at<float>(j + 1, i), e = d.at<float>(j + 1, i + 1);
  if (!(std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(e)))
    return std::numeric_limits<float>::quiet_NaN();
  if (std::max({a, b, c, e}) - std::min({a, b, c, e}) > spread)
    return std::numeric_limits<float>::quiet_NaN();
  const float fx = x - static_cast<float>(i), fy = y - static_cast<float>(j);
  return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + e * fx) * fy;
}

cv::Mat leftDepth(const Rectification &rect, const vpImage<vpRGBa> &L, const vpImage<vpRGBa> &R, const vpImage<unsigned char> &region,
                  double zNear, double zFar, const MatchParams &p)
{
  const int w = rect.size.width, h = rect.size.height;
  for (const vpImage<vpRGBa> *im : {&L, &R})
    if (static_cast<int>(im->getWidth()) != w || static_cast<int>(im->getHeight()) != h)
      throw core::Error("stereo depth: an image of " + std::to_string(im->getWidth()) + "x" + std::to_string(im->getHeight()) +
                  " for a rig of " + std::to_string(w) + "x" + std::to_string(h));
  const double dA = rect.disparityAt(std::max(1.0, zNear)), dB = rect.disparityAt(std::max(zNear + 1, zFar));
  const int dMin = static_cast<int>(std::floor(std::min(dA, dB))) - 1;
  const int n = std::max(16, ((static_cast<int>(std::ceil(std::fabs(dA - dB))) + 2 + 15) / 16) * 16);
  std::vector<cv::Point2f> px;
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u)
      if (region[static_cast<unsigned>(v)][static_cast<unsigned>(u)])
        px.emplace_back(static_cast<float>(u), static_cast<float>(v));
  cv::Mat z(h, w, CV_32F, cv::Scalar(std::numeric_limits<float>::quiet_NaN()));
  if (px.empty())
    return z;
  const std::vector<cv::Point2f> r = rect.rectifiedLeft(px);
  // Only the band of rectified rows and columns the region needs (the right image's columns shifted
  // by the disparities): the matcher's cost is the band's area times the disparities.
  float x0 = 1e9f, x1 = -1e9f, y0 = 1e9f, y1 = -1e9f;
  for (const cv::Point2f &q : r)
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  const int m = p.blockPx + 2;
  const int r0 = std::clamp(static_cast<int>(std::floor(y0)) - m, 0, h - 1), r1 = std::clamp(static_cast<int>(std::ceil(y1)) + m + 1, r0 + 1, h);
  const int c0 = std::clamp(static_cast<int>(std::floor(x0)) - (dMin + n) - m, 0, w - 1),
            c1 = std::clamp(static_cast<int>(std::ceil(x1)) - dMin + m + 1, c0 + 1, w);
  const cv::Rect band(c0, r0, c1 - c0, r1 - r0);
  const cv::Mat rl = rect.remap(toBgr(L), 0);
  cv::Mat dBand = disparity(rl(band), rect.remap(toBgr(R), 1)(band), dMin, n, p.blockPx, p.uniquenessPercent, p.fast);
  if (p.minTexture > 0) {
    // Texture across the epipolar lines is what the matcher sees: where the block's mean horizontal
    // gradient is weak (a plain patch, stripes along the lines) its disparity is a guess.
    cv::Mat grey, gx;
    cv::cvtColor(rl(band), grey, cv::COLOR_BGR2GRAY);
    cv::Sobel(grey, gx, CV_32F, 1, 0, 3, 0.25);
    gx = cv::abs(gx);
    cv::blur(gx, gx, cv::Size(p.blockPx, p.blockPx));
    for (int v = 0; v < dBand.rows; ++v)
      for (int u = 0; u < dBand.cols; ++u)
        if (gx.at<float>(v, u) < p.minTexture)
          dBand.at<float>(v, u) = std::numeric_limits<float>::quiet_NaN();
  }
  cv::Mat disp(h, w, CV_32F, cv::Scalar(std::numeric_limits<float>::quiet_NaN()));
  dBand.copyTo(disp(band));
  for (std::size_t i = 0; i < px.size(); ++i) {
    const float d = sampleDisparity(disp, r[i].x, r[i].y, p.maxDisparitySpreadPx);
    if (!std::isfinite(d))
      continue;
    const double Z = rect.depthAt(d);
    const cv::Vec3d Xr((r[i].x - rect.cx1) * Z / rect.f, (r[i].y - rect.cy) * Z / rect.f, Z);
    // Back into the left camera's frame: R1^T Xr, its z.
    const double zc = rect.R1.at<double>(0, 2) * Xr[0] + rect.R1.at<double>(1, 2) * Xr[1] + rect.R1.at<double>(2, 2) * Xr[2];
    if (zc > 0)
      z.at<float>(static_cast<int>(px[i].y), static_cast<int>(px[i].x)) = static_cast<float>(zc);
  }
  return z;
}

} // namespace pm::model::stereo
