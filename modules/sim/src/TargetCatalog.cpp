#include "pm/sim/TargetCatalog.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>

#include "pm/core/Error.h"
#include "pm/sim/Noise.h"

namespace pm::sim {

namespace {

struct Vec2
{
  double x, y;
};

struct Hsv3
{
  double h, s, v;
};

enum class Kind { Ellipse, Capsule, Polygon };
enum class Pattern { None, Spots, Stripes };

//! One rounded part of a creature. Solid parts make the outline; bumps sit on what is below.
struct Part
{
  Kind kind = Kind::Ellipse;
  Vec2 c{0, 0}, r{1, 1};  // ellipse centre, radii
  double angleDeg = 0;    // ellipse rotation; stripe direction
  Vec2 a{0, 0}, b{0, 0};  // capsule ends
  double ra = 1, rb = 1;  // capsule radii at a, b
  std::vector<Vec2> poly; // polygon (any winding)
  Hsv3 color{0, 0, 0};
  double relief = 1;      // peak height as a fraction of the creature's depth
  double round = 1;       // edge rounding radius as a fraction of the part's inner radius
  bool bump = false;      // added on top of what lies below instead of making the outline
  Pattern pattern = Pattern::None;
  Hsv3 patColor{0, 0, 0};
  double patScale = 8;    // spot spacing / stripe period (mm)
  double patFill = 0.35;  // spot radius / stripe duty fraction
  double patAngleDeg = 0; // stripe direction

  double innerRadius() const
  {
    switch (kind) {
    case Kind::Ellipse:
      return std::min(r.x, r.y);
    case Kind::Capsule:
      return std::max(ra, rb);
    case Kind::Polygon: {
      double cx = 0, cy = 0;
      for (const auto &p : poly) {
        cx += p.x;
        cy += p.y;
      }
      cx /= static_cast<double>(poly.size());
      cy /= static_cast<double>(poly.size());
      return std::max(1.0, -sdf(cx, cy));
    }
    }
    return 1;
  }

  double sdf(double x, double y) const
  {
    switch (kind) {
    case Kind::Ellipse: {
      const double t = angleDeg * M_PI / 180, ct = std::cos(t), st = std::sin(t);
      const double lx = ct * (x - c.x) + st * (y - c.y), ly = -st * (x - c.x) + ct * (y - c.y);
      const double k0 = std::hypot(lx / r.x, ly / r.y), k1 = std::hypot(lx / (r.x * r.x), ly / (r.y * r.y));
      return k1 > 1e-12 ? k0 * (k0 - 1.0) / k1 : -std::min(r.x, r.y);
    }
    case Kind::Capsule: {
      const double bx = b.x - a.x, by = b.y - a.y, l2 = bx * bx + by * by;
      const double t = l2 > 0 ? std::clamp(((x - a.x) * bx + (y - a.y) * by) / l2, 0.0, 1.0) : 0.0;
      return std::hypot(x - a.x - t * bx, y - a.y - t * by) - (ra + t * (rb - ra));
    }
    case Kind::Polygon: {
      double d = 1e30;
      bool in = false;
      for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const Vec2 &p = poly[i], &q = poly[j];
        const double ex = q.x - p.x, ey = q.y - p.y, l2 = ex * ex + ey * ey;
        const double t = l2 > 0 ? std::clamp(((x - p.x) * ex + (y - p.y) * ey) / l2, 0.0, 1.0) : 0.0;
        d = std::min(d, std::hypot(x - p.x - t * ex, y - p.y - t * ey));
        if ((p.y > y) != (q.y > y) && x < (q.x - p.x) * (y - p.y) / (q.y - p.y) + p.x)
          in = !in;
      }
      return in ? -d : d;
    }
    }
    return 1e30;
  }

