#include "pm/sim/ShadowMap.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pm/core/Error.h"

namespace pm::sim {

ShadowMap::ShadowMap(const Mesh &mesh, const double towardLight[3], double texelM, double marginM)
{
  const double n = std::sqrt(towardLight[0] * towardLight[0] + towardLight[1] * towardLight[1] + towardLight[2] * towardLight[2]);
  if (!(n > 0) || !std::isfinite(n))
    throw core::Error("shadow map: the light direction must be a non-zero vector");
  if (!(texelM > 0) || !(marginM >= 0))
    throw core::Error("shadow map: the texel must be positive and the margin non-negative");
  if (mesh.vertices.empty() || mesh.triangles.empty())
    throw core::Error("shadow map: empty mesh");
  for (int i = 0; i < 3; ++i) {
    m_toward[i] = towardLight[i] / n;
    m_ed[i] = -m_toward[i];
  }
  // eu: the object x axis made orthogonal to ed (or y when x is nearly along the light); ev = ed x eu.
  const double ax[3] = {std::fabs(m_ed[0]) < 0.9 ? 1.0 : 0.0, std::fabs(m_ed[0]) < 0.9 ? 0.0 : 1.0, 0.0};
  const double dot = ax[0] * m_ed[0] + ax[1] * m_ed[1] + ax[2] * m_ed[2];
  for (int i = 0; i < 3; ++i)
    m_eu[i] = ax[i] - dot * m_ed[i];
  const double un = std::sqrt(m_eu[0] * m_eu[0] + m_eu[1] * m_eu[1] + m_eu[2] * m_eu[2]);
  for (double &c : m_eu)
    c /= un;
  m_ev[0] = m_ed[1] * m_eu[2] - m_ed[2] * m_eu[1];
  m_ev[1] = m_ed[2] * m_eu[0] - m_ed[0] * m_eu[2];
  m_ev[2] = m_ed[0] * m_eu[1] - m_ed[1] * m_eu[0];

  // Extent across the light.
  double u0 = 1e30, u1 = -1e30, v0 = 1e30, v1 = -1e30;
  for (const auto &p : mesh.vertices) {
    const double u = p.x * m_eu[0] + p.y * m_eu[1] + p.z * m_eu[2];
    const double v = p.x * m_ev[0] + p.y * m_ev[1] + p.z * m_ev[2];
    u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
  }
  constexpr int kMax = 4096;
  m_texel = std::max(texelM, std::max(u1 - u0, v1 - v0) / (kMax - 8) + 1e-12);
  m_u0 = u0 - marginM - m_texel;
  m_v0 = v0 - marginM - m_texel;
  m_cols = static_cast<int>(std::ceil((u1 - u0 + 2 * marginM) / m_texel)) + 3;
  m_rows = static_cast<int>(std::ceil((v1 - v0 + 2 * marginM) / m_texel)) + 3;
  m_maxU = static_cast<float>(m_cols - 1);
  m_maxV = static_cast<float>(m_rows - 1);
  m_depth.assign(static_cast<std::size_t>(m_cols) * static_cast<std::size_t>(m_rows), std::numeric_limits<float>::infinity());

  struct P
  {
    double u, v, d, mask;
  };
  std::vector<P> proj(mesh.vertices.size());
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    const MeshVertex &q = mesh.vertices[k];
    project(q.x, q.y, q.z, proj[k].u, proj[k].v, proj[k].d);
    proj[k].mask = q.mask;
  }
  // Orthographic: attributes are linear in (u, v). Texel centres at integers; the nearest depth wins.
  for (const auto &tri : mesh.triangles) {
    const P &a = proj[tri[0]], &b = proj[tri[1]], &c = proj[tri[2]];
    const double area = (b.u - a.u) * (c.v - a.v) - (c.u - a.u) * (b.v - a.v);
    if (std::fabs(area) < 1e-12)
      continue;
    const int i0 = std::max(0, static_cast<int>(std::ceil(std::min({a.u, b.u, c.u}))));
    const int i1 = std::min(m_cols - 1, static_cast<int>(std::floor(std::max({a.u, b.u, c.u}))));
    const int j0 = std::max(0, static_cast<int>(std::ceil(std::min({a.v, b.v, c.v}))));
    const int j1 = std::min(m_rows - 1, static_cast<int>(std::floor(std::max({a.v, b.v, c.v}))));
    const double inv = 1.0 / area;
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const double x = i, y = j;
        const double wa = ((b.u - x) * (c.v - y) - (c.u - x) * (b.v - y)) * inv;
        const double wb = ((c.u - x) * (a.v - y) - (a.u - x) * (c.v - y)) * inv;
        const double wc = 1.0 - wa - wb;
        if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9)
          continue;
        if (mesh.useMask && wa * a.mask + wb * b.mask + wc * c.mask > 0)
          continue;
        const float d = static_cast<float>(wa * a.d + wb * b.d + wc * c.d);
        float &o = m_depth[static_cast<std::size_t>(j) * static_cast<std::size_t>(m_cols) + static_cast<std::size_t>(i)];
        o = std::min(o, d);
      }
  }
}

} // namespace pm::sim
