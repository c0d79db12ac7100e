#include "pm/core/StereoFitness.h"

#include <algorithm>
#include <cmath>

#include "FitnessKernels.h"

namespace pm::core {

std::size_t StereoFitness::cubeCell(const double c[3])
{
  const double a[3] = {std::fabs(c[0]), std::fabs(c[1]), std::fabs(c[2])};
  const int axis = a[0] >= a[1] && a[0] >= a[2] ? 0 : (a[1] >= a[2] ? 1 : 2);
  const double m = a[axis] > 0 ? a[axis] : 1.0;
  const int face = 2 * axis + (c[axis] < 0 ? 1 : 0);
  auto cell = [](double x) { // x in [-1, 1]
    const int k = static_cast<int>((x + 1.0) * 0.5 * kCubeCells);
    return std::min(kCubeCells - 1, std::max(0, k));
  };
  const int i = cell(c[(axis + 1) % 3] / m), j = cell(c[(axis + 2) % 3] / m);
  return (static_cast<std::size_t>(face) * kCubeCells + static_cast<std::size_t>(j)) * kCubeCells + static_cast<std::size_t>(i);
}

const StereoFitness::View &StereoFitness::viewFor(const Projection &p) const
{
  if (m_views.size() == 1)
    return m_views[0];
  // The camera's centre in the model frame, -R^T t of cMm, as a direction from the origin: the view
  // whose camera looked from the nearest direction.
  double c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = -(static_cast<double>(p.r[k]) * p.t[0] + static_cast<double>(p.r[3 + k]) * p.t[1] + static_cast<double>(p.r[6 + k]) * p.t[2]);
  if (!m_viewCube.empty())
    return m_views[m_viewCube[cubeCell(c)]];
  std::size_t best = 0;
  double bestDot = -2;
  for (std::size_t i = 0; i < m_views.size(); ++i) {
    const double d = m_views[i].dir[0] * c[0] + m_views[i].dir[1] * c[1] + m_views[i].dir[2] * c[2];
    if (d > bestDot) {
      bestDot = d;
      best = i;
    }
  }
  return m_views[best];
}

} // namespace pm::core
