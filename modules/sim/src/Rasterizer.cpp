#include "pm/sim/Rasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pm/core/Error.h"
#include "pm/sim/Noise.h"

namespace pm::sim {

void Rasterizer::reset(unsigned width, unsigned height, unsigned supersampling)
{
  if (width == 0 || height == 0 || supersampling < 1 || supersampling > 4)
    throw Error("renderer: image size must be positive and supersampling in [1, 4]");
  m_w = width;
  m_h = height;
  m_ss = supersampling;
  m_W = width * supersampling;
  m_H = height * supersampling;
  const std::size_t n = static_cast<std::size_t>(m_W) * m_H;
  m_color.assign(3 * n, 0.f);
  m_invDepth.assign(n, 0.f);
  m_id.assign(n, 0);
}

void Rasterizer::clear(float r, float g, float b)
{
  for (std::size_t i = 0; i < m_invDepth.size(); ++i) {
    m_color[3 * i] = r;
    m_color[3 * i + 1] = g;
    m_color[3 * i + 2] = b;
  }
  std::fill(m_invDepth.begin(), m_invDepth.end(), 0.f);
  std::fill(m_id.begin(), m_id.end(), std::uint8_t(0));
}

void Rasterizer::draw(const Mesh &mesh, const vpHomogeneousMatrix &cMo, const vpCameraParameters &cam,
                      const Lighting &light, std::uint8_t id)
{
  if (!mesh.texture || mesh.texture->width <= 0 || mesh.texture->height <= 0)
    throw Error("renderer: mesh without texture");
  const double ss = m_ss;
  const double px = cam.get_px() * ss, py = cam.get_py() * ss;
  const double u0 = cam.get_u0() * ss + (ss - 1) / 2, v0 = cam.get_v0() * ss + (ss - 1) / 2;
  const double zNear = 1e-3;

  // Light and camera centre in the object frame, for per-vertex shading.
  double L[3] = {light.dirCamera[0], light.dirCamera[1], light.dirCamera[2]};
  const double ln = std::sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
  double Lo[3], Co[3];
  const vpHomogeneousMatrix oMc = cMo.inverse();
  for (int i = 0; i < 3; ++i) {
    Lo[i] = 0;
    for (int k = 0; k < 3; ++k)
      Lo[i] += cMo[static_cast<unsigned>(k)][static_cast<unsigned>(i)] * L[k] / ln; // R^T L
    Co[i] = oMc[static_cast<unsigned>(i)][3];
  }

  const ShadowMap *shadow = light.shadow;
  if (shadow) {
    const double *t = shadow->towardLight();
    if (std::fabs(t[0] - Lo[0]) + std::fabs(t[1] - Lo[1]) + std::fabs(t[2] - Lo[2]) > 1e-6)
      throw Error("renderer: the shadow map was made for another light direction");
  }
  const double specK = light.specular >= 0 ? light.specular : static_cast<double>(mesh.specular);
  const double shin = light.shininess >= 0 ? light.shininess : static_cast<double>(mesh.shininess);

  double R[3][4];
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 4; ++j)
      R[i][j] = cMo[i][j];

