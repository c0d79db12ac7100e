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
    // Fitted by `pm-uncertainty --fit` on random6dof with C12 and R2 (docs/trust.md). Along z the
    // lines say little of the error (the model's depth bias, about 0.3 mm): a floor alone (0.53 mm).
    : scale{1.9138, 0.9050, 0.05, 1.2836, 0.7791, 1.4184}, floor{0.0312, 0.1751, 0.5324, 0.0312, 0.1972, 0.0}
{
}

PoseUncertainty UncertaintyModel::uncertainty(const std::array<double, 36> &information, double residualPx) const
{
  return uncertainty(lineSigmas(information), residualPx);
}

PoseUncertainty UncertaintyModel::uncertainty(const std::array<double, 6> &s, double residualPx) const
{
  PoseUncertainty u;
  u.known = std::isfinite(residualPx) && residualPx >= 0 && std::all_of(s.begin(), s.end(), [](double v) { return std::isfinite(v); });
  if (!u.known)
    return u;
  for (std::size_t i = 0; i < 6; ++i) {
    const double v = sigma(i, s[i], residualPx);
    (i < 3 ? u.sigmaMm[i] : u.sigmaDeg[i - 3]) = v;
  }
  return u;
}

void UncertaintyModel::validate() const
{
  for (std::size_t i = 0; i < 6; ++i)
    if (!(std::isfinite(scale[i]) && scale[i] > 0 && std::isfinite(floor[i]) && floor[i] >= 0))
      throw core::Error("uncertainty model: every scale must be positive and every floor non-negative (and finite)");
}

} // namespace pm::precise
