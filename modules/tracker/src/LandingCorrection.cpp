#include "pm/tracker/LandingCorrection.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"
#include "pm/precise/ModelErrorFloor.h"

namespace pm::tracker {

LandingCorrection::LandingCorrection(const std::vector<core::PassLanding> &landings, const vpHomogeneousMatrix &hMc, double widthDeg)
    : m_landings(landings), m_dirs(precise::landingDirections(landings)), m_cameraMm{hMc[0][3] * 1e3, hMc[1][3] * 1e3, hMc[2][3] * 1e3},
      m_width(widthDeg * M_PI / 180.0)
{
  if (!(widthDeg > 0 && std::isfinite(widthDeg)))
    throw core::Error("landing correction: the width must be a positive angle (deg)");
}

std::array<double, 6> LandingCorrection::inModel(const core::Phi &phi) const
{
  std::array<double, 6> out{};
  double d[3];
  if (m_landings.empty() || !precise::cameraDirectionInModel(phi, m_cameraMm, d))
    return out;
  double sum = 0;
  for (std::size_t k = 0; k < m_landings.size(); ++k) {
    const std::array<double, 3> &v = m_dirs[k];
    const double a = std::acos(std::clamp(d[0] * v[0] + d[1] * v[1] + d[2] * v[2], -1.0, 1.0));
    const double w = std::exp(-0.5 * a * a / (m_width * m_width));
    sum += w;
    for (std::size_t i = 0; i < 3; ++i) {
      out[i] += w * m_landings[k].offsetMm[i];
      out[3 + i] += w * m_landings[k].offsetDeg[i];
    }
  }
  const double norm = std::max(1.0, sum); // whole at a view, fading between views
  for (double &x : out)
    x /= norm;
  return out;
}

//! \e m (model frame's axes) turned into the hand frame's: hRm m, for its mm and its deg.
static std::array<double, 6> toHand(const core::Rot3 &R, const std::array<double, 6> &m)
{
  std::array<double, 6> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    out[i] = R[3 * i] * m[0] + R[3 * i + 1] * m[1] + R[3 * i + 2] * m[2];
    out[3 + i] = R[3 * i] * m[3] + R[3 * i + 1] * m[4] + R[3 * i + 2] * m[5];
  }
  return out;
}

std::array<double, 6> LandingCorrection::at(const core::Phi &phi) const
{
  return toHand(core::rotationOf(phi), inModel(phi));
}

core::Phi LandingCorrection::takenOff(const core::Phi &phi, const std::array<double, 6> &mModel)
{
  // Taken off in the hand frame, turned by the pose's own rotation: t - R m_t and exp(-R m_w) R = R exp(-m_w),
  // the pose times a fixed motion of the model.
  const std::array<double, 6> e = toHand(core::rotationOf(phi), mModel);
  const double back[6] = {-e[0], -e[1], -e[2], -e[3] * M_PI / 180.0, -e[4] * M_PI / 180.0, -e[5] * M_PI / 180.0};
  return core::applyTwist(phi, back);
}

} // namespace pm::tracker
