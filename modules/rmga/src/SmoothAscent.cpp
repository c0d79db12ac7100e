#include "pm/rmga/SmoothAscent.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "pm/core/Error.h"

namespace pm::rmga {

void SmoothAscentParams::validate() const
{
  if (maxEvaluations < 1 || maxEvaluations > 1000000)
    throw core::Error("smooth ascent: the evaluations must lie in [1, 1000000]");
  if (!(minStepPx > 0) || !(firstStepPx >= minStepPx) || !(maxStepPx >= firstStepPx) || !std::isfinite(maxStepPx))
    throw core::Error("smooth ascent: the steps must satisfy 0 < minimum <= first <= maximum (finite), in px");
  if (!(grow >= 1 && grow <= 10) || !(shrink > 0 && shrink < 1))
    throw core::Error("smooth ascent: the step must grow by a factor in [1, 10] and shrink by one in (0, 1)");
}

SmoothAscentResult climbSmooth(SmoothFunction &f, const core::Phi *starts, std::size_t n, const SmoothAscentParams &params)
{
  params.validate();
  if (n == 0 || static_cast<long>(n) > params.maxEvaluations)
    throw core::Error("smooth ascent: between 1 and maxEvaluations (" + std::to_string(params.maxEvaluations) + ") starts are needed, got " +
                std::to_string(n));
  using Vec6 = Eigen::Matrix<double, 6, 1>;
  using Mat6 = Eigen::Matrix<double, 6, 6, Eigen::RowMajor>;
  SmoothAscentResult r;
  Vec6 g, gTrial;
  Mat6 M;
  for (std::size_t k = 0; k < n; ++k) {
    if (!starts[k].isValid())
      throw core::Error("smooth ascent from an invalid pose " + starts[k].toString());
    Vec6 gk;
    Mat6 Mk;
    const double s = f.valueAndGradient(starts[k], gk.data(), Mk.data());
    ++r.evaluations;
    if (k == 0 || s > r.score) {
      r.best = starts[k];
      r.score = s;
      g = gk;
      M = Mk;
    }
  }
  r.startScore = r.score;
  // The metric is that of the best start: a climb moves the pose by a few pixels, which changes it little.
  M.diagonal().array() += 1e-9 * std::max(1e-300, M.trace());
  const Eigen::LDLT<Mat6> ldlt(M);
  double stepPx = params.firstStepPx;
  while (r.evaluations < params.maxEvaluations && stepPx >= params.minStepPx) {
    const Vec6 d = ldlt.solve(g);
    const double motion = std::sqrt(std::max(0.0, d.dot(M * d)));
    if (!(motion > 0) || !std::isfinite(motion))
      break; // a flat spot: no direction to climb
    const Vec6 step = d * (stepPx / motion);
    const core::Phi trial = core::applyTwist(r.best, step.data());
    if (!trial.isValid()) {
      stepPx *= params.shrink;
      continue;
    }
    const double s = f.valueAndGradient(trial, gTrial.data(), nullptr);
    ++r.evaluations;
    if (s > r.score) {
      r.best = trial;
      r.score = s;
      g = gTrial;
      stepPx = std::min(params.maxStepPx, stepPx * params.grow);
    } else {
      stepPx *= params.shrink;
    }
  }
  return r;
}

} // namespace pm::rmga
