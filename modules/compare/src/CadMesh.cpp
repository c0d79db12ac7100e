#include "pm/compare/CadMesh.h"

#include <cstdio>
#include <sstream>

namespace pm::compare {

std::string meshCaoText(const HullMesh &mesh, const std::string &comment)
{
  std::ostringstream s;
  s << "V1\n# " << comment << "\n# 3D points\n" << mesh.vertices.size() << "\n";
  char buf[96];
  for (const hull::Vec3 &v : mesh.vertices) {
    std::snprintf(buf, sizeof buf, "%.6f %.6f %.6f\n", 1e-3 * v[0], 1e-3 * v[1], 1e-3 * v[2]);
    s << buf;
  }
  s << "# 3D lines\n0\n# Faces from 3D lines\n0\n# Faces from 3D points\n" << mesh.triangles.size() << "\n";
  for (const auto &t : mesh.triangles)
    s << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  s << "# 3D cylinders\n0\n# 3D circles\n0\n";
  return s.str();
}

} // namespace pm::compare