  void bounds(double &x0, double &y0, double &x1, double &y1) const
  {
    switch (kind) {
    case Kind::Ellipse: {
      const double t = angleDeg * M_PI / 180;
      const double hx = std::hypot(r.x * std::cos(t), r.y * std::sin(t));
      const double hy = std::hypot(r.x * std::sin(t), r.y * std::cos(t));
      x0 = c.x - hx, x1 = c.x + hx, y0 = c.y - hy, y1 = c.y + hy;
      return;
    }
    case Kind::Capsule:
      x0 = std::min(a.x - ra, b.x - rb), x1 = std::max(a.x + ra, b.x + rb);
      y0 = std::min(a.y - ra, b.y - rb), y1 = std::max(a.y + ra, b.y + rb);
      return;
    case Kind::Polygon:
      x0 = y0 = 1e30, x1 = y1 = -1e30;
      for (const auto &p : poly)
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
      return;
    }
  }
};

// Small constructors that keep the creature descriptions readable.
Part ellipse(Vec2 c, Vec2 r, double angleDeg, Hsv3 col, double relief, double round = 1)
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
Part capsule(Vec2 a, Vec2 b, double ra, double rb, Hsv3 col, double relief, double round = 1)
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
Part polygon(std::vector<Vec2> pts, Hsv3 col, double relief, double round = 1)
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
Part spots(Part p, Hsv3 col, double scale, double fill = 0.3)
{
  p.pattern = Pattern::Spots;
  p.patColor = col;
  p.patScale = scale;
  p.patFill = fill;
  return p;
}
Part stripes(Part p, Hsv3 col, double period, double angleDeg, double duty = 0.3)
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

struct Creature
{
  TargetInfo info;
  std::vector<Part> parts;
  std::uint64_t seed;
  double mottle = 0.12; // value variation of the surface (fraction)
};

void hsvToRgb(const Hsv3 &c, double rgb[3])
{
  const double h = std::fmod(std::fmod(c.h, 360.0) + 360.0, 360.0) / 60.0;
  const double s = std::clamp(c.s, 0.0, 1.0), v = std::clamp(c.v, 0.0, 1.0);
  const int i = static_cast<int>(std::floor(h)) % 6;
  const double f = h - std::floor(h), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  const double tab[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
  rgb[0] = tab[i][0], rgb[1] = tab[i][1], rgb[2] = tab[i][2];
}

//! Writes colour \e c into texel \e k of \e s (8-bit RGB).
void setTexel(TargetShape &s, std::size_t k, const Hsv3 &c)
{
  double rgb[3];
  hsvToRgb(c, rgb);
  for (int ch = 0; ch < 3; ++ch)
    s.rgb[3 * k + static_cast<std::size_t>(ch)] = static_cast<std::uint8_t>(std::lround(std::clamp(rgb[ch], 0.0, 1.0) * 255));
}

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

  TargetShape s;
  s.info = cr.info;
  s.texelMm = texelMm;
  s.cols = static_cast<int>(std::ceil((cr.info.widthMm + 2 * margin) / texelMm));
  s.rows = static_cast<int>(std::ceil((cr.info.heightMm + 2 * margin) / texelMm));
  s.originCol = (s.cols - 1) / 2.0;
  s.originRow = (s.rows - 1) / 2.0;
  const std::size_t n = static_cast<std::size_t>(s.cols) * s.rows;
  s.rgb.assign(3 * n, 0);
  s.sdf.assign(n, 0.f);
  s.height.assign(n, 0.f);

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

// ---- The 12 creatures. Coordinates in mm near their final size: x right, y down. ----

Creature seahorse()
{
  const Hsv3 body{48, 0.85, 0.9}, ring{32, 0.85, 0.62}, dark{25, 0.6, 0.25};
  Creature c{{"C01", "seahorse", 45, 130, 27}, {}, 101};
  auto &P = c.parts;
  P.push_back(ellipse({6, -50}, {11, 8.5}, -12, body, 0.85));
  P.push_back(capsule({12, -52}, {30, -47}, 3.8, 3.0, body, 0.55));
  P.push_back(ellipse({1, -61}, {5, 5}, 0, ring, 0.8));
  P.push_back(stripes(capsule({3, -43}, {-3, -24}, 8, 9.5, body, 0.9), ring, 7, 90, 0.25));
  P.push_back(stripes(ellipse({0, -4}, {12.5, 22}, 8, body, 1.0), ring, 7, 90, 0.25));
  P.push_back(polygon({{-11, -16}, {-20, -4}, {-11, 8}}, {40, 0.6, 0.95}, 0.35));
  std::vector<Part> tail;
  chain(tail, {{-2, 14}, {2, 33}, {-1, 48}, {-9, 58}, {-17, 53}, {-14, 45}}, 8, 2.5, body, 0.8);
  for (auto &t : tail)
    P.push_back(stripes(t, ring, 6, 80, 0.3));
  P.push_back(bump(ellipse({9, -52}, {2.4, 2.4}, 0, dark, 0.08)));
  return c;
}

Creature coelacanth()
{
  const Hsv3 body{30, 0.6, 0.5}, spot{45, 0.35, 0.9}, fin{24, 0.55, 0.42};
  Creature c{{"C02", "coelacanth", 145, 70, 60}, {}, 202};
  auto &P = c.parts;
  P.push_back(spots(ellipse({0, 0}, {55, 24}, 0, body, 1.0), spot, 9, 0.45));
  P.push_back(spots(ellipse({-50, 2}, {21, 18}, 0, body, 0.9), spot, 9, 0.4));
  P.push_back(polygon({{48, 0}, {72, -24}, {66, 0}, {72, 24}}, fin, 0.35));
  P.push_back(capsule({50, 0}, {75, 0}, 6, 4, fin, 0.4));
  for (const auto &f : std::vector<std::pair<Vec2, Vec2>>{{{-25, 15}, {-31, 34}}, {{10, 18}, {7, 35}},
                                                          {{5, -20}, {12, -34}}, {{30, -17}, {38, -29}},
                                                          {{32, 15}, {40, 28}}})
    P.push_back(capsule(f.first, f.second, 6, 4, fin, 0.35));
  P.push_back(bump(ellipse({-58, -4}, {3.5, 3.5}, 0, {40, 0.5, 0.15}, 0.06)));
  return c;
}

Creature morayEel()
{
  const Hsv3 body{95, 0.7, 0.55}, spot{85, 0.8, 0.28};
  Creature c{{"C03", "moray eel", 142, 30, 23}, {}, 303};
  auto &P = c.parts;
  std::vector<Vec2> spine;
  for (int i = 0; i <= 12; ++i) {
    const double x = -60 + 11 * i;
    spine.push_back({x, 6 * std::sin(x / 18.0)});
  }
  std::vector<Part> b;
  chain(b, spine, 9, 3, body, 1.0);
  for (auto &p : b)
    P.push_back(spots(p, spot, 6, 0.45));
  P.push_back(spots(ellipse({-62, -1}, {12, 9}, -5, body, 0.95), spot, 6, 0.4));
  P.push_back(capsule({-73, 3}, {-60, 5}, 3, 3, {90, 0.6, 0.45}, 0.5));
  P.push_back(bump(ellipse({-66, -4}, {2.2, 2.2}, 0, {55, 0.8, 0.9}, 0.1)));
  return c;
}

Creature dolphin()
{
  const Hsv3 body{340, 0.45, 0.85}, fin{335, 0.5, 0.7};
  Creature c{{"C04", "dolphin", 80, 60, 45}, {}, 404};
  auto &P = c.parts;
  chain(P, {{30, 24}, {16, 6}, {-4, -9}, {-24, -11}}, 4, 11, body, 1.0);
  P.push_back(capsule({-24, -11}, {-41, -4}, 10, 3.5, body, 0.8));
  P.push_back(polygon({{-3, -17}, {6, -31}, {11, -13}}, fin, 0.4));
  P.push_back(capsule({-12, 1}, {-19, 14}, 4.5, 2, fin, 0.4));
  P.push_back(polygon({{29, 23}, {19, 37}, {34, 29}, {46, 33}}, fin, 0.35));
  P.push_back(bump(ellipse({-29, -13}, {2.2, 2.2}, 0, {330, 0.4, 0.2}, 0.08)));
  return c;
}

Creature squid()
{
  const Hsv3 mantle{22, 0.6, 0.75}, fins{26, 0.4, 0.85}, spot{12, 0.7, 0.5}, arm{18, 0.55, 0.7};
  Creature c{{"C05", "bigfin reef squid", 210, 82.5, 45}, {}, 505};
  auto &P = c.parts;
  P.push_back(spots(ellipse({35, 0}, {64, 39}, 0, fins, 0.25, 0.6), spot, 10, 0.3));
  P.push_back(spots(ellipse({30, 0}, {60, 20}, 0, mantle, 1.0), spot, 7, 0.45));
  P.push_back(ellipse({-38, 0}, {15, 14}, 0, mantle, 0.8));
  for (int k = 0; k < 8; ++k) {
    const double y = -10.5 + 3 * k, yEnd = -26 + 7.5 * k;
    chain(P, {{-48, y}, {-70, y * 1.5}, {-92, yEnd}}, 4, 1.5, arm, 0.3);
  }
  chain(P, {{-48, -2}, {-80, -8}, {-112, -4}}, 2.5, 3, arm, 0.25);
  chain(P, {{-48, 2}, {-80, 8}, {-112, 4}}, 2.5, 3, arm, 0.25);
  for (double s : {-1.0, 1.0})
    P.push_back(bump(ellipse({-38, 9 * s}, {4, 3.5}, 0, {30, 0.5, 0.2}, 0.1)));
  return c;
}

Creature jellyfish()
{
  const Hsv3 bell{310, 0.5, 0.85}, arm{320, 0.6, 0.7}, spot{300, 0.25, 0.95};
  Creature c{{"C06", "jellyfish", 90, 90, 110}, {}, 606};
  auto &P = c.parts;
  P.push_back(spots(ellipse({0, -15}, {42, 30}, 0, bell, 1.0), spot, 8, 0.35));
  for (double x : {-12.0, 0.0, 12.0})
    chain(P, {{x, 8}, {x * 1.3 + 4, 26}, {x * 1.6, 44}}, 6, 3, arm, 0.35);
  for (int k = 0; k < 6; ++k) {
    const double x = -35 + 14 * k;
    chain(P, {{x, 8}, {x + 4, 24}, {x - 2, 38}, {x + 3, 48}}, 2, 1, arm, 0.15);
  }
  return c;
}

Creature turtle()
{
  const Hsv3 shell{70, 0.4, 0.42}, ridge{60, 0.5, 0.25}, skin{65, 0.3, 0.5}, spot{60, 0.15, 0.85};
  Creature c{{"C07", "leatherback sea turtle", 105, 132, 30}, {}, 707};
  auto &P = c.parts;
  P.push_back(stripes(ellipse({0, 5}, {38, 52}, 0, shell, 1.0), ridge, 12, 0, 0.18));
  P.push_back(spots(ellipse({0, -55}, {13, 14}, 0, skin, 0.6), spot, 6, 0.3));
  for (double s : {-1.0, 1.0}) {
    P.push_back(spots(capsule({s * 28, -25}, {s * 54, -4}, 10, 5, skin, 0.3), spot, 6, 0.3));
    P.push_back(ellipse({s * 22, 55}, {10, 14}, s * 30, skin, 0.3));
  }
  P.push_back(capsule({0, 55}, {0, 66}, 5, 2, skin, 0.3));
  return c;
}

Creature octopus()
{
  const Hsv3 body{2, 0.8, 0.7}, sucker{15, 0.35, 0.95};
  Creature c{{"C08", "octopus", 143, 125, 35}, {}, 808};
  auto &P = c.parts;
  P.push_back(spots(ellipse({0, -35}, {28, 32}, 0, body, 1.0), sucker, 7, 0.25));
  P.push_back(ellipse({0, -5}, {22, 16}, 0, body, 0.8));
  for (int k = 0; k < 8; ++k) {
    const double a = (200.0 + 20.0 * k) * M_PI / 180.0, curl = (k % 2 ? 1.0 : -1.0) * 0.5;
    std::vector<Vec2> pts;
    for (int i = 0; i <= 5; ++i) {
      const double rr = 8 + 13 * i, aa = a + curl * i * 0.12;
      pts.push_back({rr * std::cos(aa) * 1.1, 5 - rr * std::sin(aa)});
    }
    std::vector<Part> arm;
    chain(arm, pts, 8, 2, body, 0.35);
    for (auto &p : arm)
      P.push_back(spots(p, sucker, 5, 0.3));
  }
  for (double s : {-1.0, 1.0})
    P.push_back(bump(ellipse({12 * s, -8}, {4, 3.5}, 0, {50, 0.4, 0.9}, 0.1)));
  return c;
}

Creature anemonefish()
{
  const Hsv3 body{25, 0.9, 0.95}, white{30, 0.05, 0.97}, fin{22, 0.9, 0.85};
  Creature c{{"C09", "anemonefish", 120, 36, 50}, {}, 909};
  auto &P = c.parts;
  P.push_back(ellipse({0, 0}, {45, 16}, 0, body, 1.0));
  P.push_back(ellipse({-40, 1}, {14, 13}, 0, body, 0.9));
  P.push_back(polygon({{42, 0}, {60, -16}, {55, 0}, {60, 16}}, fin, 0.3));
  P.push_back(capsule({-10, -14}, {25, -15}, 4, 3, fin, 0.3));
  P.push_back(bump(capsule({-33, -13}, {-33, 13}, 4, 4, white, 0.04)));
  P.push_back(bump(capsule({0, -15}, {0, 15}, 4.5, 4.5, white, 0.04)));
  P.push_back(bump(capsule({38, -9}, {38, 9}, 3, 3, white, 0.04)));
  P.push_back(bump(ellipse({-45, -3}, {2.5, 2.5}, 0, {20, 0.5, 0.15}, 0.05)));
  return c;
}

Creature mobula()
{
  const Hsv3 body{265, 0.45, 0.55}, wing{270, 0.4, 0.5}, tip{275, 0.35, 0.35};
  Creature c{{"C10", "mobula", 100, 80, 20}, {}, 1010};
  auto &P = c.parts;
  P.push_back(ellipse({0, 0}, {18, 22}, 0, body, 1.0));
  for (double s : {-1.0, 1.0}) {
    P.push_back(spots(polygon({{5 * s, -15}, {50 * s, 5}, {8 * s, 18}}, wing, 0.5, 0.8), tip, 9, 0.3));
    P.push_back(capsule({8 * s, -20}, {10 * s, -32}, 3, 2.5, tip, 0.4));
  }
  P.push_back(capsule({0, 20}, {0, 48}, 2.5, 1, tip, 0.3));
  return c;
}

Creature ribbontailRay()
{
  const Hsv3 disc{40, 0.55, 0.7}, blue{205, 0.8, 0.9};
  Creature c{{"C11", "bluespotted ribbontail ray", 85, 150, 15}, {}, 1111};
  auto &P = c.parts;
  P.push_back(spots(ellipse({0, -25}, {42, 48}, 0, disc, 1.0), blue, 9, 0.35));
  P.push_back(stripes(capsule({0, 20}, {0, 100}, 6, 1.5, disc, 0.4), blue, 10, 90, 0.2));
  for (double s : {-1.0, 1.0})
    P.push_back(bump(ellipse({10 * s, -40}, {3, 3}, 0, {35, 0.5, 0.2}, 0.15)));
  return c;
}

Creature crab()
{
  const Hsv3 shell{8, 0.85, 0.8}, claw{12, 0.85, 0.75}, leg{16, 0.75, 0.7}, spot{20, 0.3, 0.92};
  Creature c{{"C12", "crab", 175, 140, 40}, {}, 1212};
  auto &P = c.parts;
  P.push_back(spots(ellipse({0, 10}, {55, 42}, 0, shell, 1.0), spot, 9, 0.25));
  for (double s : {-1.0, 1.0}) {
    P.push_back(capsule({s * 15, -26}, {s * 16, -36}, 3, 3, shell, 0.9));
    P.push_back(capsule({s * 45, -12}, {s * 64, -42}, 9, 8, claw, 0.6));
    P.push_back(ellipse({s * 72, -56}, {20, 13}, s * 55, claw, 0.75));
    P.push_back(capsule({s * 78, -70}, {s * 66, -82}, 5, 3, claw, 0.55));
    for (int k = 0; k < 3; ++k) {
      const double y = 5 + 14 * k;
      chain(P, {{s * 50, y}, {s * 82, y + 12}, {s * 86, y + 32}}, 5, 2.5, leg, 0.35);
    }
  }
  for (double s : {-1.0, 1.0})
    P.push_back(bump(ellipse({s * 16, -37}, {3.5, 3.5}, 0, {0, 0.6, 0.22}, 0.05)));
  return c;
}

const std::vector<std::function<Creature()>> &builders()
{
  static const std::vector<std::function<Creature()>> b = {seahorse, coelacanth, morayEel, dolphin, squid, jellyfish,
                                                           turtle, octopus, anemonefish, mobula, ribbontailRay, crab};
  return b;
}

// ---- The relief targets R1..R3: bodies a flat photo-model cannot fake (steep sides, an
// outline above the backdrop, a nearest point off the centre). Built on the grid directly. ----

//! One texel of a relief target: signed distance to the outline, top and underside heights, colour.
struct ReliefTexel
{
  double sdf = 1, top = 0, base = 0;
  Hsv3 col{0, 0, 0.5};
};

//! Steep wall of height \e H with a rounded top edge, \e d mm inside the outline: a straight ramp from
//! 0 to H - r over the first millimetre (the mesh's step), continued as a straight line outside,
//! then a quarter round of radius \e r up to H. The ramp is straight across the outline so that the
//! mesh, cut where its interpolated signed distance is 0, is cut exactly at height 0 (a curved
//! profile there leaves the cut too high or too low by millimetres: gaps under the walls).
double wallProfile(double d, double H, double r)
{
  const double w = 1.0;
  if (d <= w)
    return (H - r) * d / w;
  const double t = std::min(1.0, (d - w) / r);
  return H - r + r * std::sqrt(1.0 - (1.0 - t) * (1.0 - t));
}

//! edgeProfile(d / R) with its first millimetre straight (the secant), for the same reason.
double roundProfile(double d, double R)
{
  return d >= 1.0 ? edgeProfile(d / R, 1.0 / R) : d * edgeProfile(1.0 / R, 1.0 / R);
}

//! Signed distance to a rectangle of half sizes (hx, hy) centred at (cx, cy), corners rounded by rc.
double roundRectSdf(double x, double y, double cx, double cy, double hx, double hy, double rc)
{
  const double qx = std::fabs(x - cx) - (hx - rc), qy = std::fabs(y - cy) - (hy - rc);
  return std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0) - rc;
}

//! Signed distance to an ellipse (the same approximation as the creatures' parts).
double ellipseSdf(double x, double y, double cx, double cy, double rx, double ry)
{
  const double lx = x - cx, ly = y - cy;
  const double k0 = std::hypot(lx / rx, ly / ry), k1 = std::hypot(lx / (rx * rx), ly / (ry * ry));
  return k1 > 1e-12 ? k0 * (k0 - 1.0) / k1 : -std::min(rx, ry);
}

double smooth01(double t)
{
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

//! A smooth bump (Gaussian) of amplitude \e a at (cx, cy), widths (sx, sy).
double bumpAt(double x, double y, double cx, double cy, double sx, double sy, double a)
{
  const double u = (x - cx) / sx, v = (y - cy) / sy;
  return a * std::exp(-0.5 * (u * u + v * v));
}

//! True where (x, y) falls on a random dot of a lattice of \e cell mm (radius \e r mm, density \e p).
bool dotAt(double x, double y, double cell, double r, double p, std::uint64_t seed)
{
  const auto ci = static_cast<std::int64_t>(std::floor(x / cell)), cj = static_cast<std::int64_t>(std::floor(y / cell));
  for (std::int64_t j = cj - 1; j <= cj + 1; ++j)
    for (std::int64_t i = ci - 1; i <= ci + 1; ++i) {
      if (latticeValue(i, j, seed + 3) > p)
        continue;
      const double sx = (static_cast<double>(i) + latticeValue(i, j, seed)) * cell;
      const double sy = (static_cast<double>(j) + latticeValue(i, j, seed + 1)) * cell;
      const double rr = r * (0.6 + 0.8 * latticeValue(i, j, seed + 2));
      if (std::hypot(x - sx, y - sy) < rr)
        return true;
    }
  return false;
}

//! Fills a shape's grids from \e at(x, y) (mm, nominal centre at 0), then frames it on its outline.
TargetShape reliefGrid(const TargetInfo &info, double texelMm, bool underside, std::uint64_t seed,
                       const std::function<ReliefTexel(double, double)> &at)
{
  const double margin = 4.0;
  TargetShape s;
  s.info = info;
  s.texelMm = texelMm;
  s.cols = static_cast<int>(std::ceil((info.widthMm + 2 * margin) / texelMm));
  s.rows = static_cast<int>(std::ceil((info.heightMm + 2 * margin) / texelMm));
  s.originCol = (s.cols - 1) / 2.0;
  s.originRow = (s.rows - 1) / 2.0;
  const std::size_t n = static_cast<std::size_t>(s.cols) * static_cast<std::size_t>(s.rows);
  s.rgb.assign(3 * n, 0);
  s.sdf.assign(n, 0.f);
  s.height.assign(n, 0.f);
  if (underside)
    s.base.assign(n, 0.f);
#pragma omp parallel for schedule(dynamic, 8)
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      const double x = (c - s.originCol) * texelMm, y = (r - s.originRow) * texelMm;
      const ReliefTexel t = at(x, y);
      const std::size_t k = static_cast<std::size_t>(r) * static_cast<std::size_t>(s.cols) + static_cast<std::size_t>(c);
      s.sdf[k] = static_cast<float>(t.sdf);
      s.height[k] = static_cast<float>(t.top);
      if (underside)
        s.base[k] = static_cast<float>(t.base);
      Hsv3 col = t.col;
      // Fine grain for stereo matching: a little value noise at the texel scale.
      col.v *= 1.0 + 0.06 * (2.0 * latticeValue(c, r, seed + 77) - 1.0);
      setTexel(s, k, col);
    }
  s.centreOnOutline();
  return s;
}

//! R1: a cardboard box with a landscape poster on its front face.
TargetShape reliefBox(double texelMm)
{
  const TargetInfo info{"R1", "poster box", 140, 100, 30};
  const double hx = 70, hy = 50, H = 30, roundMm = 2.5;
  const std::uint64_t seed = 2101;
  const Hsv3 card{33, 0.55, 0.62};
  auto poster = [&](double x, double y) {
    // Landscape in poster colours: sunset sky, sun, violet mountains, green hills, a red barn,
    // a field of yellow and orange rows with poppies. y down, the horizon at y = -8.
    const double u = x / 65.0; // about [-1, 1]
    Hsv3 c;
    const double mtn = -8 - 14 * fbm(x / 22.0, 0.0, seed + 1, 3) - 10 * std::max(0.0, 1 - std::fabs(x + 25) / 30);
    const double hill = 4 + 6 * std::sin(x / 17.0 + 1) + 3 * fbm(x / 9.0, 1.0, seed + 2, 2);
    if (y < mtn) {
      const double t = std::clamp((y + 45) / 45, 0.0, 1.0); // 0 top, 1 horizon
      c = {330 + 85 * t, 0.75 - 0.2 * t, 0.75 + 0.2 * t};    // magenta -> orange -> yellow
      const double cloud = fbm(x / 14.0, y / 4.0, seed + 3, 4);
      if (cloud > 0.58)
        c = {300 + 20 * cloud, 0.45, 0.85};
      if (std::hypot(x - 30, y + 26) < 11)
        c = {52, 0.55 + 0.3 * std::hypot(x - 30, y + 26) / 11, 1.0};
    } else if (y < hill) {
      c = {275 + 15 * fbm(x / 8, y / 8, seed + 4, 3), 0.5, 0.45 + 0.25 * (y - mtn) / 20}; // violet mountains
      if (y < mtn + 3 && x > -40 && x < -10)
        c = {280, 0.1, 0.95}; // snow cap
    } else if (y < 22) {
      c = {100 + 30 * fbm(x / 10, y / 10, seed + 5, 3), 0.7, 0.55};
      if (dotAt(x, y, 4.0, 1.4, 0.5, seed + 6))
        c = {130, 0.8, 0.3}; // trees
      if (x > -48 && x < -22 && y > hill + 2 && y < 20) { // the barn
        c = {2, 0.85, 0.72};
        if (std::fabs(x + 35) < 3 && y > 13)
          c = {30, 0.2, 0.95}; // its door
      }
    } else {
      const double row = std::sin((x + 0.35 * (y - 22) * u * 8) / 2.2);
      c = row > 0 ? Hsv3{50, 0.9, 0.9} : Hsv3{28, 0.9, 0.75}; // yellow and orange rows
      if (dotAt(x, y, 3.0, 0.9, 0.35, seed + 7))
        c = {0, 0.9, 0.85}; // poppies
    }
    c.v *= 0.88 + 0.24 * fbm(x / 1.5, y / 1.5, seed + 8, 3); // print texture
    c.h += 8 * (fbm(x / 6, y / 6, seed + 9, 2) - 0.5);
    return c;
  };
  return reliefGrid(info, texelMm, false, seed, [&](double x, double y) {
    ReliefTexel t;
    t.sdf = roundRectSdf(x, y, 0, 0, hx, hy, 3.0);
    t.top = wallProfile(-t.sdf, H, roundMm);
    if (-t.sdf < roundMm + 1.5) {
      t.col = card;
      t.col.v *= 0.9 + 0.2 * fbm(x / 2, y / 2, seed + 10, 3);
    } else {
      t.col = poster(x, y);
    }
    return t;
  });
}

//! R2: a head on a short stand, turned to its left (our right): outline 18 mm above the backdrop.
TargetShape reliefHead(double texelMm)
{
  const TargetInfo info{"R2", "head on a stand", 120, 150, 55};
  const double ax = 60, ay = 75, rim = 18, depth = 55;
  const std::uint64_t seed = 2202;
  const Hsv3 skin{22, 0.42, 0.88}, hair{16, 0.7, 0.36}, lips{355, 0.55, 0.72}, brow{20, 0.6, 0.3};
  auto raw = [&](double x, double y, ReliefTexel &t) {
    t.sdf = ellipseSdf(x, y, 0, 0, ax, ay);
    const double d = -t.sdf;
    // Top: a dome with a vertical rim, and the face's features (toward +x: the head is turned).
    double top = 28 * roundProfile(d, 55);
    const double feat = smooth01(d / 12);
    const double nose = bumpAt(x, y, 26, 4, 5.5, 12, 10) + bumpAt(x, y, 27, 15, 5, 4, 3);
    const double browRidge = bumpAt(x, y, 12, -17, 28, 4, 3.5);
    const double sockets = -bumpAt(x, y, -4, -7, 7, 5, 3) - bumpAt(x, y, 33, -7, 6, 5, 3);
    const double cheeks = bumpAt(x, y, -12, 14, 10, 9, 2.5) + bumpAt(x, y, 40, 14, 8, 9, 2);
    const double chin = bumpAt(x, y, 18, 52, 12, 8, 5), lip = bumpAt(x, y, 21, 33, 9, 3.5, 2.2);
    const double ear = bumpAt(x, y, -50, 2, 5, 11, 4);
    top += feat * (nose + browRidge + sockets + cheeks + chin + lip + ear);
    t.top = top; // above the rim, rescaled below
    // Underside: the back of the head curves 9 mm down from the rim; the stand reaches the backdrop.
    const double back = rim - 9 * roundProfile(d, 14);
    const double stand = std::max(0.0, (std::hypot(x, (y - 28) * 1.2) - 20) * 6);
    t.base = std::min(back, stand);
    // Colours.
    const double hairline = -32 + 6 * std::sin(x / 14.0);
    const bool inHair = y < hairline || (x < -40 && y < 28) || (x > 52 && y < -5);
    const bool inEar = std::hypot((x + 50) / 5.5, (y - 2) / 11.5) < 1;
    Hsv3 c = skin;
    c.v *= 0.92 + 0.12 * fbm(x / 3, y / 3, seed + 1, 3);
    c.s *= 0.9 + 0.2 * fbm(x / 10, y / 10, seed + 2, 2);
    if (inHair && !inEar) {
      const double strand = std::sin((x * 0.3 + y * 1.0 + 6 * fbm(x / 12, y / 12, seed + 3, 3)) * 2.4);
      c = hair;
      c.v *= 0.7 + 0.5 * (0.5 + 0.5 * strand) * (0.7 + 0.6 * latticeValue(static_cast<std::int64_t>(x * 2), 0, seed + 4));
      c.h += 10 * (fbm(x / 7, y / 7, seed + 5, 2) - 0.5);
    } else {
      if (dotAt(x, y, 2.6, 0.55, 0.45, seed + 6) && bumpAt(x, y, 18, 8, 30, 16, 1) > 0.25)
        c = {20, 0.62, 0.62}; // freckles over nose and cheeks
      if (std::hypot((x - 21) / 10, (y - 33) / 3.2) < 1)
        c = lips;
      for (const double ex : {-4.0, 33.0}) {
        if (std::hypot((x - ex) / 7.5, (y + 26 - 6) / 1.6 * 0.5) < 1 && y < -17 && y > -23)
          c = brow;
        const double e = std::hypot((x - ex) / 6.5, (y + 7) / 3.2);
        if (e < 1) {
          const double ri = std::hypot(x - ex - 1, y + 7);
          c = ri < 1.1 ? Hsv3{0, 0, 0.08} : ri < 2.8 ? Hsv3{95, 0.55, 0.45} : Hsv3{35, 0.06, 0.93};
        }
      }
      if (inEar && std::hypot((x + 50) / 3, (y - 2) / 8) < 1)
        c.v *= 0.8;
    }
    t.col = c;
  };
  // Scale the relief above the rim so that the nearest point is 'depth' from the backdrop.
  double peak = 0;
  for (double y = -ay; y <= ay; y += 0.5)
    for (double x = -ax; x <= ax; x += 0.5) {
      ReliefTexel t;
      raw(x, y, t);
      if (t.sdf < 0)
        peak = std::max(peak, t.top);
    }
  const double k = (depth - rim) / peak;
  return reliefGrid(info, texelMm, true, seed, [&](double x, double y) {
    ReliefTexel t;
    raw(x, y, t);
    t.top = rim + k * t.top;
    return t;
  });
}

//! R3: a three-tier pagoda standing on the backdrop, seen from the front (its top toward the camera).
TargetShape reliefTower(double texelMm)
{
  const TargetInfo info{"R3", "pagoda tower", 70, 90, 110};
  const std::uint64_t seed = 2303;
  struct Tier
  {
    double hx, hy, h0, h1, roof; // half sizes, base and eaves heights, roof rise inward
    Hsv3 roofCol, wallCol;
  };
  const Tier tiers[3] = {{35, 45, 0, 42, 5, {10, 0.75, 0.62}, {40, 0.45, 0.85}},
                         {25, 33, 47, 75, 5, {140, 0.6, 0.45}, {8, 0.7, 0.6}},
                         {15, 21, 80, 96, 4, {45, 0.8, 0.8}, {0, 0.75, 0.55}}};
  return reliefGrid(info, texelMm, false, seed, [&](double x, double y) {
    ReliefTexel t;
    t.sdf = roundRectSdf(x, y, 0, 0, tiers[0].hx, tiers[0].hy, 4);
    double top = -1e30;
    int on = 0;
    for (int i = 0; i < 3; ++i) {
      const Tier &T = tiers[i];
      const double d = -roundRectSdf(x, y, 0, 0, T.hx, T.hy, 4);
      const double prevTop = i == 0 ? 0.0 : tiers[i - 1].h1 + tiers[i - 1].roof;
      const double h = prevTop + wallProfile(d, T.h1 - prevTop, 2.0) + T.roof * smooth01(d / std::min(T.hx, T.hy));
      if (h > top)
        top = h, on = i;
    }
    // The spire: a rounded cone up to 110 mm.
    const double rs = std::hypot(x, y * 0.8);
    const double spireBase = tiers[2].h1 + tiers[2].roof;
    const double spire = spireBase + (110 - spireBase) * roundProfile(9 - rs, 9);
    if (spire > top)
      top = spire, on = 3;
    t.top = top;
    // Colours: roofs of tiles in rows, walls of bricks near each tier's edge, a gold spire.
    if (on == 3) {
      t.col = {48, 0.85, 0.85};
      t.col.v *= 0.85 + 0.3 * fbm(x / 1.5, y / 1.5, seed + 1, 2);
    } else {
      const Tier &T = tiers[on];
      const double d = -roundRectSdf(x, y, 0, 0, T.hx, T.hy, 4);
      if (d < 2.6) {
        t.col = T.wallCol;
        const double bx = x + y, brick = std::fmod(std::fabs(bx), 3.0);
        if (brick < 0.5)
          t.col.v *= 0.6; // mortar
      } else {
        t.col = T.roofCol;
        const double ring = std::fmod(d, 3.2); // tile rows parallel to the eaves
        t.col.v *= ring < 0.6 ? 0.65 : 1.0;
        if (dotAt(x, y, 3.5, 0.8, 0.3, seed + 2 + static_cast<std::uint64_t>(on)))
          t.col.s *= 0.5, t.col.v = std::min(1.0, t.col.v * 1.3); // weathered tiles
      }
      t.col.v *= 0.88 + 0.24 * fbm(x / 2, y / 2, seed + 5, 3);
    }
    return t;
  });
}

const std::vector<std::function<TargetShape(double)>> &reliefBuilders()
{
  static const std::vector<std::function<TargetShape(double)>> b = {reliefBox, reliefHead, reliefTower};
  return b;
}

std::string upper(const std::string &code)
{
  std::string u = code;
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
  return u;
}

int indexIn(const std::vector<TargetInfo> &cat, const std::string &code)
{
  const std::string u = upper(code);
  for (std::size_t i = 0; i < cat.size(); ++i)
    if (cat[i].code == u)
      return static_cast<int>(i);
  return -1;
}

int indexOf(const std::string &code) { return indexIn(targetCatalog(), code); }

int reliefIndexOf(const std::string &code) { return indexIn(reliefTargetCatalog(), code); }

} // namespace

