#include "pm/precise/ModelErrorFloor.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pm/core/Error.h"

namespace pm::precise {

std::vector<std::array<double, 3>> landingDirections(const std::vector<core::PassLanding> &landings)
{
  std::vector<std::array<double, 3>> dirs;
  for (const core::PassLanding &l : landings) {
    const double n = std::sqrt(l.cameraMm[0] * l.cameraMm[0] + l.cameraMm[1] * l.cameraMm[1] + l.cameraMm[2] * l.cameraMm[2]);
    dirs.push_back({l.cameraMm[0] / n, l.cameraMm[1] / n, l.cameraMm[2] / n});
  }
  return dirs;
}

bool cameraDirectionInModel(const core::Phi &phi, const std::array<double, 3> &cameraMm, double d[3])
{
  // mRh (c - t), with R = hRm row-major.
  const core::Rot3 R = core::rotationOf(phi);
  const double toCamera[3] = {cameraMm[0] - phi.x, cameraMm[1] - phi.y, cameraMm[2] - phi.z};
  for (int j = 0; j < 3; ++j)
    d[j] = R[j] * toCamera[0] + R[3 + j] * toCamera[1] + R[6 + j] * toCamera[2];
  const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(n > 0))
    return false;
  for (int j = 0; j < 3; ++j)
    d[j] /= n;
  return true;
}

ModelErrorFloor::ModelErrorFloor(const std::vector<core::PassLanding> &landings, const vpHomogeneousMatrix &hMc, double widthDeg)
    : m_landings(landings), m_dirs(landingDirections(landings)), m_cameraMm{hMc[0][3] * 1e3, hMc[1][3] * 1e3, hMc[2][3] * 1e3},
      m_width(widthDeg * M_PI / 180.0)
{
  if (!(widthDeg > 0 && std::isfinite(widthDeg)))
    throw core::Error("model error floor: the width must be a positive angle (deg)");
}

std::array<double, 6> ModelErrorFloor::at(const core::Phi &phi) const
{
  std::array<double, 6> out{};
  double d[3];
  if (m_landings.empty() || !cameraDirectionInModel(phi, m_cameraMm, d))
    return out;
  const core::Rot3 R = core::rotationOf(phi);
  // Gaussian weights on the angle; relative to the nearest landing's, so that a direction far from
  // every view still takes its nearest views' (no underflow to nothing).
  double nearest = std::numeric_limits<double>::infinity();
  for (const std::array<double, 3> &v : m_dirs)
    nearest = std::min(nearest, std::acos(std::clamp(d[0] * v[0] + d[1] * v[1] + d[2] * v[2], -1.0, 1.0)));
  double sum = 0, Ct[3][3] = {}, Cw[3][3] = {}; // second moments of the offsets, model frame
  for (std::size_t k = 0; k < m_landings.size(); ++k) {
    const std::array<double, 3> &v = m_dirs[k];
    const double a = std::acos(std::clamp(d[0] * v[0] + d[1] * v[1] + d[2] * v[2], -1.0, 1.0));
    const double w = std::exp(-0.5 * (a * a - nearest * nearest) / (m_width * m_width));
    sum += w;
    const core::PassLanding &l = m_landings[k];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        Ct[i][j] += w * l.offsetMm[i] * l.offsetMm[j];
        Cw[i][j] += w * l.offsetDeg[i] * l.offsetDeg[j];
      }
  }
  // Into the hand frame's axes: the diagonal of hRm C mRh.
  for (int i = 0; i < 3; ++i) {
    double vt = 0, vw = 0;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        vt += R[3 * i + a] * Ct[a][b] * R[3 * i + b];
        vw += R[3 * i + a] * Cw[a][b] * R[3 * i + b];
      }
    out[i] = std::sqrt(std::max(0.0, vt / sum));
    out[3 + i] = std::sqrt(std::max(0.0, vw / sum));
  }
  return out;
}

} // namespace pm::precise
