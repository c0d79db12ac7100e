// The surface nets of HullMesh.h (a template: the field is the caller's).
#pragma once
#include <cmath>
#include <limits>

#include "pm/core/Error.h"

namespace pm::model {

namespace nets {

//! The index of grid corner (\e x, \e y, \e z) of a grid of \e n cells a side.
inline std::size_t cornerIndex(int n, int x, int y, int z)
{
  const std::size_t nc = static_cast<std::size_t>(n) + 1;
  return (static_cast<std::size_t>(z) * nc + static_cast<std::size_t>(y)) * nc + static_cast<std::size_t>(x);
}

/*!
  The field at the corners of every cell whose occupancy differs from a face neighbour's, on both
  sides, and of their neighbours (the field's zero level may pass a cell beside the carved
  boundary); NaN at the other corners.
*/
template <class Field>
std::vector<float> fieldNearBoundary(const VisualHull &g, Field &field)
{
  const int n = g.n, nc = n + 1;
  auto cornerIdx = [n](int x, int y, int z) { return cornerIndex(n, x, y, z); };
  const float unknown = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> f(static_cast<std::size_t>(nc) * nc * nc, unknown);
  // The corners of every cell whose occupancy differs from a face neighbour's, on both sides, and of
  // their neighbours (the field's zero level may pass a cell beside the carved boundary).
  std::vector<std::uint8_t> band(static_cast<std::size_t>(n) * n * n, 0);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const bool o = g.at(x, y, z);
        if (o == g.at(x - 1, y, z) && o == g.at(x + 1, y, z) && o == g.at(x, y - 1, z) && o == g.at(x, y + 1, z) &&
            o == g.at(x, y, z - 1) && o == g.at(x, y, z + 1))
          continue;
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int xx = x + dx, yy = y + dy, zz = z + dz;
              if (xx >= 0 && yy >= 0 && zz >= 0 && xx < n && yy < n && zz < n)
                band[g.idx(xx, yy, zz)] = 1;
            }
      }
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        if (!band[g.idx(x, y, z)])
          continue;
        for (int dz = 0; dz < 2; ++dz)
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
              float &v = f[cornerIdx(x + dx, y + dy, z + dz)];
              if (std::isnan(v))
                v = static_cast<float>(field(x + dx, y + dy, z + dz));
            }
      }
  return f;
}

//! One vertex per crossed cell of \e f: the mean of the crossings along its twelve edges; returns each cell's vertex (-1: none).
inline std::vector<std::int32_t> netVertices(const VisualHull &g, const std::vector<float> &f, HullMesh &m)
{
  const int n = g.n;
  auto cornerIdx = [n](int x, int y, int z) { return cornerIndex(n, x, y, z); };
  std::vector<std::int32_t> vertexOf(static_cast<std::size_t>(n) * n * n, -1);
  static const int kEdges[12][6] = {{0, 0, 0, 1, 0, 0}, {0, 1, 0, 1, 1, 0}, {0, 0, 1, 1, 0, 1}, {0, 1, 1, 1, 1, 1},
                                    {0, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0}, {0, 0, 1, 0, 1, 1}, {1, 0, 1, 1, 1, 1},
                                    {0, 0, 0, 0, 0, 1}, {1, 0, 0, 1, 0, 1}, {0, 1, 0, 0, 1, 1}, {1, 1, 0, 1, 1, 1}};
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        float c[2][2][2];
        bool known = true, pos = false, neg = false;
        for (int dz = 0; dz < 2 && known; ++dz)
          for (int dy = 0; dy < 2 && known; ++dy)
            for (int dx = 0; dx < 2 && known; ++dx) {
              c[dz][dy][dx] = f[cornerIdx(x + dx, y + dy, z + dz)];
              known = !std::isnan(c[dz][dy][dx]);
              (c[dz][dy][dx] > 0 ? pos : neg) = true;
            }
        if (!known || !pos || !neg)
          continue;
        hull::Vec3 sum{0, 0, 0};
        int k = 0;
        for (const auto &e : kEdges) {
          const float a = c[e[2]][e[1]][e[0]], b = c[e[5]][e[4]][e[3]];
          if ((a > 0) == (b > 0))
            continue;
          const double t = a / (a - b);
          sum[0] += e[0] + t * (e[3] - e[0]);
          sum[1] += e[1] + t * (e[4] - e[1]);
          sum[2] += e[2] + t * (e[5] - e[2]);
          ++k;
        }
        vertexOf[g.idx(x, y, z)] = static_cast<std::int32_t>(m.vertices.size());
        m.vertices.push_back({g.origin[0] + (x + sum[0] / k) * g.cell, g.origin[1] + (y + sum[1] / k) * g.cell,
                              g.origin[2] + (z + sum[2] / k) * g.cell});
      }
  return vertexOf;
}

