#include "pm/sim/Clutter.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Hue.h"
#include "pm/sim/TargetCatalog.h"

namespace pm::sim {

namespace {
//! The smallest angle between two hues (degrees).
double hueGapDeg(double a, double b)
{
  const double d = std::fabs(a - b);
  return std::min(d, 360 - d);
}
} // namespace

double meanHueDeg(const TargetShape &target)
{
  double sx = 0, sy = 0;
  for (std::size_t i = 0; i < target.sdf.size(); ++i) {
    if (target.sdf[i] >= 0)
      continue;
    const core::Hsv c = core::rgbToHsv(target.rgb[3 * i], target.rgb[3 * i + 1], target.rgb[3 * i + 2]);
    const double a = c.h * M_PI / 180;
    sx += c.s * std::cos(a);
    sy += c.s * std::sin(a);
  }
  const double h = std::atan2(sy, sx) * 180 / M_PI;
  return h < 0 ? h + 360 : h;
}

std::vector<ClutterToy> clutterAround(const TargetShape &target)
{
  const std::string own = target.info.code;
  const double hue = meanHueDeg(target);
  // The sea creature nearest in hue (the relief targets are not toys to stand about).
  std::string similar;
  double best = 1e9;
  for (const TargetInfo &t : targetCatalog()) {
    if (t.code == own)
      continue;
    const double gap = hueGapDeg(hue, meanHueDeg(makeTarget(t.code, 1.0)));
    if (gap < best) {
      best = gap;
      similar = t.code;
    }
  }
  // Then two of another hue: the moray eel (green), the mobula (blue), or the next ones.
  std::vector<std::string> codes{similar};
  for (const char *c : {"C03", "C10", "C06", "C07"})
    if (codes.size() < 3 && c != own && c != similar)
      codes.push_back(c);

  // Left, right, below (+y), 25 mm clear of the nominal outlines, each a little turned about z.
  const double sideX[3] = {-1, 1, 0}, sideY[3] = {0, 0, 1}, turnDeg[3] = {10, -15, 20};
  std::vector<ClutterToy> out;
  for (std::size_t i = 0; i < codes.size(); ++i) {
    const TargetInfo &n = *std::find_if(targetCatalog().begin(), targetCatalog().end(),
                                        [&](const TargetInfo &t) { return t.code == codes[i]; });
    ClutterToy t;
    t.code = codes[i];
    t.similarHue = i == 0;
    t.poseMm[0] = sideX[i] * (target.info.widthMm / 2 + n.widthMm / 2 + 25);
    t.poseMm[1] = sideY[i] * (target.info.heightMm / 2 + n.heightMm / 2 + 25);
    t.poseMm[5] = std::sin(turnDeg[i] * M_PI / 360);
    out.push_back(t);
  }
  return out;
}

} // namespace pm::sim
