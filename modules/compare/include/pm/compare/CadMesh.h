#pragma once
/*!
  \file CadMesh.h
  The all-around photo-model's surface as a CAD model for ViSP's model-based trackers
  (vpMbGenericTracker): the mesh the model was built with (AllAroundBuild::mesh, model frame),
  decimated to a few hundred faces, written in ViSP's .cao format (metres; faces from 3-D points,
  counter-clockwise seen from outside). pm-compare gives it to ViSP's trackers on 3-D targets, so
  that they and ours follow the same shape (the paper's flat outline is the alternative); or, with
  `--mbt-true-cad`, the toy's own mesh (the lab knows it), decimated the same way: ours from photos
  against ViSP with the exact CAD model, as a ViSP user with the object's drawings would run it.

  \code
      const std::string cao = pm::compare::meshCaoText(build.mesh.decimated(6.0), "C12, all-around surface");
      const std::string exact = pm::compare::meshCaoText(pm::compare::toyCadMesh(pm::sim::buildTargetMesh(target, 1.0)).decimated(6.0), "C12, true");
  \endcode
*/
#include <string>

#include "pm/model/HullMesh.h"
#include "pm/sim/Mesh.h"

namespace pm::compare {

/*!
  \e mesh (mm, model frame) as a ViSP .cao model (metres), every triangle a face from its 3-D points;
  \e comment goes on the second line.
  \code
  std::ofstream("model.cao") << pm::compare::meshCaoText(build.mesh.decimated(6.0), "all-around surface");
  \endcode
*/
std::string meshCaoText(const model::HullMesh &mesh, const std::string &comment);

/*!
  The renderer's mesh of a toy (metres, the toy's object frame) as a HullMesh (mm, the same frame):
  each triangle cut along the toy's outline where the renderer cuts its fragments (Mesh::useMask,
  the mask interpolated linearly), turned to face out (as its vertices' normals do), its vertices
  welded where they coincide (a texture's seams, the cuts). For decimated() and meshCaoText().
*/
model::HullMesh toyCadMesh(const sim::Mesh &toy);

} // namespace pm::compare
