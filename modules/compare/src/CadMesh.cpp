#include "pm/compare/CadMesh.h"

#include <cmath>
#include <map>
#include <tuple>

#include "pm/compare/OutlineModel.h"

namespace pm::compare {

std::string meshCaoText(const model::HullMesh &mesh, const std::string &comment)
{
  std::vector<std::array<double, 3>> pointsM;
  pointsM.reserve(mesh.vertices.size());
  for (const model::hull::Vec3 &v : mesh.vertices)
    pointsM.push_back({1e-3 * v[0], 1e-3 * v[1], 1e-3 * v[2]});
  std::vector<std::vector<std::size_t>> faces;
  faces.reserve(mesh.triangles.size());
  for (const auto &t : mesh.triangles)
    faces.push_back({static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]), static_cast<std::size_t>(t[2])});
  return caoText(pointsM, faces, comment);
}

namespace {

//! A toy mesh's vertex as the CAD model takes it: position (mm), outward normal, the outline mask.
struct CadVertex
{
  model::hull::Vec3 X, n;
  double mask;
};

CadVertex between(const CadVertex &a, const CadVertex &b)
{
  const double t = a.mask / (a.mask - b.mask); // where the mask crosses 0
  auto mix = [t](const model::hull::Vec3 &p, const model::hull::Vec3 &q) {
    return model::hull::Vec3{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2])};
  };
  return {mix(a.X, b.X), mix(a.n, b.n), 0.0};
}

//! The vertices of \e mesh, one per position (to a micrometre).
class Welder
{
public:
  explicit Welder(model::HullMesh &mesh) : m_mesh(mesh) {}
  std::uint32_t at(const model::hull::Vec3 &X)
  {
    const auto key = std::make_tuple(std::lround(X[0] * 1e3), std::lround(X[1] * 1e3), std::lround(X[2] * 1e3));
    const auto it = m_index.find(key);
    if (it != m_index.end())
      return it->second;
    const auto i = static_cast<std::uint32_t>(m_mesh.vertices.size());
    m_mesh.vertices.push_back(X);
    m_index.emplace(key, i);
    return i;
  }

private:
  model::HullMesh &m_mesh;
  std::map<std::tuple<long, long, long>, std::uint32_t> m_index;
};

} // namespace

model::HullMesh toyCadMesh(const sim::Mesh &toy)
{
  model::HullMesh m;
  Welder weld(m);
  for (const auto &t : toy.triangles) {
    // The triangle's part inside the toy's outline (the mask <= 0 where the renderer keeps fragments).
    std::vector<CadVertex> in, poly;
    for (std::uint32_t k : t) {
      const sim::MeshVertex &v = toy.vertices[k];
      in.push_back({{1e3 * v.x, 1e3 * v.y, 1e3 * v.z}, {v.nx, v.ny, v.nz}, toy.useMask ? static_cast<double>(v.mask) : -1.0});
    }
    for (std::size_t k = 0; k < 3; ++k) {
      const CadVertex &a = in[k], &b = in[(k + 1) % 3];
      if (a.mask <= 0)
        poly.push_back(a);
      if ((a.mask <= 0) != (b.mask <= 0))
        poly.push_back(between(a, b));
    }
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) { // a fan: a triangle or a quad
      std::array<std::uint32_t, 3> f{weld.at(poly[0].X), weld.at(poly[k].X), weld.at(poly[k + 1].X)};
      if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
        continue;
      const model::hull::Vec3 n = model::hull::cross(model::hull::sub(m.vertices[f[1]], m.vertices[f[0]]), model::hull::sub(m.vertices[f[2]], m.vertices[f[0]]));
      const model::hull::Vec3 out = model::hull::add(model::hull::add(poly[0].n, poly[k].n), poly[k + 1].n);
      if (model::hull::dot(n, out) < 0)
        std::swap(f[1], f[2]);
      m.triangles.push_back(f);
    }
  }
  m.update();
  return m;
}

} // namespace pm::compare
