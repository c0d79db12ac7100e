#include "pm/model/HullMesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace pm::model {

using hull::Vec3;

void HullMesh::update()
{
  faceNormals.assign(triangles.size(), Vec3{0, 0, 0});
  normals.assign(vertices.size(), Vec3{0, 0, 0});
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const auto &t = triangles[f];
    const Vec3 c = hull::cross(hull::sub(vertices[t[1]], vertices[t[0]]), hull::sub(vertices[t[2]], vertices[t[0]]));
    faceNormals[f] = hull::unit(c);
    for (std::uint32_t v : t)
      normals[v] = hull::add(normals[v], c); // area-weighted
  }
  for (Vec3 &n : normals)
    n = hull::unit(n);
  edges.clear();
  std::unordered_map<std::uint64_t, std::size_t> index;
  index.reserve(triangles.size() * 2);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles[f][static_cast<std::size_t>(k)], b = triangles[f][static_cast<std::size_t>((k + 1) % 3)];
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      const auto it = index.find(key);
      if (it == index.end()) {
        index.emplace(key, edges.size());
        edges.push_back({std::min(a, b), std::max(a, b), static_cast<std::int32_t>(f), -1});
      } else if (edges[it->second].f1 < 0) {
        edges[it->second].f1 = static_cast<std::int32_t>(f);
      }
    }
}

void HullMesh::transform(const double R[9], const Vec3 &from)
{
  auto rot = [R](const Vec3 &d) {
    return Vec3{R[0] * d[0] + R[1] * d[1] + R[2] * d[2], R[3] * d[0] + R[4] * d[1] + R[5] * d[2], R[6] * d[0] + R[7] * d[1] + R[8] * d[2]};
  };
  for (Vec3 &v : vertices)
    v = rot(hull::sub(v, from));
  for (Vec3 &nn : normals)
    nn = rot(nn);
  for (Vec3 &nn : faceNormals)
    nn = rot(nn);
}

void HullMesh::smooth(int iterations, double lambda, double mu)
{
  std::vector<Vec3> sum(vertices.size());
  std::vector<int> count(vertices.size());
  auto step = [&](double f) {
    std::fill(sum.begin(), sum.end(), Vec3{0, 0, 0});
    std::fill(count.begin(), count.end(), 0);
    for (const MeshEdge &e : edges) {
      sum[e.a] = hull::add(sum[e.a], vertices[e.b]);
      sum[e.b] = hull::add(sum[e.b], vertices[e.a]);
      ++count[e.a], ++count[e.b];
    }
    for (std::size_t i = 0; i < vertices.size(); ++i)
      if (count[i] > 0)
        vertices[i] = hull::add(vertices[i], hull::scaled(hull::sub(hull::scaled(sum[i], 1.0 / count[i]), vertices[i]), f));
  };
  for (int k = 0; k < iterations; ++k) {
    step(lambda);
    step(mu);
  }
  update();
}

double HullMesh::volume() const
{
  double v = 0;
  for (const auto &t : triangles)
    v += hull::dot(vertices[t[0]], hull::cross(vertices[t[1]], vertices[t[2]]));
  return v / 6.0;
}

namespace {

//! An integral \e x as an int within [-1, n]: outside the image's n pixels it only matters on which side (NaN: -1).
inline int toPixelRange(double x, int n)
{
  return x > n ? n : x >= -1 ? static_cast<int>(x) : -1;
}

} // namespace

void HullMesh::depthMap(const core::PinholeCamera::Projection &cam, std::vector<float> &zbuf) const
{
  std::vector<Projected> scratch;
  depthMap(cam, zbuf, scratch);
}

