#include "pm/model/HullGeometry.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace pm::model::hull {

Pinhole::Pinhole(const vpHomogeneousMatrix &wMc, const vpCameraParameters &cam, unsigned width, unsigned height)
    : px(cam.get_px()), py(cam.get_py()), u0(cam.get_u0()), v0(cam.get_v0()), w(static_cast<int>(width)), h(static_cast<int>(height))
{
  const vpHomogeneousMatrix cMw = wMc.inverse();
  for (unsigned r = 0; r < 3; ++r) {
    for (unsigned c = 0; c < 3; ++c)
      R[3 * r + c] = cMw[r][c];
    t[r] = 1e3 * cMw[r][3];
    centre[r] = 1e3 * wMc[r][3];
  }
}

Pinhole Pinhole::lookingAtOrigin(const Vec3 &C, const vpCameraParameters &cam, unsigned width, unsigned height)
{
  const Vec3 zc = unit({-C[0], -C[1], -C[2]});
  const Vec3 up = std::fabs(zc[1]) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  const Vec3 xc = unit(cross(up, zc)), yc = cross(zc, xc);
  vpHomogeneousMatrix mMc;
  for (unsigned r = 0; r < 3; ++r) {
    mMc[r][0] = xc[r], mMc[r][1] = yc[r], mMc[r][2] = zc[r], mMc[r][3] = C[r] * 1e-3;
  }
  return Pinhole(mMc, cam, width, height);
}

double HullCamera::sdSmooth(double u, double v) const
{
  const double cu = std::clamp(u, 0.0, cam.w - 1.0), cv = std::clamp(v, 0.0, cam.h - 1.0);
  const double off = std::hypot(u - cu, v - cv);
  const int x = std::min(static_cast<int>(cu), cam.w - 2), y = std::min(static_cast<int>(cv), cam.h - 2);
  const double fu = cu - x, fv = cv - y;
  const float *r0 = signedDist.ptr<float>(y), *r1 = signedDist.ptr<float>(y + 1);
  const double s = (1 - fv) * ((1 - fu) * r0[x] + fu * r0[x + 1]) + fv * ((1 - fu) * r1[x] + fu * r1[x + 1]);
  return s - off;
}

cv::Mat signedDistance(const vpImage<unsigned char> &mask)
{
  const int h = static_cast<int>(mask.getHeight()), w = static_cast<int>(mask.getWidth());
  cv::Mat m(h, w, CV_8U, const_cast<unsigned char *>(mask.bitmap));
  cv::Mat inside, outside, inv;
  cv::distanceTransform(m, inside, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cv::bitwise_not(m, inv);
  cv::distanceTransform(inv, outside, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return inside - outside;
}

} // namespace pm::model::hull
