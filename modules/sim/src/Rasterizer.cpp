#include "pm/sim/Rasterizer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "pm/core/Error.h"
#include "pm/core/Rounding.h"
#include "pm/sim/Noise.h"
#include "RasterKernels.h"

namespace pm::sim {

namespace {

using namespace raster; // the kernels (RasterKernels.h)

//! floor(q / d) for d > 0, exact: a double quotient (no 64-bit integer division, ~5x slower) corrected by one step.
inline std::int64_t floorDiv(std::int64_t q, std::int64_t d)
{
  auto k = static_cast<std::int64_t>(static_cast<double>(q) / static_cast<double>(d)); // truncated: corrected below
  while (k * d > q)
    --k;
  while ((k + 1) * d <= q)
    ++k;
  return k;
}
inline std::int64_t ceilDiv(std::int64_t q, std::int64_t d) { return -floorDiv(-q, d); }
//! floor(q / 256) and ceil(q / 256) (an arithmetic shift).
inline std::int64_t floorDiv256(std::int64_t q) { return q >> 8; }
inline std::int64_t ceilDiv256(std::int64_t q) { return -((-q) >> 8); }
/*!
  Narrows [lo, hi] (steps from the row's first sample) to where e + k step + bias >= 0: an edge
  function is linear along the row, so the samples inside a triangle are one span, found exactly.
*/
inline void clipSpan(std::int64_t e, std::int64_t step, std::int64_t bias, std::int64_t &lo, std::int64_t &hi)
{
  const std::int64_t e0 = e + bias;
  // A short range (a small triangle's row) is stepped through: the same samples, no division.
  const bool shortRange = hi - lo < 8;
  if (step > 0) {
    if (e0 + lo * step < 0) {
      if (shortRange) {
        while (lo <= hi && e0 + lo * step < 0)
          ++lo;
      } else {
        lo = ceilDiv(-e0, step);
      }
    }
  } else if (step < 0) {
    if (e0 + hi * step < 0) {
      if (shortRange) {
        while (hi >= lo && e0 + hi * step < 0)
          --hi;
      } else {
        hi = floorDiv(e0, -step);
      }
    }
  } else if (e0 < 0) {
    hi = lo - 1;
  }
}

/*!
  True if the mask discards every fragment of the triangle: the mask is positive (outside the
  outline) at its three vertices, by a margin that the float rounding of its interpolation cannot
  undo, so it is positive everywhere between them. Such triangles (the outer part of the strip of
  cells a toy's mesh keeps around its outline) are skipped whole: the same images.
*/
template <class V>
inline bool masksAll(const V &a, const V &b, const V &c)
{
  constexpr float kMargin = 1e-3f; // mask times 1/z (mm per m): about 1e3 times the interpolation's rounding
  return a.mask > kMargin && b.mask > kMargin && c.mask > kMargin;
}

} // namespace

bool Rasterizer::simdAvailable()
{
#if PM_RASTER_AVX2
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
#else
  return false;
#endif
}

void Rasterizer::reset(unsigned width, unsigned height, unsigned supersampling)
{
  if (width == 0 || height == 0 || supersampling < 1 || supersampling > 4)
    throw core::Error("renderer: image size must be positive and supersampling in [1, 4]");
  m_w = width;
  m_h = height;
  m_ss = supersampling;
  m_W = width * supersampling;
  m_H = height * supersampling;
  const std::size_t n = static_cast<std::size_t>(m_W) * m_H;
  // The whole frame's colour buffer (16 bytes a sample) only for draw(); render() uses a band. It is
  // sized by draw() and never cleared: a sample's colour is read only where its id says something
  // was drawn (at supersampling 4, 78 MB a frame that were written with zeros before each draw).
  m_invDepth.assign(n, 0.f);
  m_id.assign(n, 0);
  m_colorValid = true;
}

void Rasterizer::clear(float r, float g, float b)
{
  // The colour of a sample is read only where something was drawn (its id is not 0): resolve()
  // uses the clear colour elsewhere, so the colour buffer (16 bytes a sample) is not written here.
  m_clearColor[0] = r;
  m_clearColor[1] = g;
  m_clearColor[2] = b;
  std::fill(m_invDepth.begin(), m_invDepth.end(), 0.f);
  std::fill(m_id.begin(), m_id.end(), std::uint8_t(0));
  m_colorValid = true;
}

namespace {
void checkDrawable(const Mesh &mesh, std::uint8_t id)
{
  if (!mesh.texture || mesh.texture->width <= 0 || mesh.texture->height <= 0)
    throw core::Error("renderer: mesh without texture");
  if (id == 0)
    throw core::Error("renderer: object id 0 means nothing drawn; use 1..255");
}
} // namespace

void Rasterizer::draw(const Mesh &mesh, const vpHomogeneousMatrix &cMo, const vpCameraParameters &cam,
                      const Lighting &light, std::uint8_t id)
{
  checkDrawable(mesh, id);
  if (m_W == 0)
    throw core::Error("renderer: reset() the image size before drawing");
  if (!m_colorValid)
    throw core::Error("renderer: clear() after render() before drawing on (render() keeps no whole-frame colours)");
  if (m_color.size() != kStride * m_invDepth.size())
    m_color.assign(kStride * m_invDepth.size(), 0.f);
  if (m_scratch.empty())
    m_scratch.resize(1);
  std::vector<ProjVertex> &proj = m_scratch[0].proj;
  project(mesh, cMo, cam, light, proj);
  if (light.shadow)
    drawTriangles<true>(mesh, proj, light, id, nullptr, mesh.triangles.size(), 0, static_cast<int>(m_H), m_color.data(), 0);
  else
    drawTriangles<false>(mesh, proj, light, id, nullptr, mesh.triangles.size(), 0, static_cast<int>(m_H), m_color.data(), 0);
}

void Rasterizer::render(const float clearColor[3], const DrawCall *calls, std::size_t n, const vpCameraParameters &cam,
                        vpImage<vpRGBa> &out, double exposure, double noiseSigma, std::uint64_t noiseSeed)
{
  if (m_W == 0)
    throw core::Error("renderer: reset() the image size before rendering");
  for (std::size_t c = 0; c < n; ++c)
    checkDrawable(*calls[c].mesh, calls[c].id);
  for (int k = 0; k < 3; ++k)
    m_clearColor[k] = clearColor[k];
  m_colorValid = false; // the whole-frame colour buffer is not this frame's
  // Bands of whole pixel rows whose colour (16 bytes a sample) fits in a quarter of a core's L2.
  const unsigned rows = std::max(1u, static_cast<unsigned>((256u << 10) / (kStride * sizeof(float) * m_W) / m_ss)) * m_ss;
  const unsigned nBands = (m_H + rows - 1) / rows;
  if (m_scratch.size() < n)
    m_scratch.resize(n);
  for (std::size_t c = 0; c < n; ++c) {
    Scratch &sc = m_scratch[c];
    project(*calls[c].mesh, calls[c].cMo, cam, calls[c].light, sc.proj);
    bin(*calls[c].mesh, sc, rows, nBands);
  }
  m_band.resize(kStride * static_cast<std::size_t>(m_W) * rows);
  out.resize(m_h, m_w);
  for (unsigned b = 0; b < nBands; ++b) {
    const unsigned y0 = b * rows, y1 = std::min(m_H, y0 + rows);
    const std::size_t first = static_cast<std::size_t>(y0) * m_W, last = static_cast<std::size_t>(y1) * m_W;
    std::fill(m_invDepth.begin() + static_cast<std::ptrdiff_t>(first), m_invDepth.begin() + static_cast<std::ptrdiff_t>(last), 0.f);
    std::fill(m_id.begin() + static_cast<std::ptrdiff_t>(first), m_id.begin() + static_cast<std::ptrdiff_t>(last), std::uint8_t(0));
    for (std::size_t c = 0; c < n; ++c) {
      const Scratch &sc = m_scratch[c];
      const std::uint32_t *tris = sc.binTris.data() + sc.binStart[b];
      const std::size_t count = sc.binStart[b + 1] - sc.binStart[b];
      if (calls[c].light.shadow)
        drawTriangles<true>(*calls[c].mesh, sc.proj, calls[c].light, calls[c].id, tris, count, static_cast<int>(y0),
                            static_cast<int>(y1), m_band.data(), first);
      else
        drawTriangles<false>(*calls[c].mesh, sc.proj, calls[c].light, calls[c].id, tris, count, static_cast<int>(y0),
                             static_cast<int>(y1), m_band.data(), first);
    }
    resolveRows(out, y0 / m_ss, y1 / m_ss, m_band.data(), first, exposure, noiseSigma, noiseSeed);
  }
}

void Rasterizer::bin(const Mesh &mesh, Scratch &sc, unsigned rows, unsigned nBands) const
{
  // Each triangle into every band its rows may reach: a conservative row range from the projected
  // vertices (drawTriangles finds the exact rows and clips them to the band).
  constexpr float kMaxCoord = 1 << 20;
  const float maxRow = static_cast<float>(m_H - 1);
  sc.binStart.assign(nBands + 1, 0);
  sc.triBands.resize(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto &tri = mesh.triangles[t];
    const ProjVertex &a = sc.proj[tri[0]], &b = sc.proj[tri[1]], &c = sc.proj[tri[2]];
    sc.triBands[t] = {1, 0};
    if (!a.valid || !b.valid || !c.valid || std::fabs(a.Y) > kMaxCoord || std::fabs(b.Y) > kMaxCoord ||
        std::fabs(c.Y) > kMaxCoord)
      continue;
    const float lo = std::min({a.Y, b.Y, c.Y}) - 1.f, hi = std::max({a.Y, b.Y, c.Y}) + 1.f;
    if (hi < 0.f || lo > maxRow)
      continue;
    const auto b0 = static_cast<std::uint32_t>(static_cast<unsigned>(std::max(lo, 0.f)) / rows);
    const auto b1 = static_cast<std::uint32_t>(static_cast<unsigned>(std::min(hi, maxRow)) / rows);
    sc.triBands[t] = {b0, b1};
    for (std::uint32_t k = b0; k <= b1; ++k)
      ++sc.binStart[k + 1];
  }
  for (unsigned k = 0; k < nBands; ++k)
    sc.binStart[k + 1] += sc.binStart[k];
  sc.binTris.resize(sc.binStart[nBands]);
  sc.binFill.assign(sc.binStart.begin(), sc.binStart.end() - 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::uint32_t k = sc.triBands[t].first; k <= sc.triBands[t].second; ++k)
      sc.binTris[sc.binFill[k]++] = static_cast<std::uint32_t>(t);
}

void Rasterizer::project(const Mesh &mesh, const vpHomogeneousMatrix &cMo, const vpCameraParameters &cam,
                         const Lighting &light, std::vector<ProjVertex> &proj) const
{
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
      throw core::Error("renderer: the shadow map was made for another light direction");
  }
  const double specK = light.specular >= 0 ? light.specular : static_cast<double>(mesh.specular);
  const double shin = light.shininess >= 0 ? light.shininess : static_cast<double>(mesh.shininess);

