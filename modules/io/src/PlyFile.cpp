#include "pm/io/PlyFile.h"

#include <sstream>

namespace pm::io {

std::string plyText(const std::vector<model::SurfacePoint> &surface, const model::HullMesh *mesh)
{
  const bool faces = mesh && mesh->vertices.size() == surface.size();
  std::ostringstream s;
  s << "ply\nformat ascii 1.0\ncomment visp-photomodel all-around surface, model frame, mm\nelement vertex " << surface.size()
    << "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
       "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (faces)
    s << "element face " << mesh->triangles.size() << "\nproperty list uchar int vertex_indices\n";
  s << "end_header\n";
  for (const model::SurfacePoint &p : surface)
    s << p.x << ' ' << p.y << ' ' << p.z << ' ' << p.nx << ' ' << p.ny << ' ' << p.nz << ' ' << int(p.r) << ' ' << int(p.g)
      << ' ' << int(p.b) << '\n';
  if (faces)
    for (const auto &t : mesh->triangles)
      s << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return s.str();
}

} // namespace pm::io