  m_proj.resize(mesh.vertices.size());
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    const MeshVertex &v = mesh.vertices[k];
    const double X = R[0][0] * v.x + R[0][1] * v.y + R[0][2] * v.z + R[0][3];
    const double Y = R[1][0] * v.x + R[1][1] * v.y + R[1][2] * v.z + R[1][3];
    const double Z = R[2][0] * v.x + R[2][1] * v.y + R[2][2] * v.z + R[2][3];
    ProjVertex &p = m_proj[k];
    p.valid = Z > zNear;
    if (!p.valid)
      continue;
    const double w = 1.0 / Z;
    p.X = static_cast<float>(px * X * w + u0);
    p.Y = static_cast<float>(py * Y * w + v0);
    p.w = static_cast<float>(w);
    // Shading: two-sided Lambert toward the viewer, Blinn-Phong highlight.
    double n[3] = {v.nx, v.ny, v.nz}, V[3] = {Co[0] - v.x, Co[1] - v.y, Co[2] - v.z};
    const double vn = std::sqrt(V[0] * V[0] + V[1] * V[1] + V[2] * V[2]);
    for (double &c : V)
      c /= vn;
    if (n[0] * V[0] + n[1] * V[1] + n[2] * V[2] < 0)
      for (double &c : n)
        c = -c;
    const double nl = std::max(0.0, n[0] * Lo[0] + n[1] * Lo[1] + n[2] * Lo[2]);
    double Hh[3] = {Lo[0] + V[0], Lo[1] + V[1], Lo[2] + V[2]};
    const double hn = std::sqrt(Hh[0] * Hh[0] + Hh[1] * Hh[1] + Hh[2] * Hh[2]);
    const double nh = hn > 0 ? std::max(0.0, (n[0] * Hh[0] + n[1] * Hh[1] + n[2] * Hh[2]) / hn) : 0.0;
    // With shadows the ambient term is added per fragment (it is all a shadowed fragment gets).
    const double diff = shadow ? light.diffuse * nl : light.ambient + light.diffuse * nl;
    const double spec = nl > 0 ? specK * std::pow(nh, shin) : 0.0;
    p.s = static_cast<float>(v.s * w);
    p.t = static_cast<float>(v.t * w);
    p.mask = static_cast<float>(v.mask * w);
    p.diff = static_cast<float>(diff * w);
    p.spec = static_cast<float>(spec * w);
    if (shadow) {
      // Slope-scaled bias: a surface lit at incidence theta changes depth by tan(theta) per unit across the light.
      const double c = std::max(nl, 0.1), tanInc = std::sqrt(1.0 - c * c) / c;
      const double bias = light.shadowBiasM + light.shadowSlopeBias * shadow->texel() * tanInc;
      double su = 0, sv = 0, sd = 0;
      shadow->project(v.x, v.y, v.z, su, sv, sd);
      p.su = static_cast<float>(su * w);
      p.sv = static_cast<float>(sv * w);
      p.sd = static_cast<float>((sd - bias) * w);
    }
  }
  if (shadow)
    drawTriangles<true>(mesh, light, id);
  else
    drawTriangles<false>(mesh, light, id);
}