void HullMesh::depthMap(const core::PinholeCamera::Projection &cam, std::vector<float> &zbuf, std::vector<Projected> &scratch) const
{
  zbuf.assign(static_cast<std::size_t>(cam.w) * static_cast<std::size_t>(cam.h), std::numeric_limits<float>::infinity());
  scratch.resize(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    Projected &q = scratch[i];
    q.ok = cam.project(vertices[i], q.u, q.v, q.z);
    if (!q.ok)
      continue;
    q.iz = 1.0 / q.z; // once a vertex, not once for each of its triangles
    q.cu = toPixelRange(std::ceil(q.u), cam.w), q.fu = toPixelRange(std::floor(q.u), cam.w);
    q.cv = toPixelRange(std::ceil(q.v), cam.h), q.fv = toPixelRange(std::floor(q.v), cam.h);
  }
  // The faces are about a pixel across (pm-bench's Model_DepthMap: 137k faces, 80 % of their boxes
  // hold a pixel centre, 1.4 centres tested a face), so each face's set-up is much of the time: its
  // box comes from the vertices' integers, before any floating-point work (4.03 -> 3.14 ms there).
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const Projected &p0 = scratch[triangles[f][0]], &p1 = scratch[triangles[f][1]], &p2 = scratch[triangles[f][2]];
    if (!p0.ok || !p1.ok || !p2.ok)
      continue;
    // ceil(min u) = min ceil(u), floor(max u) = max floor(u): the box from the vertices' integers.
    const int x0 = std::max(0, std::min({p0.cu, p1.cu, p2.cu})), x1 = std::min(cam.w - 1, std::max({p0.fu, p1.fu, p2.fu}));
    if (x0 > x1)
      continue;
    const int y0 = std::max(0, std::min({p0.cv, p1.cv, p2.cv})), y1 = std::min(cam.h - 1, std::max({p0.fv, p1.fv, p2.fv}));
    if (y0 > y1)
      continue;
    const double u[3] = {p0.u, p1.u, p2.u}, v[3] = {p0.v, p1.v, p2.v};
    const double area = (u[1] - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (v[1] - v[0]);
    if (std::fabs(area) < 1e-12)
      continue;
    const double inv = 1.0 / area, iz[3] = {p0.iz, p1.iz, p2.iz};
    for (int y = y0; y <= y1; ++y) {
      float *row = zbuf.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(cam.w);
      for (int x = x0; x <= x1; ++x) {
        // Barycentric weights of the pixel centre (x, y); inside when all of one sign as the area's.
        const double w0 = ((u[1] - x) * (v[2] - y) - (u[2] - x) * (v[1] - y)) * inv;
        const double w1 = ((u[2] - x) * (v[0] - y) - (u[0] - x) * (v[2] - y)) * inv;
        const double w2 = 1.0 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0)
          continue;
        const float d = static_cast<float>(1.0 / (w0 * iz[0] + w1 * iz[1] + w2 * iz[2])); // perspective-correct depth
        row[x] = std::min(row[x], d);
      }
    }
  }
}

HullMesh HullMesh::decimated(double cellMm) const
{
  HullMesh out;
  if (!(cellMm > 0) || vertices.empty())
    return out;
  std::unordered_map<std::uint64_t, std::uint32_t> cluster;
  std::vector<std::uint32_t> of(vertices.size());
  std::vector<int> count;
  auto key = [cellMm](const Vec3 &v) {
    auto c = [cellMm](double x) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(x / cellMm)) + (1 << 20)) & 0x1FFFFF; };
    return (c(v[0]) << 42) | (c(v[1]) << 21) | c(v[2]);
  };
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto it = cluster.emplace(key(vertices[i]), static_cast<std::uint32_t>(out.vertices.size()));
    if (it.second) {
      out.vertices.push_back({0, 0, 0});
      count.push_back(0);
    }
    of[i] = it.first->second;
    out.vertices[of[i]] = hull::add(out.vertices[of[i]], vertices[i]);
    ++count[of[i]];
  }
  for (std::size_t k = 0; k < out.vertices.size(); ++k)
    out.vertices[k] = hull::scaled(out.vertices[k], 1.0 / count[k]);
  for (const auto &t : triangles) {
    const std::array<std::uint32_t, 3> d{of[t[0]], of[t[1]], of[t[2]]};
    if (d[0] != d[1] && d[1] != d[2] && d[0] != d[2])
      out.triangles.push_back(d);
  }
  // Two triangles over the same three vertices (a fold the merge made) are dropped together.
  std::unordered_map<std::uint64_t, int> seen;
  auto triKey = [](std::array<std::uint32_t, 3> t) {
    std::sort(t.begin(), t.end());
    return (static_cast<std::uint64_t>(t[0]) << 42) ^ (static_cast<std::uint64_t>(t[1]) << 21) ^ t[2];
  };
  for (const auto &t : out.triangles)
    ++seen[triKey(t)];
  std::vector<std::array<std::uint32_t, 3>> kept;
  for (const auto &t : out.triangles)
    if (seen[triKey(t)] == 1)
      kept.push_back(t);
  out.triangles.swap(kept);
  out.update();
  return out;
}

HullMesh meshVisualHull(const VisualHull &g, const std::vector<const hull::HullView *> &cams)
{
  return meshField(g, [&](int x, int y, int z) { return hull::field(cams, g.corner(x, y, z)); });
}

} // namespace pm::model
