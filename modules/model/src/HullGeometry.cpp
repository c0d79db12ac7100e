#include "pm/model/HullGeometry.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace pm::model::hull {

double HullView::sdSmooth(double u, double v) const
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
