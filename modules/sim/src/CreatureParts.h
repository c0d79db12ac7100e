#pragma once
/*!
  \file CreatureParts.h
  The sea creatures C01..C12 as the catalogue draws them (private to it): each a union of rounded
  parts (ellipses, capsules, polygons) with a colour, a relief and a pattern, and bumps on top;
  rasterise() turns a creature into its target grid (outline, height, colour). The creatures
  themselves: Creatures.cpp.
*/
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "TargetTexels.h"
#include "pm/sim/TargetShape.h"

namespace pm::sim::catalog {

struct Vec2
{
  double x, y;
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

struct Creature
{
  TargetInfo info;
  std::vector<Part> parts;
  std::uint64_t seed;
  double mottle = 0.12; // value variation of the surface (fraction)
};

// Small constructors that keep the creature descriptions readable.
Part ellipse(Vec2 c, Vec2 r, double angleDeg, Hsv3 col, double relief, double round = 1);
Part capsule(Vec2 a, Vec2 b, double ra, double rb, Hsv3 col, double relief, double round = 1);
Part polygon(std::vector<Vec2> pts, Hsv3 col, double relief, double round = 1);
Part bump(Part p);
Part spots(Part p, Hsv3 col, double scale, double fill = 0.3);
Part stripes(Part p, Hsv3 col, double period, double angleDeg, double duty = 0.3);
//! A chain of capsules through \e pts with radius tapering from r0 to r1.
void chain(std::vector<Part> &out, const std::vector<Vec2> &pts, double r0, double r1, Hsv3 col, double relief);

//! The creature's target: its parts scaled to its nominal size on a grid of \e texelMm texels.
TargetShape rasterise(const Creature &cr, double texelMm);

//! C01..C12's descriptions, in the catalogue's order (Creatures.cpp).
const std::vector<std::function<Creature()>> &creatureBuilders();

} // namespace pm::sim::catalog
