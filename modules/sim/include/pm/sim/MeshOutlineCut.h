#pragma once
/*!
  \file MeshOutlineCut.h
  A toy's mesh cut along its outline: the renderer keeps a fragment where the interpolated mask is
  <= 0 (Mesh.h), and another renderer (Blender's Cycles, scripts/cycles/) needs that outline as
  geometry. Each triangle is clipped by the plane mask = 0 of its own linear mask: a triangle
  wholly inside is kept, one wholly outside dropped, one across the outline becomes the one or two
  triangles of its inside part, their new vertices interpolated linearly (position, normal,
  texture coordinates) where the mask crosses 0. The fragments the rasterizer keeps are exactly
  the cut mesh's.

  \code
    const pm::sim::Mesh toy = pm::sim::buildTargetMesh(pm::sim::makeTarget("C12"));
    const pm::sim::Mesh cut = pm::sim::cutAlongOutline(toy); // cut.useMask is false
  \endcode
*/
#include "pm/sim/Mesh.h"

namespace pm::sim {

//! \e mesh cut along its outline (see the file's description); a mesh without a mask is returned as it is.
Mesh cutAlongOutline(const Mesh &mesh);

} // namespace pm::sim
