#pragma once
/*!
  \file ShadowMap.h
  A shadow map for a directional light fixed in an object frame (the target frame of the scene):
  the depth of a mesh (the toy) along the light, rasterised once in an orthographic projection
  across the light's direction. A point of the same frame is in shadow where something of the
  mesh lies between it and the light, i.e. where its depth along the light exceeds the map's
  (nearest) depth at its place by more than a bias.

  Map coordinates of a point P (metres, object frame): u = (P . eu - u0) / texel,
  v = (P . ev - v0) / texel (texel centres at integers), depth = P . ed, where ed is the
  direction the light travels (away from the light) and (eu, ev, ed) is orthonormal. All three
  are affine in P, so the renderer interpolates them like any other attribute.

  Immutable once built; safe to read from several threads.
*/
#include <cstdint>
#include <vector>

#include "pm/sim/Mesh.h"

namespace pm::sim {

/*!
  The depth map of a mesh along a directional light, for cast shadows (see ShadowMap.h). Made once
  (Scene::shadowMap() builds and keeps the toy's), then handed to the renderer through
  Lighting::shadow, which does not own it.
*/
class ShadowMap
{
public:
  /*!
    Rasterises the depth of \e mesh (fragments cut by its mask where it uses one) seen along the
    light that comes from direction \e towardLight (object frame, normalised here), with square
    texels of \e texelM metres, over the mesh's extent plus \e marginM. The map is limited to
    4096 x 4096 texels (the texel grows if needed). Throws pm::core::Error for a zero direction, a
    non-positive texel or an empty mesh.
  */
  ShadowMap(const Mesh &mesh, const double towardLight[3], double texelM, double marginM = 2e-3);

  //! Map coordinates (texels, texels, metres along the light) of an object-frame point (metres).
  inline void project(double x, double y, double z, double &u, double &v, double &depth) const
  {
    u = (x * m_eu[0] + y * m_eu[1] + z * m_eu[2] - m_u0) / m_texel;
    v = (x * m_ev[0] + y * m_ev[1] + z * m_ev[2] - m_v0) / m_texel;
    depth = x * m_ed[0] + y * m_ed[1] + z * m_ed[2];
  }

  /*!
    Fraction of light (0 in shadow .. 1 lit) at map coordinates (u, v) for a surface at \e depth
    (bias already subtracted): the four nearest texels compared with \e depth, weighted bilinearly
    (percentage-closer filtering: soft, anti-aliased shadow edges). 1 outside the map.
  */
  inline float visibility(float u, float v, float depth) const
  {
    if (!(u >= 0.f && v >= 0.f && u < m_maxU && v < m_maxV))
      return 1.f;
    const int i = static_cast<int>(u), j = static_cast<int>(v);
    const float a = u - static_cast<float>(i), b = v - static_cast<float>(j);
    const float *p = &m_depth[static_cast<std::size_t>(j) * static_cast<std::size_t>(m_cols) + static_cast<std::size_t>(i)];
    const float l00 = depth <= p[0] ? 1.f : 0.f, l10 = depth <= p[1] ? 1.f : 0.f;
    const float l01 = depth <= p[m_cols] ? 1.f : 0.f, l11 = depth <= p[m_cols + 1] ? 1.f : 0.f;
    const float top = l00 + a * (l10 - l00), bot = l01 + a * (l11 - l01);
    return top + b * (bot - top);
  }

  //! Nearest depth (metres along the light) stored at texel (i, j), 0 \<= i \< cols(), 0 \<= j \< rows() (not checked); +infinity where the mesh is absent.
  float depthAt(int i, int j) const { return m_depth[static_cast<std::size_t>(j) * static_cast<std::size_t>(m_cols) + static_cast<std::size_t>(i)]; }
  int cols() const { return m_cols; } //!< map width (texels, along eu)
  int rows() const { return m_rows; } //!< map height (texels, along ev)
  double texel() const { return m_texel; } //!< texel size (metres)
  //! Unit vector toward the light (object frame).
  const double *towardLight() const { return m_toward; }

private:
  double m_eu[3], m_ev[3], m_ed[3], m_toward[3];
  double m_u0 = 0, m_v0 = 0, m_texel = 1e-3;
  int m_cols = 0, m_rows = 0;
  float m_maxU = 0, m_maxV = 0; // last position with a right/bottom neighbour
  std::vector<float> m_depth;
};

} // namespace pm::sim