template <bool kShadow>
void Rasterizer::drawTriangles(const Mesh &mesh, const Lighting &light, std::uint8_t id)
{

  const Texture &tex = *mesh.texture;
  [[maybe_unused]] const float ambient = static_cast<float>(light.ambient);
  const int W = static_cast<int>(m_W), H = static_cast<int>(m_H);
  // Edge functions in fixed point (1/256 px) and 64-bit integers: exact, so two triangles that
  // share an edge cover each sample on it exactly once (top-left rule), with no crack between them.
  constexpr double kSub = 256.0, kMaxCoord = 1 << 20;
  struct Fixed
  {
    std::int64_t x, y;
  };
  auto fixedOf = [&](const ProjVertex &v) {
    return Fixed{static_cast<std::int64_t>(std::llround(v.X * kSub)), static_cast<std::int64_t>(std::llround(v.Y * kSub))};
  };
  for (const auto &tri : mesh.triangles) {
    const ProjVertex *pa = &m_proj[tri[0]], *pb = &m_proj[tri[1]], *pc = &m_proj[tri[2]];
    if (!pa->valid || !pb->valid || !pc->valid)
      continue;
    if (std::fabs(pa->X) > kMaxCoord || std::fabs(pa->Y) > kMaxCoord || std::fabs(pb->X) > kMaxCoord ||
        std::fabs(pb->Y) > kMaxCoord || std::fabs(pc->X) > kMaxCoord || std::fabs(pc->Y) > kMaxCoord)
      continue; // a vertex projected too far (grazing the camera plane)
    Fixed A = fixedOf(*pa), B = fixedOf(*pb), C = fixedOf(*pc);
    std::int64_t area = (B.x - A.x) * (C.y - A.y) - (C.x - A.x) * (B.y - A.y);
    if (area == 0)
      continue;
    if (area < 0) { // make the winding counter-clockwise in these coordinates (y down)
      std::swap(B, C);
      std::swap(pb, pc);
      area = -area;
    }
    const ProjVertex &a = *pa, &b = *pb, &c = *pc;
    // The bounding box from the same fixed-point coordinates as the edge test (from the floats, a
    // vertex at 342.9999 whose fixed value is 343 dropped the samples of column 343 that lie on
    // its edges from both triangles: a crack along a mesh line that projects onto a sample column).
    // Kept off by default (setExactBounds) so that existing images stay bit-identical.
    auto floorDiv = [](std::int64_t q) { return q >= 0 ? q / 256 : -((-q + 255) / 256); };
    auto ceilDiv = [&](std::int64_t q) { return -floorDiv(-q); };
    int x0, x1, y0, y1;
    if (m_exactBounds) {
      x0 = static_cast<int>(std::max<std::int64_t>(0, ceilDiv(std::min({A.x, B.x, C.x}))));
      x1 = static_cast<int>(std::min<std::int64_t>(W - 1, floorDiv(std::max({A.x, B.x, C.x}))));
      y0 = static_cast<int>(std::max<std::int64_t>(0, ceilDiv(std::min({A.y, B.y, C.y}))));
      y1 = static_cast<int>(std::min<std::int64_t>(H - 1, floorDiv(std::max({A.y, B.y, C.y}))));
    } else {
      x0 = std::max(0, static_cast<int>(std::ceil(std::min({a.X, b.X, c.X}))));
      x1 = std::min(W - 1, static_cast<int>(std::floor(std::max({a.X, b.X, c.X}))));
      y0 = std::max(0, static_cast<int>(std::ceil(std::min({a.Y, b.Y, c.Y}))));
      y1 = std::min(H - 1, static_cast<int>(std::floor(std::max({a.Y, b.Y, c.Y}))));
    }
    if (x0 > x1 || y0 > y1)
      continue;
    // E_pq(x, y) = (q.x - p.x)(y - p.y) - (q.y - p.y)(x - p.x), >= 0 inside; the edge opposite a is b->c.
    auto bias = [](const Fixed &p, const Fixed &q) { // top-left rule: samples on other edges belong to the neighbour
      const bool top = p.y == q.y && q.x > p.x, left = q.y < p.y;
      return (top || left) ? 0 : -1;
    };
    const std::int64_t ba0 = bias(B, C), bb0 = bias(C, A), bc0 = bias(A, B);
    const std::int64_t stepAx = -(C.y - B.y) * 256, stepBx = -(A.y - C.y) * 256, stepCx = -(B.y - A.y) * 256;
    const float inv = 1.f / static_cast<float>(area);
    for (int y = y0; y <= y1; ++y) {
      const std::int64_t sy = static_cast<std::int64_t>(y) * 256, sx0 = static_cast<std::int64_t>(x0) * 256;
      std::int64_t ea = (C.x - B.x) * (sy - B.y) - (C.y - B.y) * (sx0 - B.x);
      std::int64_t eb = (A.x - C.x) * (sy - C.y) - (A.y - C.y) * (sx0 - C.x);
      std::int64_t ec = (B.x - A.x) * (sy - A.y) - (B.y - A.y) * (sx0 - A.x);
      std::size_t idx = static_cast<std::size_t>(y) * m_W + static_cast<std::size_t>(x0);
      for (int x = x0; x <= x1; ++x, ++idx, ea += stepAx, eb += stepBx, ec += stepCx) {
        if (ea + ba0 < 0 || eb + bb0 < 0 || ec + bc0 < 0)
          continue;
        const float wa = static_cast<float>(ea) * inv, wb = static_cast<float>(eb) * inv, wc = static_cast<float>(ec) * inv;
        const float w = wa * a.w + wb * b.w + wc * c.w;
        if (w <= m_invDepth[idx])
          continue;
        const float iz = 1.f / w;
        if (mesh.useMask && (wa * a.mask + wb * b.mask + wc * c.mask) * iz > 0.f)
          continue;
        const float s = (wa * a.s + wb * b.s + wc * c.s) * iz;
        const float t = (wa * a.t + wb * b.t + wc * c.t) * iz;
        const float diff = (wa * a.diff + wb * b.diff + wc * c.diff) * iz;
        const float spec = (wa * a.spec + wb * b.spec + wc * c.spec) * iz;
        float col[3];
        tex.sample(s, t, col);
        m_invDepth[idx] = w;
        m_id[idx] = id;
        float *o = &m_color[3 * idx];
        if constexpr (kShadow) {
          const float su = (wa * a.su + wb * b.su + wc * c.su) * iz;
          const float sv = (wa * a.sv + wb * b.sv + wc * c.sv) * iz;
          const float sd = (wa * a.sd + wb * b.sd + wc * c.sd) * iz;
          const float lit = light.shadow->visibility(su, sv, sd);
          const float d = ambient + lit * diff, sp = lit * spec;
          o[0] = col[0] * d + sp;
          o[1] = col[1] * d + sp;
          o[2] = col[2] * d + sp;
        } else {
          o[0] = col[0] * diff + spec;
          o[1] = col[1] * diff + spec;
          o[2] = col[2] * diff + spec;
        }
      }
    }
  }
}

