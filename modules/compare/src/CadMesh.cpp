#include "pm/compare/CadMesh.h"

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

} // namespace pm::compare
