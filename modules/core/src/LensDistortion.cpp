#include "pm/core/LensDistortion.h"

#include <cmath>
#include <sstream>

#include <opencv2/calib3d.hpp>

#include "pm/core/Error.h"

namespace pm::core {

namespace {
cv::Matx33d cameraMatrix(const vpCameraParameters &cam)
{
  return cv::Matx33d(cam.get_px(), 0, cam.get_u0(), 0, cam.get_py(), cam.get_v0(), 0, 0, 1);
}

//! r_d(r) of the radial part: r (1 + k1 r^2 + k2 r^4 + k3 r^6) / (1 + k4 r^2 + k5 r^4 + k6 r^6).
double radial(const std::vector<double> &k, double r)
{
  const auto c = [&](std::size_t i) { return i < k.size() ? k[i] : 0.0; };
  const double r2 = r * r, r4 = r2 * r2, r6 = r4 * r2;
  return r * (1 + c(0) * r2 + c(1) * r4 + c(4) * r6) / (1 + c(5) * r2 + c(6) * r4 + c(7) * r6);
}
} // namespace

bool LensDistortion::isNone() const
{
  for (double c : coefficients)
    if (c != 0.0)
      return false;
  return true;
}

void LensDistortion::validate(const vpCameraParameters &cam, unsigned w, unsigned h, const std::string &who) const
{
  const std::size_t n = coefficients.size();
  if (n != 0 && n != 4 && n != 5 && n != 8 && n != 12 && n != 14)
    throw Error(who + ": " + std::to_string(n) + " distortion coefficients; OpenCV's model has 4, 5, 8, 12 or 14");
  for (double c : coefficients)
    if (!std::isfinite(c))
      throw Error(who + ": a distortion coefficient is not finite");
  if (isNone())
    return;
  // The farthest image corner, in distorted normalized coordinates.
  double rc = 0;
  for (double u : {0.0, static_cast<double>(w)})
    for (double v : {0.0, static_cast<double>(h)})
      rc = std::max(rc, std::hypot((u - cam.get_u0()) / cam.get_px(), (v - cam.get_v0()) / cam.get_py()));
  // Walk the ideal radius out until the distorted one reaches the corner: it must grow all the way.
  const double step = 1e-3;
  double prev = 0;
  for (double r = step; r < 20; r += step) {
    const double rd = radial(coefficients, r);
    if (!(rd > prev)) {
      std::ostringstream os;
      os << who << ": the lens distortion (" << describe() << ") folds the image: rays farther out land back inside "
         << std::lround(prev * cam.get_px()) << " px from the centre, short of the image's corner at "
         << std::lround(rc * cam.get_px()) << " px; the coefficients do not describe this camera";
      throw Error(os.str());
    }
    if (rd >= rc)
      return;
    prev = rd;
  }
  throw Error(who + ": the lens distortion (" + describe() + ") never reaches the image corner: it folds the image");
}

vpImagePoint LensDistortion::distort(const vpCameraParameters &cam, const vpImagePoint &ideal) const
{
  if (isNone())
    return ideal;
  const std::vector<cv::Point3d> obj{{(ideal.get_u() - cam.get_u0()) / cam.get_px(), (ideal.get_v() - cam.get_v0()) / cam.get_py(), 1.0}};
  std::vector<cv::Point2d> img;
  cv::projectPoints(obj, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cameraMatrix(cam), coefficients, img);
  return vpImagePoint(img[0].y, img[0].x);
}

vpImagePoint LensDistortion::undistort(const vpCameraParameters &cam, const vpImagePoint &raw) const
{
  return undistort(cam, std::vector<vpImagePoint>{raw})[0];
}

std::vector<vpImagePoint> LensDistortion::undistort(const vpCameraParameters &cam, const std::vector<vpImagePoint> &raw) const
{
  if (isNone() || raw.empty())
    return raw;
  std::vector<cv::Point2d> src(raw.size()), dst;
  for (std::size_t i = 0; i < raw.size(); ++i)
    src[i] = cv::Point2d(raw[i].get_u(), raw[i].get_v());
  const cv::Matx33d K = cameraMatrix(cam);
  cv::undistortPoints(src, dst, K, coefficients, cv::noArray(), K,
                      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 200, 1e-12));
  std::vector<vpImagePoint> out(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i)
    out[i] = vpImagePoint(dst[i].y, dst[i].x);
  return out;
}

bool LensDistortion::isVispModel() const
{
  for (std::size_t i = 1; i < coefficients.size(); ++i)
    if (coefficients[i] != 0.0)
      return false;
  return true;
}

std::string LensDistortion::describe() const
{
  if (isNone())
    return "none";
  static const char *names[] = {"k1", "k2", "p1", "p2", "k3", "k4", "k5", "k6", "s1", "s2", "s3", "s4", "tauX", "tauY"};
  std::ostringstream os;
  os.precision(4);
  for (std::size_t i = 0; i < coefficients.size() && i < 14; ++i)
    os << (i ? ", " : "") << names[i] << " " << coefficients[i];
  return os.str();
}

} // namespace pm::core
