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

//! The backdrop panel: its size, the resolution of its texture and the seed of its pattern.
struct SeaBottomParams
{
  //! Panel width (mm).
  double widthMm = 1600, heightMm = 1200; //!< panel height (mm); the size covers the views over the search range
  double texelMm = 0.6;   //!< texel size of the texture (mm; > 0.05, at most 40 million texels in all)
  std::uint64_t seed = 7; //!< seed of the pattern (the same seed, the same sea bottom)
};

/*!
  The sea-bottom texture for \e p (widthMm / texelMm x heightMm / texelMm texels, rounded up).
  Deterministic; one texture per parameter set is shared by the whole process while it is in use
  (thread-safe). Throws pm::core::Error for a non-positive size, a texel of 0.05 mm or less, or more
  than 40 million texels.
*/
std::shared_ptr<const Texture> makeSeaBottomTexture(const SeaBottomParams &p);
//! The panel as a mesh centred on the target frame's z axis at depth \e zMm (mm), facing -z; it shares \e texture.
Mesh makeBackdropMesh(std::shared_ptr<const Texture> texture, const SeaBottomParams &p, double zMm);

} // namespace pm::sim
