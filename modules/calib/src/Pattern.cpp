#include "pm/calib/Pattern.h"

#include <cmath>

#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpPixelMeterConversion.h>
#include <visp3/vision/vpPose.h>

#include "pm/core/Error.h"
#include "pm/core/UndistortMap.h"

namespace pm::calib {

void CornerMatches::add(vpPoint model, const vpImagePoint &ip, const vpCameraParameters &cam)
{
  double x = 0, y = 0;
  vpPixelMeterConversion::convertPoint(cam, ip, x, y);
  model.set_x(x);
  model.set_y(y);
  points.push_back(model);
  pixels.push_back(ip);
}

BoardView Pattern::find(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const core::LensDistortion &distortion,
                        const std::string &name, bool whole) const
{
  if (distortion.isNone())
    return find(I, cam, name, whole);
  core::PinholeCamera camera{name, cam, I.getWidth(), I.getHeight(), vpHomogeneousMatrix(), distortion};
  const core::UndistortMap map(camera);
  vpImage<vpRGBa> ideal;
  map.undistort(I, ideal);
  BoardView view = find(ideal, cam, name, whole);
  for (vpImagePoint &p : view.corners)
    p = distortion.distort(cam, p);
  return view;
}

void solveBoardPose(const CornerMatches &matches, const vpCameraParameters &cam, BoardView &view)
{
  const std::vector<vpPoint> &matched = matches.points;
  if (matched.size() < 4)
    throw core::Error("calibration pattern: " + std::to_string(matched.size()) + " points matched, at least 4 needed for a pose");
  view.corners = matches.pixels;
  vpPose pose;
  for (const vpPoint &P : matched)
    pose.addPoint(P);
  pose.computePose(vpPose::DEMENTHON_VIRTUAL_VS, view.cMb);
  double s2 = 0;
  for (vpPoint P : matched) {
    const double xm = P.get_x(), ym = P.get_y();
    P.track(view.cMb);
    double u0 = 0, v0 = 0, u1 = 0, v1 = 0;
    vpMeterPixelConversion::convertPoint(cam, xm, ym, u0, v0);
    vpMeterPixelConversion::convertPoint(cam, P.get_x(), P.get_y(), u1, v1);
    s2 += (u0 - u1) * (u0 - u1) + (v0 - v1) * (v0 - v1);
  }
  view.reprojectionRmsPx = std::sqrt(s2 / static_cast<double>(matched.size()));
}

} // namespace pm::calib
