#include "pm/calib/RigComparison.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pm::calib {

namespace {
double cameraMapRms(const core::PinholeCamera &est, const core::PinholeCamera &truth)
{
  std::vector<vpImagePoint> raw;
  for (unsigned v = 0; v <= truth.height; v += truth.height / 12)
    for (unsigned u = 0; u <= truth.width; u += truth.width / 16)
      raw.emplace_back(std::min<double>(v, truth.height - 1), std::min<double>(u, truth.width - 1));
  const std::vector<vpImagePoint> ideal = truth.distortion.undistort(truth.cam, raw);
  double s2 = 0;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    // The ray of the true camera through this raw pixel, seen by the estimated camera.
    const double x = (ideal[i].get_u() - truth.cam.get_u0()) / truth.cam.get_px();
    const double y = (ideal[i].get_v() - truth.cam.get_v0()) / truth.cam.get_py();
    const vpImagePoint e(est.cam.get_v0() + y * est.cam.get_py(), est.cam.get_u0() + x * est.cam.get_px());
    const vpImagePoint d = est.distortion.distort(est.cam, e);
    s2 += vpImagePoint::sqrDistance(d, raw[i]);
  }
  return std::sqrt(s2 / static_cast<double>(raw.size()));
}
} // namespace

CalibrationErrors compareRigs(const core::StereoRig &estimated, const core::StereoRig &truth)
{
  CalibrationErrors e;
  const vpHomogeneousMatrix a = estimated.cLMcR(), b = truth.cLMcR();
  const vpTranslationVector ta = a.getTranslationVector(), tb = b.getTranslationVector();
  e.baselineErrorMm = (ta.frobeniusNorm() - tb.frobeniusNorm()) * 1e3;
  e.translationErrorMm = (ta - tb).frobeniusNorm() * 1e3;
  e.rotationErrorDeg = (b.inverse() * a).getThetaUVector().getTheta() * 180.0 / M_PI;
  e.reprojectionRmsPx[0] = cameraMapRms(estimated.left, truth.left);
  e.reprojectionRmsPx[1] = cameraMapRms(estimated.right, truth.right);
  return e;
}

CameraErrors compareCameras(const core::PinholeCamera &estimated, const core::PinholeCamera &truth)
{
  CameraErrors e;
  e.reprojectionRmsPx = cameraMapRms(estimated, truth);
  e.translationErrorMm = (estimated.hMc.getTranslationVector() - truth.hMc.getTranslationVector()).frobeniusNorm() * 1e3;
  e.rotationErrorDeg = (truth.hMc.inverse() * estimated.hMc).getThetaUVector().getTheta() * 180.0 / M_PI;
  return e;
}

} // namespace pm::calib
