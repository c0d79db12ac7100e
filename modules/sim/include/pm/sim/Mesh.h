#pragma once
/*!
  \file Mesh.h
  A textured triangle mesh for the renderer: positions in metres in the object frame,
  texture coordinates in texels, and a mask value per vertex: fragments where the
  interpolated mask is positive are discarded, which cuts a smooth outline out of a
  regular grid (the mask is the signed distance to the target's outline).
*/
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace pm::sim {

/*!
  An RGB texture, 8 bits per channel, row-major, sampled bilinearly. Meshes hold theirs through a
  std::shared_ptr to const (Mesh::texture), so that one texture serves several meshes.
*/
struct Texture
{
  //! Width in texels.
  int width = 0, height = 0; //!< height in texels
  std::vector<std::uint8_t> rgb; //!< 3 * width * height

  //! Bilinear sample at texel coordinates (texel centres at integers), clamped; out in [0, 1].
  inline void sample(float s, float t, float out[3]) const
  {
    s = std::min(std::max(s, 0.f), static_cast<float>(width - 1));
    t = std::min(std::max(t, 0.f), static_cast<float>(height - 1));
    const int i = std::min(static_cast<int>(s), width - 2 < 0 ? 0 : width - 2);
    const int j = std::min(static_cast<int>(t), height - 2 < 0 ? 0 : height - 2);
    const float a = s - static_cast<float>(i), b = t - static_cast<float>(j);
    const int di = width > 1 ? 3 : 0, dj = height > 1 ? 3 * width : 0;
    const std::uint8_t *p = &rgb[3 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(width) + static_cast<std::size_t>(i))];
    for (int c = 0; c < 3; ++c) {
      const float top = p[c] + a * (static_cast<float>(p[c + di]) - p[c]);
      const float bot = p[c + dj] + a * (static_cast<float>(p[c + dj + di]) - p[c + dj]);
      out[c] = (top + b * (bot - top)) * (1.f / 255.f);
    }
  }
};

/*!
  One vertex of a Mesh: position and normal in the object frame, texture coordinates and the
  outline mask (see Mesh.h).
*/
struct MeshVertex
{
  //! Position in the object frame (m): x (y and z likewise).
  float x, y, z;    //!< position in the object frame (m): z
  //! Unit normal in the object frame: x component (the top of a toy and the backdrop face -z, a toy's underside +z).
  float nx, ny, nz; //!< unit normal in the object frame: z component (shading is two-sided)
  //! Texture coordinate along the texture's width (texels, texel centres at integers).
  float s, t;       //!< texture coordinate along the texture's height (texels)
  float mask;       //!< fragment kept where the interpolated mask is <= 0 (when Mesh::useMask)
  /*!
    \var MeshVertex::y
      Position in the object frame (m): y.
    \var MeshVertex::ny
      Unit normal in the object frame: y component.
  */
};

/*!
  A textured triangle mesh, drawn by Rasterizer::draw() and Rasterizer::render() and, for cast
  shadows, rasterised by ShadowMap. Vertices are in the object frame, in metres; a mesh owns its
  vertices and triangles and shares its (immutable) texture. Made by buildTargetMesh() (a toy)
  and makeBackdropMesh() (the sea-bottom panel).
*/
struct Mesh
{
  std::vector<MeshVertex> vertices;                     //!< the vertices (object frame, metres)
  std::vector<std::array<std::uint32_t, 3>> triangles; //!< vertex indices of each triangle
  std::shared_ptr<const Texture> texture;               //!< the texture (required to draw; shared, immutable)
  bool useMask = false;  //!< discard fragments by mask
  float specular = 0.f;  //!< specular strength (glossy plastic of a toy); 0 = matte
  float shininess = 20.f; //!< Blinn-Phong exponent of the highlight
};

/*!
  A width x height texture of the colour \e colourAt(i, j) (r, g, b in [0, 255]) speckled by the
  lattice noise of \e seed: each texel its colour times lo + amp * latticeValue(i, j, seed), at most
  255 (the flat quads' and the gripper's a little textured surfaces).
  \code
  auto olive = pm::sim::speckledTexture(8, 64, 5, 0.8, 0.4, [](int, int) { return std::array<double, 3>{60, 120, 40}; });
  \endcode
*/
std::shared_ptr<Texture> speckledTexture(int width, int height, std::uint64_t seed, double lo, double amp,
                                         const std::function<std::array<double, 3>(int i, int j)> &colourAt);

} // namespace pm::sim
