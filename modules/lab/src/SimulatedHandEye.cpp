#include "pm/lab/SimulatedHandEye.h"

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "pm/calib/HandEye.h"
#include "pm/core/Error.h"
#include "pm/lab/ClosedLoop.h"
#include "pm/sim/Rasterizer.h"
#include "pm/robot/Pa10Model.h"
#include "pm/sim/RobotPA10.h"

namespace pm::lab {

vpImage<vpRGBa> defocused(const vpImage<vpRGBa> &I, double px)
{
  if (px <= 0)
    return I;
  cv::Mat m(static_cast<int>(I.getHeight()), static_cast<int>(I.getWidth()), CV_8UC4, const_cast<vpRGBa *>(I.bitmap)), b;
  cv::GaussianBlur(m, b, cv::Size(0, 0), px);
  vpImage<vpRGBa> out(I.getHeight(), I.getWidth());
  std::memcpy(static_cast<void *>(out.bitmap), b.data, I.getSize() * sizeof(vpRGBa));
  return out;
}

HandEyeResult simulatedHandEye(const sim::Scene &scene, const core::StereoRig &truthRig, const core::StereoRig &rig, const calib::Pattern &pattern,
                               int poses, std::uint64_t seed, double blurPx)
{
  const vpColVector q0 = robot::Pa10Model().restJoints();
  const vpHomogeneousMatrix wMb = sim::RobotPA10::forward(q0) * vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0);
  std::mt19937 rng(static_cast<std::uint32_t>(seed) + 17);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<vpHomogeneousMatrix> fMe, cMb[2];
  sim::Rasterizer raster;
  for (int m = 0; m < poses; ++m) {
    vpColVector q = q0;
    for (unsigned i = 0; i < 7; ++i)
      q[i] += 0.12 * u(rng); // up to 7 deg on each joint: the board stays in both views
    const vpHomogeneousMatrix fMh = sim::RobotPA10::forward(q);
    const vpHomogeneousMatrix hMb = fMh.inverse() * wMb;
    bool seen = true;
    vpHomogeneousMatrix views[2];
    for (int c = 0; c < 2 && seen; ++c) {
      const core::PinholeCamera &cam = c ? truthRig.right : truthRig.left;
      vpImage<vpRGBa> I;
      scene.render(raster, cam, hMb, static_cast<std::uint64_t>(1000 + m), static_cast<unsigned>(c), I);
      I = defocused(I, blurPx);
      try {
        const calib::BoardView view = pattern.find(I, (c ? rig.right : rig.left).cam, (c ? rig.right : rig.left).distortion,
                                                   "hand-eye pose " + std::to_string(m), true);
        if (view.reprojectionRmsPx > 0.5) // a doubtful pose (partly hidden board) would spoil the calibration
          throw core::Error("reprojection " + std::to_string(view.reprojectionRmsPx) + " px");
        views[c] = view.cMb;
      } catch (const core::Error &) {
        seen = false; // the board left the view at this pose: skip it
      }
    }
    if (!seen)
      continue;
    fMe.push_back(fMh);
    cMb[0].push_back(views[0]);
    cMb[1].push_back(views[1]);
  }
  if (fMe.size() < 3)
    throw core::Error("hand-eye: the board was seen from only " + std::to_string(fMe.size()) + " poses (3 needed)");
  HandEyeResult r;
  r.poses = fMe.size();
  for (int c = 0; c < 2; ++c) {
    const vpHomogeneousMatrix eMc = calib::solveHandEye(cMb[c], fMe).hMc;
    const vpHomogeneousMatrix ref = (c ? rig.right : rig.left).hMc;
    HandEyeEstimate &h = c ? r.right : r.left;
    h.hMc = eMc;
    h.translationErrorMm = (eMc.getTranslationVector() - ref.getTranslationVector()).frobeniusNorm() * 1e3;
    h.rotationErrorDeg = (ref.inverse() * eMc).getThetaUVector().getTheta() * 180 / M_PI;
  }
  return r;
}

} // namespace pm::lab
