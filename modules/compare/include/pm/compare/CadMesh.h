#pragma once
/*!
  \file CadMesh.h
  The all-around photo-model's surface as a CAD model for ViSP's model-based trackers
  (vpMbGenericTracker): the mesh the model was built with (AllAroundBuild::mesh, model frame),
  decimated to a few hundred faces, written in ViSP's .cao format (metres; faces from 3-D points,
  counter-clockwise seen from outside). pm-compare gives it to ViSP's trackers on 3-D targets, so
  that they and ours follow the same shape (the paper's flat outline is the alternative).

      const std::string cao = pm::compare::meshCaoText(build.mesh.decimated(6.0), "C12, all-around surface");
*/
#include <string>

#include "pm/model/HullMesh.h"

namespace pm::compare {

/*!
  \e mesh (mm, model frame) as a ViSP .cao model (metres), every triangle a face from its 3-D points;
  \e comment goes on the second line.
  \code
  std::ofstream("model.cao") << pm::compare::meshCaoText(build.mesh.decimated(6.0), "all-around surface");
  \endcode
*/
std::string meshCaoText(const model::HullMesh &mesh, const std::string &comment);

} // namespace pm::compare