  double R[3][4];
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 4; ++j)
      R[i][j] = cMo[i][j];

  proj.resize(mesh.vertices.size());
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    const MeshVertex &v = mesh.vertices[k];
    const double X = R[0][0] * v.x + R[0][1] * v.y + R[0][2] * v.z + R[0][3];
    const double Y = R[1][0] * v.x + R[1][1] * v.y + R[1][2] * v.z + R[1][3];
    const double Z = R[2][0] * v.x + R[2][1] * v.y + R[2][2] * v.z + R[2][3];
    ProjVertex &p = proj[k];
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
}

template <bool kShadow>
void Rasterizer::drawTriangles(const Mesh &mesh, const std::vector<ProjVertex> &proj, const Lighting &light,
                               std::uint8_t id, const std::uint32_t *tris, std::size_t count, int yBegin, int yEnd,
                               float *color, std::size_t colorOffset)
{
  const int W = static_cast<int>(m_W), H = static_cast<int>(m_H);
  // Edge functions in fixed point (1/256 px) and 64-bit integers: exact, so two triangles that
  // share an edge cover each sample on it exactly once (top-left rule), with no crack between them.
  constexpr double kSub = 256.0, kMaxCoord = 1 << 20;
  struct Fixed
  {
    std::int64_t x, y;
  };
  auto fixedOf = [&](const ProjVertex &v) {
    return Fixed{core::roundHalfAway(v.X * kSub), core::roundHalfAway(v.Y * kSub)};
  };
  // The attributes interpolated across a triangle, in the order of ProjVertex (w, s, t, mask, diff,
  // spec, su, sv, sd): each is a plane in screen space, stepped along a span.
  constexpr int kAttrs = kShadow ? 9 : 6;
  [[maybe_unused]] const bool useAvx2 = m_simd && simdAvailable();
  for (std::size_t n = 0; n < count; ++n) {
    const auto &tri = mesh.triangles[tris ? tris[n] : n];
    const ProjVertex *pa = &proj[tri[0]], *pb = &proj[tri[1]], *pc = &proj[tri[2]];
    if (!pa->valid || !pb->valid || !pc->valid)
      continue;
    if (mesh.useMask && masksAll(*pa, *pb, *pc))
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
    // The bounding box comes from the same fixed-point vertices as the edge test, so that every
    // sample the edge test puts inside the triangle is visited (docs/simulated-lab.md: a box from
    // the floating-point vertices left a one-sample crack along mesh lines near a sample column).
    const int x0 = static_cast<int>(std::max<std::int64_t>(0, ceilDiv256(std::min({A.x, B.x, C.x}))));
    const int x1 = static_cast<int>(std::min<std::int64_t>(W - 1, floorDiv256(std::max({A.x, B.x, C.x}))));
    const int y0 = static_cast<int>(std::max<std::int64_t>(yBegin, ceilDiv256(std::min({A.y, B.y, C.y})))); // within this band's rows
    const int y1 = static_cast<int>(std::min<std::int64_t>(std::min(H, yEnd) - 1, floorDiv256(std::max({A.y, B.y, C.y}))));
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
    const float dwa = static_cast<float>(stepAx) * inv, dwb = static_cast<float>(stepBx) * inv, dwc = static_cast<float>(stepCx) * inv;
    float va[kAttrs], vb[kAttrs], vc[kAttrs], d[kAttrs];
    {
      const float fa[9] = {a.w, a.s, a.t, a.mask, a.diff, a.spec, a.su, a.sv, a.sd};
      const float fb[9] = {b.w, b.s, b.t, b.mask, b.diff, b.spec, b.su, b.sv, b.sd};
      const float fc[9] = {c.w, c.s, c.t, c.mask, c.diff, c.spec, c.su, c.sv, c.sd};
      for (int q = 0; q < kAttrs; ++q) {
        va[q] = fa[q];
        vb[q] = fb[q];
        vc[q] = fc[q];
        d[q] = dwa * fa[q] + dwb * fb[q] + dwc * fc[q];
      }
    }
    for (int y = y0; y <= y1; ++y) {
      const std::int64_t sy = static_cast<std::int64_t>(y) * 256, sx0 = static_cast<std::int64_t>(x0) * 256;
      const std::int64_t ea = (C.x - B.x) * (sy - B.y) - (C.y - B.y) * (sx0 - B.x);
      const std::int64_t eb = (A.x - C.x) * (sy - C.y) - (A.y - C.y) * (sx0 - C.x);
      const std::int64_t ec = (B.x - A.x) * (sy - A.y) - (B.y - A.y) * (sx0 - A.x);
      std::int64_t lo = 0, hi = x1 - x0;
      clipSpan(ea, stepAx, ba0, lo, hi);
      clipSpan(eb, stepBx, bb0, lo, hi);
      clipSpan(ec, stepCx, bc0, lo, hi);
      if (lo > hi)
        continue;
      // The barycentric weights at the span's first sample, then each attribute's plane along it.
      const float wa = static_cast<float>(ea + lo * stepAx) * inv, wb = static_cast<float>(eb + lo * stepBx) * inv;
      const float wc = static_cast<float>(ec + lo * stepCx) * inv;
      float v0[kAttrs];
      for (int q = 0; q < kAttrs; ++q)
        v0[q] = wa * va[q] + wb * vb[q] + wc * vc[q];
      const std::size_t row = static_cast<std::size_t>(y) * m_W + static_cast<std::size_t>(x0);
      shadeSpan<kShadow>(mesh, light, id, v0, d, row + static_cast<std::size_t>(lo), row + static_cast<std::size_t>(hi), color,
                         colorOffset, useAvx2);
    }
  }
}

