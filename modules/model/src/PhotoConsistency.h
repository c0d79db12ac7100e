#pragma once
/*!
  \file PhotoConsistency.h
  Stage 5 of the all-around build without fusion (private to the builder, AllAroundModelBuilder.h):
  a hull carved from a cap of directions bulges in front of flat and concave faces, which no
  silhouette carves; where the target has texture, the cameras' 5x5 patches agree best at the true
  depth, so each point moves inward along its normal to where they do.
*/
#include <cstdint>
#include <vector>

#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/HullGeometry.h"

namespace pm::model {

/*!
  Moves each surface point seen by 3 or more cameras inward along its normal, by whole cells up to
  refineDepthMm, to where the mean correlation of each camera's patch with the others' mean is
  highest, when that is clearly better than at the hull (by refineMinGain) and good in itself
  (refineMinScore). Returns the number of points moved.
*/
int refineByPhotoConsistency(const std::vector<const hull::HullView *> &cams, const std::vector<std::vector<std::uint16_t>> &seenBy,
                             const std::vector<hull::Vec3> &normals, const AllAroundParams &p, double cell, std::vector<hull::Vec3> &pts);

} // namespace pm::model
