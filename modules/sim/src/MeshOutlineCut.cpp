#include "pm/sim/MeshOutlineCut.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace pm::sim {

namespace {

//! The vertex where the mask crosses 0 on the edge a-b (the masks of a and b have opposite signs).
MeshVertex crossing(const MeshVertex &a, const MeshVertex &b)
{
  const float t = a.mask / (a.mask - b.mask);
  auto mix = [t](float p, float q) { return p + t * (q - p); };
  MeshVertex v;
  v.x = mix(a.x, b.x);
  v.y = mix(a.y, b.y);
  v.z = mix(a.z, b.z);
  v.nx = mix(a.nx, b.nx);
  v.ny = mix(a.ny, b.ny);
  v.nz = mix(a.nz, b.nz);
  const float n = std::sqrt(v.nx * v.nx + v.ny * v.ny + v.nz * v.nz);
  if (n > 0) {
    v.nx /= n;
    v.ny /= n;
    v.nz /= n;
  }
  v.s = mix(a.s, b.s);
  v.t = mix(a.t, b.t);
  v.mask = 0;
  return v;
}

} // namespace

Mesh cutAlongOutline(const Mesh &mesh)
{
  if (!mesh.useMask)
    return mesh;
  Mesh out;
  out.texture = mesh.texture;
  out.specular = mesh.specular;
  out.shininess = mesh.shininess;
  out.useMask = false;
  std::vector<std::int64_t> kept(mesh.vertices.size(), -1);
  // A vertex inside is kept once; a crossing is made once per edge (shared by the edge's two triangles).
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> crossings;
  auto inside = [&](std::uint32_t i) -> std::uint32_t {
    if (kept[i] < 0) {
      MeshVertex v = mesh.vertices[i];
      v.mask = std::min(v.mask, 0.f);
      kept[i] = static_cast<std::int64_t>(out.vertices.size());
      out.vertices.push_back(v);
    }
    return static_cast<std::uint32_t>(kept[i]);
  };
  auto edge = [&](std::uint32_t a, std::uint32_t b) -> std::uint32_t {
    const auto key = a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    const auto it = crossings.find(key);
    if (it != crossings.end())
      return it->second;
    const auto id = static_cast<std::uint32_t>(out.vertices.size());
    out.vertices.push_back(crossing(mesh.vertices[key.first], mesh.vertices[key.second]));
    crossings.emplace(key, id);
    return id;
  };
  for (const auto &tri : mesh.triangles) {
    // The polygon of the triangle's inside part, in the triangle's own order (Sutherland-Hodgman, one plane).
    std::uint32_t poly[4];
    int n = 0;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri[static_cast<std::size_t>(k)], b = tri[static_cast<std::size_t>((k + 1) % 3)];
      const bool aIn = mesh.vertices[a].mask <= 0, bIn = mesh.vertices[b].mask <= 0;
      if (aIn)
        poly[n++] = inside(a);
      if (aIn != bIn)
        poly[n++] = edge(a, b);
    }
    for (int k = 1; k + 1 < n; ++k)
      out.triangles.push_back({poly[0], poly[k], poly[k + 1]});
  }
  return out;
}

} // namespace pm::sim