template <bool kShadow>
void Rasterizer::shadeSpan(const Mesh &mesh, const Lighting &light, std::uint8_t id, const float *v0, const float *d, std::size_t first,
                           std::size_t end, float *color, std::size_t colorOffset, [[maybe_unused]] bool useAvx2)
{
  const Texture &tex = *mesh.texture;
  [[maybe_unused]] const float ambient = static_cast<float>(light.ambient);
  float kf = 0.f;
#if PM_RASTER_AVX2
  if constexpr (!kShadow) {
    if (useAvx2 && end - first + 1 >= kMinAvx2Span) {
      const std::size_t done = shadeSpanAvx2(v0, d, end - first + 1, m_invDepth.data() + first, m_id.data() + first,
                                             color + kStride * (first - colorOffset), tex, mesh.useMask, id);
      first += done;
      kf = static_cast<float>(done);
    }
  }
#endif
  for (std::size_t idx = first; idx <= end; ++idx, kf += 1.f) {
    const float w = v0[0] + kf * d[0];
    if (w <= m_invDepth[idx])
      continue;
    const float iz = 1.f / w;
    if (mesh.useMask && v0[3] + kf * d[3] > 0.f)
      continue;
    const float s = (v0[1] + kf * d[1]) * iz;
    const float t = (v0[2] + kf * d[2]) * iz;
    float diff = (v0[4] + kf * d[4]) * iz, spec = (v0[5] + kf * d[5]) * iz;
    if constexpr (kShadow) {
      const float su = (v0[6] + kf * d[6]) * iz;
      const float sv = (v0[7] + kf * d[7]) * iz;
      const float sd = (v0[8] + kf * d[8]) * iz;
      const float lit = light.shadow->visibility(su, sv, sd);
      diff = ambient + lit * diff;
      spec = lit * spec;
    }
    m_invDepth[idx] = w;
    m_id[idx] = id;
    shadeTexel(tex, s, t, diff, spec, color + kStride * (idx - colorOffset));
  }
}

