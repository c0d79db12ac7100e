#pragma once
/*!
  \file SeaBottom.h
  The backdrop of the paper's experiments: a sea bottom, blue-dominant, with sand ripples,
  darker rocks, light caustics and a top-to-bottom shading, generated from a seed.
*/
#include <cstdint>
#include <memory>

#include "pm/sim/Mesh.h"

namespace pm::sim {

struct SeaBottomParams
{
  double widthMm = 1600, heightMm = 1200; //!< panel size (covers the views over the search range)
  double texelMm = 0.6;
  std::uint64_t seed = 7;
};

std::shared_ptr<const Texture> makeSeaBottomTexture(const SeaBottomParams &p);
//! The panel as a mesh centred on the target frame's z axis at depth \e zMm, facing -z.
Mesh makeBackdropMesh(std::shared_ptr<const Texture> texture, const SeaBottomParams &p, double zMm);

} // namespace pm::sim
