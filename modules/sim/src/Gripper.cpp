#include "pm/sim/Gripper.h"

#include <algorithm>
#include <memory>

#include "pm/core/Error.h"

namespace pm::sim {

void GripperParams::validate() const
{
  if (!(spacingMm > fingerWidthMm && fingerWidthMm > 0 && fingerThicknessMm > 0))
    throw core::Error("gripper: the fingers' width and thickness must be positive and their spacing more than their width");
  if (!(baseMm > 0 && tipMm > baseMm + 30 && tipMm <= 2000 && belowMm >= -1000 && belowMm <= 1000))
    throw core::Error("gripper: the fingers must run forward, 0 < base < tip - 30 mm, tip <= 2000 mm, |below| <= 1000 mm");
}

namespace {

// Texels 0-7 of a row: brushed dark-grey aluminium; 8-15: black rubber.
constexpr float kMetalS0 = 1, kMetalS1 = 6, kPadS0 = 9, kPadS1 = 14;

std::shared_ptr<Texture> gripperTexture()
{
  return speckledTexture(16, 16, 11, 0.9, 0.2, [](int i, int) {
    return i >= 8 ? std::array<double, 3>{28, 28, 30} : std::array<double, 3>{104, 106, 112};
  });
}

//! Appends the quad a, b, c, d (mm, counter-clockwise or not: shading is two-sided) of normal n, textured from s0 to s1.
void addQuad(Mesh &m, const double a[3], const double b[3], const double c[3], const double d[3], const double n[3], float s0, float s1)
{
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  const double *p[4] = {a, b, c, d};
  const float s[4] = {s0, s1, s1, s0}, t[4] = {1, 1, 14, 14};
  for (int k = 0; k < 4; ++k)
    m.vertices.push_back({static_cast<float>(p[k][0] * 1e-3), static_cast<float>(p[k][1] * 1e-3), static_cast<float>(p[k][2] * 1e-3),
                          static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2]), s[k], t[k], -1});
  m.triangles.push_back({base, base + 1, base + 2});
  m.triangles.push_back({base, base + 2, base + 3});
}

//! One finger: a box [x0, x1] x [y0, y1] x [z0, z1] (mm); its face toward x = \e padSide (+1 or -1) has a pad from padFromZ on.
void addFinger(Mesh &m, double x0, double x1, double y0, double y1, double z0, double z1, int padSide, double padFromZ)
{
  const double nxm[3] = {-1, 0, 0}, nxp[3] = {1, 0, 0}, nym[3] = {0, -1, 0}, nyp[3] = {0, 1, 0}, nzm[3] = {0, 0, -1}, nzp[3] = {0, 0, 1};
  auto side = [&](double x, const double *n, bool pad) { // a face at constant x, split where the pad starts
    const double zs = pad ? padFromZ : z1;
    const double a[3] = {x, y0, z0}, b[3] = {x, y0, zs}, c[3] = {x, y1, zs}, d[3] = {x, y1, z0};
    addQuad(m, a, b, c, d, n, kMetalS0, kMetalS1);
    if (pad) {
      const double e[3] = {x, y0, zs}, f[3] = {x, y0, z1}, g[3] = {x, y1, z1}, h[3] = {x, y1, zs};
      addQuad(m, e, f, g, h, n, kPadS0, kPadS1);
    }
  };
  side(x0, nxm, padSide < 0);
  side(x1, nxp, padSide > 0);
  const double a[3] = {x0, y0, z0}, b[3] = {x1, y0, z0}, c[3] = {x1, y0, z1}, d[3] = {x0, y0, z1};
  addQuad(m, a, b, c, d, nym, kMetalS0, kMetalS1); // top
  const double e[3] = {x0, y1, z0}, f[3] = {x1, y1, z0}, g[3] = {x1, y1, z1}, h[3] = {x0, y1, z1};
  addQuad(m, e, f, g, h, nyp, kMetalS0, kMetalS1); // bottom
  addQuad(m, a, b, f, e, nzm, kMetalS0, kMetalS1); // the base's end
  addQuad(m, d, c, g, h, nzp, kMetalS0, kMetalS1); // the tip, facing the target
}

} // namespace

Mesh makeGripperMesh(const GripperParams &params)
{
  params.validate();
  Mesh m;
  m.texture = gripperTexture();
  m.specular = 0.25f;
  m.shininess = 30.f;
  const double hw = params.fingerWidthMm / 2, ht = params.fingerThicknessMm / 2, c = params.spacingMm / 2;
  const double y0 = params.belowMm - ht, y1 = params.belowMm + ht, padFrom = params.tipMm - 30;
  addFinger(m, -c - hw, -c + hw, y0, y1, params.baseMm, params.tipMm, +1, padFrom); // the left finger, its pad facing right
  addFinger(m, c - hw, c + hw, y0, y1, params.baseMm, params.tipMm, -1, padFrom);   // the right finger, its pad facing left
  return m;
}

} // namespace pm::sim