template void Rasterizer::drawTriangles<true>(const Mesh &, const std::vector<ProjVertex> &, const Lighting &,
                                             std::uint8_t, const std::uint32_t *, std::size_t, int, int, float *,
                                             std::size_t);
template void Rasterizer::drawTriangles<false>(const Mesh &, const std::vector<ProjVertex> &, const Lighting &,
                                              std::uint8_t, const std::uint32_t *, std::size_t, int, int, float *,
                                              std::size_t);

namespace {
//! A grey level in [0, 255]: \e val clamped and rounded half away from zero (std::lround's rule, inline).
inline unsigned char toByte(double val)
{
  return static_cast<unsigned char>(static_cast<int>(std::min(255.0, std::max(0.0, val)) + 0.5));
}
} // namespace

void Rasterizer::resolve(vpImage<vpRGBa> &out, double exposure, double noiseSigma, std::uint64_t noiseSeed) const
{
  if (!m_colorValid)
    throw core::Error("renderer: render() resolved its own frame; clear() and draw() before resolve()");
  out.resize(m_h, m_w);
  resolveRows(out, 0, m_h, m_color.data(), 0, exposure, noiseSigma, noiseSeed);
}

void Rasterizer::resolveRows(vpImage<vpRGBa> &out, unsigned vBegin, unsigned vEnd, const float *color,
                             std::size_t colorOffset, double exposure, double noiseSigma, std::uint64_t noiseSeed) const
{
  const float norm = static_cast<float>(255.0 * exposure / (m_ss * m_ss));
  const float sigma = static_cast<float>(noiseSigma);
  // (R, G, B) per pixel, and one more float: a pixel's noise is read as 4 floats (the fourth, the
  // next pixel's R, goes to the alpha channel, which is set to 255 whatever it holds).
  m_noise.assign(3 * static_cast<std::size_t>(m_w) + 1, 0.f);
  [[maybe_unused]] const bool useAvx2 = m_ss == 2 && m_simd && simdAvailable();
  for (unsigned v = vBegin; v < vEnd; ++v) {
    vpRGBa *dst = out[v];
    const std::size_t row0 = static_cast<std::size_t>(v) * m_ss * m_W;
    if (noiseSigma > 0)
      fastGaussian3Run(noiseSeed, static_cast<std::uint64_t>(v) * m_w, m_w, m_noise.data(), 3);
    unsigned u = 0;
#if PM_RASTER_AVX2
    if (useAvx2)
      u = resolveRowSs2Avx2(color + kStride * (row0 - colorOffset), color + kStride * (row0 + m_W - colorOffset),
                            m_id.data() + row0, m_id.data() + row0 + m_W, m_clearColor, m_noise.data(), norm, sigma,
                            m_w, dst);
#endif
    for (; u < m_w; ++u) {
      // The box filter of the pixel's samples (the clear colour where nothing was drawn), the
      // exposure, the noise, clamped and rounded half up, in single precision.
      const float *g = &m_noise[3 * static_cast<std::size_t>(u)];
      unsigned char c[3];
#if defined(__SSE2__)
      // The same float operations as the scalar lines below, four channels at once.
      __m128 acc = _mm_setzero_ps();
      for (unsigned j = 0; j < m_ss; ++j) {
        const std::size_t first = row0 + j * m_W + static_cast<std::size_t>(u) * m_ss;
        for (unsigned i = 0; i < m_ss; ++i)
          acc = _mm_add_ps(acc, _mm_loadu_ps(m_id[first + i] ? color + kStride * (first + i - colorOffset) : m_clearColor));
      }
      __m128 x = _mm_add_ps(_mm_mul_ps(acc, _mm_set1_ps(norm)), _mm_mul_ps(_mm_set1_ps(sigma), _mm_loadu_ps(g)));
      x = _mm_add_ps(_mm_min_ps(_mm_max_ps(x, _mm_setzero_ps()), _mm_set1_ps(255.f)), _mm_set1_ps(0.5f));
      alignas(16) std::int32_t q[4];
      _mm_store_si128(reinterpret_cast<__m128i *>(q), _mm_cvttps_epi32(x));
      for (int k = 0; k < 3; ++k)
        c[k] = static_cast<unsigned char>(q[k]);
#else
      float acc[4] = {0, 0, 0, 0};
      for (unsigned j = 0; j < m_ss; ++j) {
        const std::size_t first = row0 + j * m_W + static_cast<std::size_t>(u) * m_ss;
        for (unsigned i = 0; i < m_ss; ++i) {
          const float *q = m_id[first + i] ? color + kStride * (first + i - colorOffset) : m_clearColor;
          for (std::size_t c = 0; c < 4; ++c)
            acc[c] += q[c];
        }
      }
      for (int k = 0; k < 3; ++k)
        c[k] = static_cast<unsigned char>(std::min(255.f, std::max(0.f, acc[k] * norm + sigma * g[k])) + 0.5f);
#endif
      dst[u] = vpRGBa(c[0], c[1], c[2], 255);
    }
  }
}

void Rasterizer::addNoise(vpImage<vpRGBa> &out, double noiseSigma, std::uint64_t noiseSeed)
{
  if (!(noiseSigma > 0))
    return;
  const unsigned w = out.getWidth(), h = out.getHeight();
  for (unsigned v = 0; v < h; ++v)
    for (unsigned u = 0; u < w; ++u) {
      vpRGBa &px = out[v][u];
      float g[3];
      fastGaussian3(noiseSeed, static_cast<std::uint64_t>(v) * w + u, g);
      px.R = toByte(px.R + noiseSigma * g[0]);
      px.G = toByte(px.G + noiseSigma * g[1]);
      px.B = toByte(px.B + noiseSigma * g[2]);
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
