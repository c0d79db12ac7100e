#include "pm/core/ViewpointIndex.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::core {

namespace {
//! \e c made unit; 0 stays 0 (a view without a direction is never the nearest but by default).
Vec3 unitOf(const double c[3])
{
  const double n = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  return n > 0 ? Vec3{c[0] / n, c[1] / n, c[2] / n} : Vec3{0, 0, 0};
}

//! The direction of point (s, t) in [-1, 1]^2 of cube face \e face (its axis face / 2, its sign by face % 2).
Vec3 facePoint(int face, double s, double t)
{
  const int axis = face / 2;
  Vec3 d{};
  d[static_cast<std::size_t>(axis)] = face % 2 ? -1.0 : 1.0;
  d[static_cast<std::size_t>((axis + 1) % 3)] = s;
  d[static_cast<std::size_t>((axis + 2) % 3)] = t;
  return unit(d);
}

double angle(const Vec3 &a, const Vec3 &b) { return std::acos(std::clamp(dot(a, b), -1.0, 1.0)); }
} // namespace

ViewpointIndex::ViewpointIndex(const PhotoModel &model)
{
  m_dirs.push_back(unitOf(model.cameraMm));
  for (const ModelView &v : model.views)
    m_dirs.push_back(unitOf(v.cameraMm));
  buildCells();
}

ViewpointIndex::ViewpointIndex(std::vector<Vec3> directions) : m_dirs(std::move(directions))
{
  for (Vec3 &d : m_dirs)
    d = unitOf(d.data());
  buildCells();
}

void ViewpointIndex::buildCells()
{
  if (m_dirs.size() > 65535)
    throw Error("a photo-model may hold at most 65,535 views");
  if (m_dirs.size() <= kScan)
    return;
  // Each cell keeps every view within its centre's nearest angle plus twice the cell's radius (the
  // largest angle from its centre to a corner): the nearest view of any direction in the cell is among them.
  const std::size_t cells = 6 * kCells * kCells;
  m_cellStart.assign(cells + 1, 0);
  std::vector<std::vector<std::uint16_t>> lists(cells);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < kCells; ++j)
      for (int i = 0; i < kCells; ++i) {
        auto at = [](int k) { return 2.0 * k / kCells - 1.0; };
        const Vec3 c = facePoint(face, at(i) + 1.0 / kCells, at(j) + 1.0 / kCells);
        double radius = 0;
        for (int corner = 0; corner < 4; ++corner)
          radius = std::max(radius, angle(c, facePoint(face, at(i + corner % 2), at(j + corner / 2))));
        // In cosines (one acos a cell, not one a view): within the limit <=> cos(angle) >= cos(limit).
        double bestDot = -1;
        for (const Vec3 &d : m_dirs)
          bestDot = std::max(bestDot, dot(c, d));
        const double limit = std::acos(std::clamp(bestDot, -1.0, 1.0)) + 2 * radius + 1e-9;
        const double minDot = limit >= M_PI ? -2.0 : std::cos(limit);
        const double cc[3] = {c[0], c[1], c[2]};
        std::vector<std::uint16_t> &l = lists[cell(cc)];
        for (std::size_t k = 0; k < m_dirs.size(); ++k)
          if (dot(c, m_dirs[k]) >= minDot)
            l.push_back(static_cast<std::uint16_t>(k));
      }
  for (std::size_t c = 0; c < cells; ++c) {
    m_cellStart[c + 1] = m_cellStart[c] + static_cast<std::uint32_t>(lists[c].size());
    m_candidates.insert(m_candidates.end(), lists[c].begin(), lists[c].end());
  }
}

std::size_t ViewpointIndex::cell(const double c[3])
{
  const double a[3] = {std::fabs(c[0]), std::fabs(c[1]), std::fabs(c[2])};
  const int axis = a[0] >= a[1] && a[0] >= a[2] ? 0 : (a[1] >= a[2] ? 1 : 2);
  const double m = a[axis] > 0 ? a[axis] : 1.0;
  const int face = 2 * axis + (c[axis] < 0 ? 1 : 0);
  auto index = [](double x) { // x in [-1, 1]
    const int k = static_cast<int>((x + 1.0) * 0.5 * kCells);
    return std::min(kCells - 1, std::max(0, k));
  };
  const int i = index(c[(axis + 1) % 3] / m), j = index(c[(axis + 2) % 3] / m);
  return (static_cast<std::size_t>(face) * kCells + static_cast<std::size_t>(j)) * kCells + static_cast<std::size_t>(i);
}

std::size_t ViewpointIndex::nearest(const double c[3]) const
{
  std::size_t best = 0;
  double bestDot = -2; // none nearer than about 90 degrees: view 0
  auto consider = [&](std::size_t k) {
    const double d = m_dirs[k][0] * c[0] + m_dirs[k][1] * c[1] + m_dirs[k][2] * c[2];
    if (d > bestDot) {
      bestDot = d;
      best = k;
    }
  };
  if (m_cellStart.empty()) {
    for (std::size_t k = 0; k < m_dirs.size(); ++k)
      consider(k);
    return best;
  }
  const std::size_t cl = cell(c);
  for (std::uint32_t i = m_cellStart[cl]; i < m_cellStart[cl + 1]; ++i)
    consider(m_candidates[i]);
  return best;
}

} // namespace pm::core