const std::vector<TargetInfo> &targetCatalog()
{
  static const std::vector<TargetInfo> cat = [] {
    std::vector<TargetInfo> v;
    for (const auto &b : builders())
      v.push_back(b().info);
    return v;
  }();
  return cat;
}

const std::vector<TargetInfo> &reliefTargetCatalog()
{
  static const std::vector<TargetInfo> cat = {{"R1", "poster box", 140, 100, 30},
                                              {"R2", "head on a stand", 120, 150, 55},
                                              {"R3", "pagoda tower", 70, 90, 110}};
  return cat;
}

const std::vector<TargetInfo> &labTargetCatalog()
{
  static const std::vector<TargetInfo> cat = [] {
    std::vector<TargetInfo> v = targetCatalog();
    v.insert(v.end(), reliefTargetCatalog().begin(), reliefTargetCatalog().end());
    return v;
  }();
  return cat;
}

bool isCatalogTarget(const std::string &code) { return indexOf(code) >= 0 || reliefIndexOf(code) >= 0; }

bool isReliefTarget(const std::string &code) { return reliefIndexOf(code) >= 0; }

TargetShape makeTarget(const std::string &code, double texelMm)
{
  const int i = indexOf(code), ri = reliefIndexOf(code);
  if (i < 0 && ri < 0)
    throw core::Error("unknown target '" + code + "': the catalogue has C01..C12 and R1..R3");
  if (!(texelMm > 0.02 && texelMm <= 5))
    throw core::Error("target texel size must lie in (0.02, 5] mm");
  if (ri >= 0)
    return reliefBuilders()[static_cast<std::size_t>(ri)](texelMm);
  return rasterise(builders()[static_cast<std::size_t>(i)](), texelMm);
}

} // namespace pm::sim
