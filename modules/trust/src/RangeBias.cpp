#include "pm/trust/RangeBias.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace pm::trust {

namespace {

double median(std::vector<double> v)
{
  if (v.empty())
    return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double distance(const std::array<double, 3> &a, const std::array<double, 3> &b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

std::array<double, 3> estimateOf(const PassTry &t)
{
  return {t.originMm[0] + t.error[0], t.originMm[1] + t.error[1], t.originMm[2] + t.error[2]};
}

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
    views.push_back(median(errors));
  b.views = static_cast<int>(views.size());
  const double m = median(views);
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
  const std::array<double, 3> e = estimateOf(t);
  double sum = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    c.error[i] = centreMm[i] + (e[i] - centreMm[i]) * scale - t.originMm[i];
    sum += c.error[i] * c.error[i];
  }
  c.errorMm = std::sqrt(sum);
  return c;
}

} // namespace pm::trust