//! A quad (two triangles) around every crossed grid edge of \e f, facing the side where the field is negative.
inline void netQuads(const VisualHull &g, const std::vector<float> &f, const std::vector<std::int32_t> &vertexOf, HullMesh &m)
{
  const int n = g.n;
  auto cornerIdx = [n](int x, int y, int z) { return cornerIndex(n, x, y, z); };
  for (int z = 1; z < n; ++z)
    for (int y = 1; y < n; ++y)
      for (int x = 1; x < n; ++x) {
        const float a = f[cornerIdx(x, y, z)];
        if (std::isnan(a))
          continue;
        for (int axis = 0; axis < 3; ++axis) {
          const int ex = axis == 0, ey = axis == 1, ez = axis == 2;
          if (x + ex > n || y + ey > n || z + ez > n)
            continue;
          const float b = f[cornerIdx(x + ex, y + ey, z + ez)];
          if (std::isnan(b) || (a > 0) == (b > 0))
            continue;
          // The four cells around the edge, in order around it.
          int cells[4][3];
          if (axis == 0) {
            const int q[4][3] = {{x, y - 1, z - 1}, {x, y, z - 1}, {x, y, z}, {x, y - 1, z}};
            std::copy(&q[0][0], &q[0][0] + 12, &cells[0][0]);
          } else if (axis == 1) {
            const int q[4][3] = {{x - 1, y, z - 1}, {x - 1, y, z}, {x, y, z}, {x, y, z - 1}};
            std::copy(&q[0][0], &q[0][0] + 12, &cells[0][0]);
          } else {
            const int q[4][3] = {{x - 1, y - 1, z}, {x, y - 1, z}, {x, y, z}, {x - 1, y, z}};
            std::copy(&q[0][0], &q[0][0] + 12, &cells[0][0]);
          }
          std::int32_t v[4];
          bool all = true;
          for (int i = 0; i < 4 && all; ++i) {
            v[i] = cells[i][0] < n && cells[i][1] < n && cells[i][2] < n ? vertexOf[g.idx(cells[i][0], cells[i][1], cells[i][2])] : -1;
            all = v[i] >= 0;
          }
          if (!all)
            continue;
          // Outward: from the positive corner toward the negative one.
          const hull::Vec3 out{static_cast<double>(ex * (a > 0 ? 1 : -1)), static_cast<double>(ey * (a > 0 ? 1 : -1)),
                               static_cast<double>(ez * (a > 0 ? 1 : -1))};
          const hull::Vec3 nq = hull::cross(hull::sub(m.vertices[static_cast<std::size_t>(v[2])], m.vertices[static_cast<std::size_t>(v[0])]),
                                            hull::sub(m.vertices[static_cast<std::size_t>(v[3])], m.vertices[static_cast<std::size_t>(v[1])]));
          if (hull::dot(nq, out) < 0)
            std::swap(v[1], v[3]);
          m.triangles.push_back({static_cast<std::uint32_t>(v[0]), static_cast<std::uint32_t>(v[1]), static_cast<std::uint32_t>(v[2])});
          m.triangles.push_back({static_cast<std::uint32_t>(v[0]), static_cast<std::uint32_t>(v[2]), static_cast<std::uint32_t>(v[3])});
        }
      }
}

} // namespace nets

template <class Field>
HullMesh meshField(const VisualHull &g, Field field)
{
  const std::vector<float> f = nets::fieldNearBoundary(g, field);
  HullMesh m;
  const std::vector<std::int32_t> vertexOf = nets::netVertices(g, f, m);
  nets::netQuads(g, f, vertexOf, m);
  if (m.triangles.empty())
    throw core::Error("all-around model: the hull's surface has no face (too few cells carved?)");
  m.update();
  return m;
}

} // namespace pm::model
