#include "pm/core/UndistortMap.h"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"

namespace pm::core {

UndistortMap::UndistortMap(const PinholeCamera &camera) : m_w(camera.width), m_h(camera.height)
{
  camera.distortion.validate(camera.cam, m_w, m_h, camera.name + " camera");
  const cv::Matx33d K(camera.cam.get_px(), 0, camera.cam.get_u0(), 0, camera.cam.get_py(), camera.cam.get_v0(), 0, 0, 1);
  const std::size_t n = static_cast<std::size_t>(m_w) * m_h;
  m_mapU.resize(n);
  m_mapV.resize(n);
  cv::Mat mu(static_cast<int>(m_h), static_cast<int>(m_w), CV_32F, m_mapU.data());
  cv::Mat mv(static_cast<int>(m_h), static_cast<int>(m_w), CV_32F, m_mapV.data());
  if (camera.distortion.isNone()) {
    for (unsigned v = 0; v < m_h; ++v)
      for (unsigned u = 0; u < m_w; ++u) {
        mu.at<float>(static_cast<int>(v), static_cast<int>(u)) = static_cast<float>(u);
        mv.at<float>(static_cast<int>(v), static_cast<int>(u)) = static_cast<float>(v);
      }
  } else {
    cv::Mat tu, tv;
    cv::initUndistortRectifyMap(K, camera.distortion.coefficients, cv::noArray(), K,
                                cv::Size(static_cast<int>(m_w), static_cast<int>(m_h)), CV_32FC1, tu, tv);
    tu.copyTo(mu);
    tv.copyTo(mv);
  }
  m_fixedXY.resize(2 * n);
  m_fixedA.resize(n);
  cv::Mat fxy(static_cast<int>(m_h), static_cast<int>(m_w), CV_16SC2, m_fixedXY.data());
  cv::Mat fa(static_cast<int>(m_h), static_cast<int>(m_w), CV_16UC1, m_fixedA.data());
  cv::convertMaps(mu, mv, fxy, fa, CV_16SC2);
  m_nearest.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const long u = std::lround(m_mapU[i]), v = std::lround(m_mapV[i]);
    const bool in = std::isfinite(m_mapU[i]) && std::isfinite(m_mapV[i]) && u >= 0 && v >= 0 && u < static_cast<long>(m_w) &&
                    v < static_cast<long>(m_h);
    m_nearest[i] = in ? static_cast<std::int32_t>(v * static_cast<long>(m_w) + u) : -1;
  }
}

void UndistortMap::undistort(const vpImage<vpRGBa> &raw, vpImage<vpRGBa> &ideal) const
{
  if (raw.getWidth() != m_w || raw.getHeight() != m_h)
    throw Error("undistortion: the image is " + std::to_string(raw.getWidth()) + "x" + std::to_string(raw.getHeight()) +
                " but the camera's is " + std::to_string(m_w) + "x" + std::to_string(m_h));
  ideal.resize(m_h, m_w);
  const cv::Mat src(static_cast<int>(m_h), static_cast<int>(m_w), CV_8UC4, const_cast<vpRGBa *>(raw.bitmap));
  cv::Mat dst(static_cast<int>(m_h), static_cast<int>(m_w), CV_8UC4, ideal.bitmap);
  const cv::Mat mu(static_cast<int>(m_h), static_cast<int>(m_w), CV_32F, const_cast<float *>(m_mapU.data()));
  const cv::Mat mv(static_cast<int>(m_h), static_cast<int>(m_w), CV_32F, const_cast<float *>(m_mapV.data()));
  cv::remap(src, dst, mu, mv, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0, 0, 0, 255));
}

void UndistortMap::undistortRegion(const vpImage<vpRGBa> &raw, vpImage<vpRGBa> &ideal, int u0, int v0, int u1, int v1) const
{
  if (raw.getWidth() != m_w || raw.getHeight() != m_h || ideal.getWidth() != m_w || ideal.getHeight() != m_h)
    throw Error("undistortion: the images are " + std::to_string(raw.getWidth()) + "x" + std::to_string(raw.getHeight()) + " and " +
                std::to_string(ideal.getWidth()) + "x" + std::to_string(ideal.getHeight()) + " but the camera's are " +
                std::to_string(m_w) + "x" + std::to_string(m_h));
  u0 = std::max(u0, 0), v0 = std::max(v0, 0);
  u1 = std::min(u1, static_cast<int>(m_w)), v1 = std::min(v1, static_cast<int>(m_h));
  if (u1 <= u0 || v1 <= v0)
    return;
  const cv::Rect roi(u0, v0, u1 - u0, v1 - v0);
  const cv::Mat src(static_cast<int>(m_h), static_cast<int>(m_w), CV_8UC4, const_cast<vpRGBa *>(raw.bitmap));
  cv::Mat dst(static_cast<int>(m_h), static_cast<int>(m_w), CV_8UC4, ideal.bitmap);
  const cv::Mat fxy(static_cast<int>(m_h), static_cast<int>(m_w), CV_16SC2, const_cast<std::int16_t *>(m_fixedXY.data()));
  const cv::Mat fa(static_cast<int>(m_h), static_cast<int>(m_w), CV_16UC1, const_cast<std::uint16_t *>(m_fixedA.data()));
  cv::Mat out = dst(roi);
  cv::remap(src, out, fxy(roi), fa(roi), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0, 0, 0, 255));
}

void UndistortMap::undistortField(const float *raw, float *ideal, float outside) const
{
  const cv::Mat src(static_cast<int>(m_h), static_cast<int>(m_w), CV_32F, const_cast<float *>(raw));
  cv::Mat dst(static_cast<int>(m_h), static_cast<int>(m_w), CV_32F, ideal);
  const cv::Mat mu(static_cast<int>(m_h), static_cast<int>(m_w), CV_32F, const_cast<float *>(m_mapU.data()));
  const cv::Mat mv(static_cast<int>(m_h), static_cast<int>(m_w), CV_32F, const_cast<float *>(m_mapV.data()));
  cv::remap(src, dst, mu, mv, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(outside));
}

double UndistortMap::coverage() const
{
  std::size_t in = 0;
  for (std::int32_t i : m_nearest)
    in += i >= 0;
  return m_nearest.empty() ? 0.0 : static_cast<double>(in) / static_cast<double>(m_nearest.size());
}

} // namespace pm::core
