#include "CreatureParts.h"

#include <algorithm>
#include <cmath>

#include "pm/sim/Noise.h"

namespace pm::sim::catalog {

Part ellipse(Vec2 c, Vec2 r, double angleDeg, Hsv3 col, double relief, double round)
{
  Part p;
  p.kind = Kind::Ellipse;
  p.c = c;
  p.r = r;
  p.angleDeg = angleDeg;
  p.color = col;
  p.relief = relief;
  p.round = round;
  return p;
}

Part capsule(Vec2 a, Vec2 b, double ra, double rb, Hsv3 col, double relief, double round)
{
  Part p;
  p.kind = Kind::Capsule;
  p.a = a;
  p.b = b;
  p.ra = ra;
  p.rb = rb;
  p.color = col;
  p.relief = relief;
  p.round = round;
  return p;
}

Part polygon(std::vector<Vec2> pts, Hsv3 col, double relief, double round)
{
  Part p;
  p.kind = Kind::Polygon;
  p.poly = std::move(pts);
  p.color = col;
  p.relief = relief;
  p.round = round;
  return p;
}

Part bump(Part p)
{
  p.bump = true;
  return p;
}

Part spots(Part p, Hsv3 col, double scale, double fill)
{
  p.pattern = Pattern::Spots;
  p.patColor = col;
  p.patScale = scale;
  p.patFill = fill;
  return p;
}

Part stripes(Part p, Hsv3 col, double period, double angleDeg, double duty)
{
  p.pattern = Pattern::Stripes;
  p.patColor = col;
  p.patScale = period;
  p.patFill = duty;
  p.patAngleDeg = angleDeg;
  return p;
}

//! A chain of capsules through \e pts with radius tapering from r0 to r1.
void chain(std::vector<Part> &out, const std::vector<Vec2> &pts, double r0, double r1, Hsv3 col, double relief)
{
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double t0 = static_cast<double>(i) / static_cast<double>(pts.size() - 1);
    const double t1 = static_cast<double>(i + 1) / static_cast<double>(pts.size() - 1);
    out.push_back(capsule(pts[i], pts[i + 1], r0 + (r1 - r0) * t0, r0 + (r1 - r0) * t1, col, relief));
  }
}

namespace {

bool inPattern(const Part &p, double x, double y, std::uint64_t seed)
{
  switch (p.pattern) {
  case Pattern::None:
    return false;
  case Pattern::Stripes: {
    const double t = p.patAngleDeg * M_PI / 180;
    const double along = (std::cos(t) * x + std::sin(t) * y) / p.patScale;
    const double wobble = 0.15 * (valueNoise(x / 6, y / 6, seed) - 0.5);
    return along + wobble - std::floor(along + wobble) < p.patFill;
  }
  case Pattern::Spots: {
    const double gx = x / p.patScale, gy = y / p.patScale;
    const auto ci = static_cast<std::int64_t>(std::floor(gx)), cj = static_cast<std::int64_t>(std::floor(gy));
    for (std::int64_t j = cj - 1; j <= cj + 1; ++j)
      for (std::int64_t i = ci - 1; i <= ci + 1; ++i) {
        const double sx = static_cast<double>(i) + latticeValue(i, j, seed);
        const double sy = static_cast<double>(j) + latticeValue(i, j, seed + 7);
        const double rad = p.patFill * (0.6 + 0.8 * latticeValue(i, j, seed + 13));
        if (std::hypot(gx - sx, gy - sy) < rad * 0.5)
          return true;
      }
    return false;
  }
  }
  return false;
}

} // namespace

