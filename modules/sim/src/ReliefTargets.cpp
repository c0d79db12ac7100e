#include "ReliefTargets.h"

#include <algorithm>
#include <cmath>

#include "TargetTexels.h"
#include "pm/sim/Noise.h"

namespace pm::sim::catalog {

namespace {

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
  TargetShape s = targetGrid(info, texelMm, 4.0, underside);
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

} // namespace

const std::vector<std::function<TargetShape(double)>> &reliefBuilders()
{
  static const std::vector<std::function<TargetShape(double)>> b = {reliefBox, reliefHead, reliefTower};
  return b;
}

} // namespace pm::sim::catalog
