#include "pm/calib/StereoBaseline.h"

#include <algorithm>
#include <cmath>
#include <array>

#include "pm/core/Error.h"
#include "pm/core/Statistics.h"

namespace pm::calib {

BaselineResult aggregateBaseline(const std::vector<vpHomogeneousMatrix> &perPair, const std::vector<double> &rmsPx,
                                 const core::StereoRig &rig)
{
  if (perPair.empty())
    throw core::Error("stereo check: no pair showed the board in both images");
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
    med[k] = core::median(c);
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
  const double madT = std::max(1.4826 * core::median(dt), 0.2e-3), madR = std::max(1.4826 * core::median(dr), 0.02 * M_PI / 180);
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
