#include "pm/trust/RangeBias.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "pm/core/Statistics.h"
#include "pm/core/Vec3.h"

namespace pm::trust {

namespace {

double distance(const core::Vec3 &a, const core::Vec3 &b) { return std::sqrt(core::dot(core::sub(a, b), core::sub(a, b))); }

core::Vec3 estimateOf(const PassTry &t) { return core::add(t.originMm, {t.error[0], t.error[1], t.error[2]}); }

} // namespace

double relativeRangeError(const PassTry &t, const std::array<double, 3> &centreMm)
{
  const double truth = distance(t.originMm, centreMm);
  return truth > 0 ? distance(estimateOf(t), centreMm) / truth - 1 : 0;
}

RangeBias measureRangeBias(const std::vector<PassTry> &tries, const std::array<double, 3> &centreMm, int minViews, double minPct, double maxPct)
{
  std::map<std::size_t, std::vector<double>> byView;
  for (const PassTry &t : tries)
    if (t.right() && t.cues.precise)
      byView[t.view].push_back(relativeRangeError(t, centreMm));
  RangeBias b;
  std::vector<double> views;
  for (const auto &[view, errors] : byView)
    views.push_back(core::median(errors));
  b.views = static_cast<int>(views.size());
  const double m = core::median(views);
  b.errorPct = 100 * m;
  for (double v : views)
    b.agreeing += (v > 0) == (m > 0) && v != 0;
  if (b.views >= minViews && b.agreeing >= b.views - 1 && std::fabs(b.errorPct) >= minPct)
    b.scale = 1 / (1 + std::clamp(m, -maxPct / 100, maxPct / 100));
  return b;
}

PassTry rangeCorrected(const PassTry &t, double scale, const std::array<double, 3> &centreMm)
{
  PassTry c = t;
  const core::Vec3 e = core::sub(core::add(centreMm, core::scaled(core::sub(estimateOf(t), centreMm), scale)), t.originMm);
  for (std::size_t i = 0; i < 3; ++i)
    c.error[i] = e[i];
  c.errorMm = std::sqrt(core::dot(e, e));
  return c;
}

} // namespace pm::trust