TargetShape rasterise(const Creature &cr, double texelMm)
{
  // Scale the parts' union to the nominal width and height.
  double bx0 = 1e30, by0 = 1e30, bx1 = -1e30, by1 = -1e30;
  for (const auto &p : cr.parts) {
    if (p.bump)
      continue;
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    p.bounds(x0, y0, x1, y1);
    bx0 = std::min(bx0, x0), by0 = std::min(by0, y0), bx1 = std::max(bx1, x1), by1 = std::max(by1, y1);
  }
  const double sx = cr.info.widthMm / (bx1 - bx0), sy = cr.info.heightMm / (by1 - by0);
  const double sd = std::sqrt(sx * sy); // distance scale of the (slightly anisotropic) map
  const double cxN = (bx0 + bx1) / 2, cyN = (by0 + by1) / 2;
  const double margin = 4.0;

  TargetShape s = targetGrid(cr.info, texelMm, margin, false);
  const std::size_t n = s.sdf.size();

  std::vector<double> inner(cr.parts.size());
  for (std::size_t i = 0; i < cr.parts.size(); ++i)
    inner[i] = std::max(0.3, cr.parts[i].round * cr.parts[i].innerRadius() * sd);

  const double depth = cr.info.depthMm;
  double maxH = 0;
  std::vector<double> hRaw(n);
  std::vector<int> top(n, -1);
#pragma omp parallel for schedule(dynamic, 8) reduction(max : maxH)
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      const double x = (c - s.originCol) * texelMm, y = (r - s.originRow) * texelMm; // mm
      const double xn = x / sx + cxN, yn = y / sy + cyN;                            // part space
      double sdfU = 1e30, h = -1e30, solidTopH = -1e30;
      int topPart = -1;
      for (std::size_t i = 0; i < cr.parts.size(); ++i) {
        const Part &p = cr.parts[i];
        const double d = p.sdf(xn, yn) * sd;
        const double hp = depth * p.relief * edgeProfile(-d / inner[i], 1.0 / inner[i]);
        if (!p.bump) {
          sdfU = std::min(sdfU, d);
          if (hp > h) {
            h = hp;
            if (d < 0)
              topPart = static_cast<int>(i), solidTopH = hp;
          }
        } else if (d < 0) {
          h = std::max(h, solidTopH) + std::max(0.0, hp);
          topPart = static_cast<int>(i);
        }
      }
      const std::size_t k = static_cast<std::size_t>(r) * s.cols + c;
      s.sdf[k] = static_cast<float>(sdfU);
      hRaw[k] = h;
      top[k] = topPart;
      if (sdfU < 0)
        maxH = std::max(maxH, h);
    }
  // Normalise the relief to the nominal depth, colour each texel by the part on top.
  const double scale = maxH > 0 ? depth / maxH : 1.0;
#pragma omp parallel for schedule(dynamic, 8)
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      const std::size_t k = static_cast<std::size_t>(r) * s.cols + c;
      s.height[k] = static_cast<float>(hRaw[k] * scale);
      const double x = (c - s.originCol) * texelMm, y = (r - s.originRow) * texelMm;
      Hsv3 col{0, 0, 0.2};
      if (top[k] >= 0) {
        const Part &p = cr.parts[static_cast<std::size_t>(top[k])];
        col = inPattern(p, x, y, cr.seed + static_cast<std::uint64_t>(top[k]) * 31) ? p.patColor : p.color;
      } else {
        // Outside every part: the colour of the nearest one (bilinear texture fetch at the edge).
        double best = 1e30;
        const double xn = x / sx + cxN, yn = y / sy + cyN;
        for (const auto &p : cr.parts) {
          const double d = p.bump ? 1e30 : p.sdf(xn, yn);
          if (d < best)
            best = d, col = p.color;
        }
      }
      const double m = 1.0 + cr.mottle * (2.0 * fbm(x / 9.0, y / 9.0, cr.seed, 4) - 1.0);
      col.v *= m;
      col.h += 6.0 * (fbm(x / 25.0, y / 25.0, cr.seed + 99, 2) - 0.5);
      setTexel(s, k, col);
    }
  s.centreOnOutline();
  return s;
}

} // namespace pm::sim::catalog
