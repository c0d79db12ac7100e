#include "pm/calib/HandEye.h"

#include <cmath>

#include <visp3/vision/vpHandEyeCalibration.h>

#include "pm/core/Error.h"
#include "pm/io/QuietStdout.h"

namespace pm::calib {

namespace {

//! The mean of \e poses: the mean translation, the rotation at the mean of the others' offsets from the first (small offsets).
vpHomogeneousMatrix meanPose(const std::vector<vpHomogeneousMatrix> &poses)
{
  vpTranslationVector t(0, 0, 0);
  vpColVector tu(3, 0.0);
  const vpRotationMatrix R0 = poses.front().getRotationMatrix();
  for (const vpHomogeneousMatrix &M : poses) {
    t = t + M.getTranslationVector();
    const vpThetaUVector d(R0.t() * M.getRotationMatrix());
    for (unsigned i = 0; i < 3; ++i)
      tu[i] += d[i];
  }
  const double n = static_cast<double>(poses.size());
  return vpHomogeneousMatrix(t / n, vpRotationMatrix(R0 * vpRotationMatrix(vpThetaUVector(tu[0] / n, tu[1] / n, tu[2] / n))));
}

} // namespace

HandEyeFit solveHandEye(const std::vector<vpHomogeneousMatrix> &cMo, const std::vector<vpHomogeneousMatrix> &fMh)
{
  if (cMo.size() != fMh.size())
    throw core::Error("hand-eye: " + std::to_string(cMo.size()) + " board poses but " + std::to_string(fMh.size()) +
                      " hand poses (one of each per view)");
  if (cMo.size() < 3)
    throw core::Error("hand-eye: " + std::to_string(cMo.size()) + " views, at least 3 needed (the hand turned between them)");
  HandEyeFit fit;
  int status = 0;
  {
    io::QuietStdout silence; // vpHandEyeCalibration reports on std::cout
    status = vpHandEyeCalibration::calibrate(cMo, fMh, fit.hMc);
  }
  if (status != 0)
    throw core::Error("hand-eye: vpHandEyeCalibration failed (the hand's rotations too alike?)");
  std::vector<vpHomogeneousMatrix> fMo;
  for (std::size_t i = 0; i < cMo.size(); ++i)
    fMo.push_back(fMh[i] * fit.hMc * cMo[i]);
  fit.fMo = meanPose(fMo);
  double t2 = 0, r2 = 0;
  for (const vpHomogeneousMatrix &M : fMo) {
    const vpHomogeneousMatrix d = fit.fMo.inverse() * M;
    t2 += d.getTranslationVector().sumSquare();
    const double a = d.getThetaUVector().getTheta();
    r2 += a * a;
  }
  const double n = static_cast<double>(fMo.size());
  fit.spreadMm = std::sqrt(t2 / n) * 1e3;
  fit.spreadDeg = std::sqrt(r2 / n) * 180.0 / M_PI;
  fit.views = cMo.size();
  return fit;
}

} // namespace pm::calib
