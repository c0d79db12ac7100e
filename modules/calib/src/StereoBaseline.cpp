#include "pm/calib/StereoBaseline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpPixelMeterConversion.h>
#include <visp3/detection/vpDetectorAprilTag.h>
#include <visp3/vision/vpPose.h>

#include "pm/core/Error.h"

namespace pm::calib {

BoardView findBoard(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const TagBoard &board, const std::string &name,
                    int minTags)
{
  board.validate();
  vpImage<unsigned char> grey;
  vpImageConvert::convert(I, grey);
  vpDetectorAprilTag det(vpDetectorAprilTag::TAG_36h11);
  det.setZAlignedWithCameraAxis(true); // the tag frame then matches the board's (z into the board)
  det.detect(grey);
  BoardView view;
  vpPose pose;
  std::vector<vpPoint> used;
  for (std::size_t i = 0; i < det.getNbObjects(); ++i) {
    int id = -1;
    if (std::sscanf(det.getMessage(i).c_str(), "36h11 id: %d", &id) != 1 || !board.hasId(id))
      continue;
    // Match each detected corner with the board corner that the tag's own pose projects nearest.
    vpHomogeneousMatrix cMt;
    if (!det.getPose(i, board.tagSizeMm * 1e-3, cam, cMt))
      continue;
    const vpPoint o = board.centre(id);
    const vpHomogeneousMatrix cMb = cMt * vpHomogeneousMatrix(-o.get_oX(), -o.get_oY(), 0, 0, 0, 0);
    const auto model = board.corners(id);
    int matched = 0;
    for (const vpImagePoint &ip : det.getPolygon(i)) {
      double best = 1e30;
      int bj = -1;
      for (int j = 0; j < 4; ++j) {
        vpPoint P = model[static_cast<std::size_t>(j)];
        P.track(cMb);
        double u = 0, v = 0;
        vpMeterPixelConversion::convertPoint(cam, P.get_x(), P.get_y(), u, v);
        const double d = std::hypot(u - ip.get_u(), v - ip.get_v());
        if (d < best)
          best = d, bj = j;
      }
      if (best > 5.0)
        continue;
      vpPoint P = model[static_cast<std::size_t>(bj)];
      double x = 0, y = 0;
      vpPixelMeterConversion::convertPoint(cam, ip, x, y);
      P.set_x(x);
      P.set_y(y);
      pose.addPoint(P);
      used.push_back(P);
      view.corners.push_back(ip);
      ++matched;
    }
    view.tags += matched == 4 ? 1 : 0;
  }
  if (view.tags < minTags)
    throw Error("tag board: " + std::to_string(view.tags) + " of its tags found in the " + name + " image (at least " +
                std::to_string(minTags) + " needed: is the board in view, sharp, and the layout right?)");
  pose.computePose(vpPose::DEMENTHON_VIRTUAL_VS, view.cMb);
  double s2 = 0;
  for (vpPoint P : used) {
    const double xm = P.get_x(), ym = P.get_y();
    P.track(view.cMb);
    double u0 = 0, v0 = 0, u1 = 0, v1 = 0;
    vpMeterPixelConversion::convertPoint(cam, xm, ym, u0, v0);
    vpMeterPixelConversion::convertPoint(cam, P.get_x(), P.get_y(), u1, v1);
    s2 += (u0 - u1) * (u0 - u1) + (v0 - v1) * (v0 - v1);
  }
  view.reprojectionRmsPx = std::sqrt(s2 / static_cast<double>(used.size()));
  return view;
}

namespace {
double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
} // namespace

BaselineResult aggregateBaseline(const std::vector<vpHomogeneousMatrix> &perPair, const std::vector<double> &rmsPx,
                                 const StereoRig &rig)
{
  if (perPair.empty())
    throw Error("stereo check: no pair showed the board in both images");
  // Each pair as (t, theta-u relative to the first pair's rotation).
  const vpRotationMatrix R0 = perPair.front().getRotationMatrix();
  std::vector<std::array<double, 6>> x;
  for (const auto &M : perPair) {
    const vpTranslationVector t = M.getTranslationVector();
    const vpThetaUVector r(R0.t() * M.getRotationMatrix());
    x.push_back({t[0], t[1], t[2], r[0], r[1], r[2]});
  }
  std::array<double, 6> med{};
  for (std::size_t k = 0; k < 6; ++k) {
    std::vector<double> c;
    for (const auto &e : x)
      c.push_back(e[k]);
    med[k] = median(c);
  }
  auto dist = [&](const std::array<double, 6> &e, bool rot) {
    double s = 0;
    for (std::size_t k = rot ? 3 : 0; k < (rot ? 6u : 3u); ++k)
      s += (e[k] - med[k]) * (e[k] - med[k]);
    return std::sqrt(s);
  };
  std::vector<double> dt, dr;
  for (const auto &e : x) {
    dt.push_back(dist(e, false));
    dr.push_back(dist(e, true));
  }
  const double madT = std::max(1.4826 * median(dt), 0.2e-3), madR = std::max(1.4826 * median(dr), 0.02 * M_PI / 180);
  BaselineResult res;
  std::array<double, 6> mean{};
  double rms = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (dt[i] > 3 * madT || dr[i] > 3 * madR) {
      ++res.pairsRejected;
      continue;
    }
    for (std::size_t k = 0; k < 6; ++k)
      mean[k] += x[i][k];
    rms += i < rmsPx.size() ? rmsPx[i] * rmsPx[i] : 0.0;
    ++res.pairsUsed;
  }
  for (double &m : mean)
    m /= res.pairsUsed;
  res.reprojectionRmsPx = std::sqrt(rms / res.pairsUsed);
  double sT = 0, sR = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!(dt[i] > 3 * madT || dr[i] > 3 * madR)) {
      for (std::size_t k = 0; k < 3; ++k) {
        sT += (x[i][k] - mean[k]) * (x[i][k] - mean[k]);
        sR += (x[i][k + 3] - mean[k + 3]) * (x[i][k + 3] - mean[k + 3]);
      }
    }
  res.spreadMm = res.pairsUsed > 1 ? std::sqrt(sT / (res.pairsUsed - 1)) * 1e3 : 0.0;
  res.spreadDeg = res.pairsUsed > 1 ? std::sqrt(sR / (res.pairsUsed - 1)) * 180 / M_PI : 0.0;
  res.cLMcR.buildFrom(vpTranslationVector(mean[0], mean[1], mean[2]),
                      R0 * vpRotationMatrix(vpThetaUVector(mean[3], mean[4], mean[5])));
  res.baselineMm = res.cLMcR.getTranslationVector().frobeniusNorm() * 1e3;
  const vpHomogeneousMatrix ref = rig.cLMcR();
  const vpHomogeneousMatrix d = ref.inverse() * res.cLMcR;
  res.baselineErrorMm = res.baselineMm - ref.getTranslationVector().frobeniusNorm() * 1e3;
  res.translationErrorMm = (res.cLMcR.getTranslationVector() - ref.getTranslationVector()).frobeniusNorm() * 1e3;
  res.rotationErrorDeg = d.getThetaUVector().getTheta() * 180 / M_PI;
  return res;
}

} // namespace pm::calib