template void Rasterizer::drawTriangles<true>(const Mesh &, const Lighting &, std::uint8_t);
template void Rasterizer::drawTriangles<false>(const Mesh &, const Lighting &, std::uint8_t);

void Rasterizer::resolve(vpImage<vpRGBa> &out, double exposure, double noiseSigma, std::uint64_t noiseSeed) const
{
  out.resize(m_h, m_w);
  const float norm = static_cast<float>(255.0 * exposure / (m_ss * m_ss));
  for (unsigned v = 0; v < m_h; ++v)
    for (unsigned u = 0; u < m_w; ++u) {
      float acc[3] = {0, 0, 0};
      for (unsigned j = 0; j < m_ss; ++j) {
        const float *p = &m_color[3 * ((static_cast<std::size_t>(v) * m_ss + j) * m_W + static_cast<std::size_t>(u) * m_ss)];
        for (unsigned i = 0; i < m_ss; ++i, p += 3) {
          acc[0] += p[0];
          acc[1] += p[1];
          acc[2] += p[2];
        }
      }
      unsigned char c[3];
      for (int k = 0; k < 3; ++k) {
        double val = acc[k] * norm;
        if (noiseSigma > 0)
          val += noiseSigma * static_cast<double>(fastGaussian(noiseSeed, (static_cast<std::uint64_t>(v) * m_w + u) * 3 + static_cast<std::uint64_t>(k)));
        c[k] = static_cast<unsigned char>(std::lround(std::min(255.0, std::max(0.0, val))));
      }
      out[v][u] = vpRGBa(c[0], c[1], c[2], 255);
    }
}

void Rasterizer::addNoise(vpImage<vpRGBa> &out, double noiseSigma, std::uint64_t noiseSeed)
{
  if (!(noiseSigma > 0))
    return;
  const unsigned w = out.getWidth(), h = out.getHeight();
  for (unsigned v = 0; v < h; ++v)
    for (unsigned u = 0; u < w; ++u) {
      unsigned char *c[3] = {&out[v][u].R, &out[v][u].G, &out[v][u].B};
      for (int k = 0; k < 3; ++k) {
        const double val = *c[k] + noiseSigma * static_cast<double>(fastGaussian(noiseSeed, (static_cast<std::uint64_t>(v) * w + u) * 3 + static_cast<std::uint64_t>(k)));
        *c[k] = static_cast<unsigned char>(std::lround(std::min(255.0, std::max(0.0, val))));
      }
    }
}

double Rasterizer::coverage(unsigned u, unsigned v, std::uint8_t id) const
{
  if (u >= m_w || v >= m_h)
    return 0.0;
  unsigned n = 0;
  for (unsigned j = 0; j < m_ss; ++j)
    for (unsigned i = 0; i < m_ss; ++i)
      n += m_id[(static_cast<std::size_t>(v) * m_ss + j) * m_W + static_cast<std::size_t>(u) * m_ss + i] == id;
  return static_cast<double>(n) / (m_ss * m_ss);
}

double Rasterizer::depthAt(unsigned u, unsigned v, std::uint8_t id) const
{
  if (u >= m_w || v >= m_h)
    return std::numeric_limits<double>::quiet_NaN();
  double z = 0;
  for (unsigned j = 0; j < m_ss; ++j)
    for (unsigned i = 0; i < m_ss; ++i) {
      const std::size_t idx = (static_cast<std::size_t>(v) * m_ss + j) * m_W + static_cast<std::size_t>(u) * m_ss + i;
      if (m_id[idx] != id || !(m_invDepth[idx] > 0.f))
        return std::numeric_limits<double>::quiet_NaN();
      z += 1.0 / m_invDepth[idx];
    }
  return z / (m_ss * m_ss);
}

} // namespace pm::sim
