#include "pm/precise/PoseUncertainty.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "pm/core/Error.h"

namespace pm::precise {

double PoseUncertainty::maxMm() const { return *std::max_element(sigmaMm.begin(), sigmaMm.end()); }

double PoseUncertainty::maxDeg() const { return *std::max_element(sigmaDeg.begin(), sigmaDeg.end()); }

std::array<double, 6> lineSigmas(const std::array<double, 36> &information)
{
  std::array<double, 6> s;
  s.fill(std::numeric_limits<double>::infinity());
  const Eigen::Matrix<double, 6, 6, Eigen::RowMajor> I(information.data());
  if (!I.allFinite())
    return s;
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(I);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || (ldlt.vectorD().array() <= 0).any())
    return s;
  const Eigen::Matrix<double, 6, 6> C = ldlt.solve(Eigen::Matrix<double, 6, 6>::Identity());
  for (int i = 0; i < 6; ++i) {
    const double v = C(i, i);
    if (std::isfinite(v) && v > 0)
      s[static_cast<std::size_t>(i)] = std::sqrt(v) * (i < 3 ? 1.0 : 180.0 / M_PI);
  }
  return s;
}

UncertaintyModel::UncertaintyModel()
    // Fitted by `pm-uncertainty --fit` on random6dof with C12 and R2 (docs/trust.md), the model's own
    // error near each view (its pass landings, ModelErrorFloor.h) added with gain 1. Along z the lines
    // say little of the error (the model's depth bias): mostly a floor (0.40 mm).
    : scale{0.5225, 1.2836, 0.1657, 0.7411, 0.4971, 0.5774}, floor{0.0943, 0.0838, 0.4032, 0.0426, 0.1531, 0.0}
{
}

PoseUncertainty UncertaintyModel::uncertainty(const std::array<double, 36> &information, double residualPx) const
{
  return uncertainty(lineSigmas(information), residualPx);
}

PoseUncertainty UncertaintyModel::uncertainty(const std::array<double, 6> &s, double residualPx, const std::array<double, 6> &modelError) const
{
  PoseUncertainty u;
  u.known = std::isfinite(residualPx) && residualPx >= 0 && std::all_of(s.begin(), s.end(), [](double v) { return std::isfinite(v); });
  if (!u.known)
    return u;
  for (std::size_t i = 0; i < 6; ++i) {
    const double v = gain[i] * std::hypot(sigma(i, s[i], residualPx), modelErrorGain * modelError[i]);
    (i < 3 ? u.sigmaMm[i] : u.sigmaDeg[i - 3]) = v;
  }
  return u;
}

void UncertaintyModel::validate() const
{
  for (std::size_t i = 0; i < 6; ++i)
    if (!(std::isfinite(scale[i]) && scale[i] > 0 && std::isfinite(floor[i]) && floor[i] >= 0 && std::isfinite(gain[i]) && gain[i] > 0))
      throw core::Error("uncertainty model: every scale and gain must be positive and every floor non-negative (and finite)");
  if (!(std::isfinite(modelErrorGain) && modelErrorGain >= 0) || !(std::isfinite(modelErrorWidthDeg) && modelErrorWidthDeg > 0))
    throw core::Error("uncertainty model: the model error's gain must be non-negative and its width positive (and finite)");
}

} // namespace pm::precise
