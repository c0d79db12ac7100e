#pragma once
/*!
  \file PlyFile.h
  The all-around model's surface as an ASCII PLY (model.ply: a coloured point cloud with normals,
  model frame, millimetres; opens in MeshLab or CloudCompare).

  \code
      pm::io::writeTextFile("model.ply", pm::io::plyText(build.surface, &build.mesh));
  \endcode
*/
#include <string>
#include <vector>

#include "pm/model/AllAroundModelBuilder.h"

namespace pm::io {

//! The ASCII PLY of \e surface (x y z nx ny nz red green blue), with \e mesh's triangles when it is the surface's (a vertex per point).
std::string plyText(const std::vector<model::SurfacePoint> &surface, const model::HullMesh *mesh = nullptr);

} // namespace pm::io
