#include "pm/rmga/LocalSimplex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "pm/core/Error.h"

namespace pm::rmga {

void LocalSimplexParams::validate() const
{
  for (double s : step)
    if (!(s > 0 && std::isfinite(s)))
      throw core::Error("local simplex: every first step must be positive and finite");
  if (maxEvaluations < 7)
    throw core::Error("local simplex: at least 7 evaluations are needed (the first simplex)");
  if (!(tolerance >= 0 && tolerance < 1))
    throw core::Error("local simplex: the tolerance must lie in [0, 1)");
}

LocalSimplexResult refineLocalSimplex(FitnessFunction &f, const core::Phi &start, const LocalSimplexParams &params)
{
  params.validate();
  if (!start.isValid())
    throw core::Error("local simplex: invalid start pose " + start.toString());
  constexpr int kN = 6, kV = kN + 1;
  LocalSimplexResult r;
  // Minimises the negated score; an invalid pose is worse than any.
  auto cost = [&](const core::Phi &p) {
    ++r.evaluations;
    if (!p.isValid())
      return std::numeric_limits<double>::infinity();
    double v = 0;
    f.evaluate(&p, 1, &v);
    return -v;
  };
  std::array<core::Phi, kV> x;
  std::array<double, kV> c;
  x.fill(start);
  c[0] = cost(start);
  r.startFitness = -c[0];
  for (int i = 0; i < kN; ++i) {
    x[static_cast<std::size_t>(i + 1)][static_cast<std::size_t>(i)] += params.step[i];
    c[static_cast<std::size_t>(i + 1)] = cost(x[static_cast<std::size_t>(i + 1)]);
  }
  std::array<int, kV> order;
  auto sortVertices = [&] {
    for (int i = 0; i < kV; ++i)
      order[static_cast<std::size_t>(i)] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return c[static_cast<std::size_t>(a)] < c[static_cast<std::size_t>(b)]; });
    std::array<core::Phi, kV> xs;
    std::array<double, kV> cs;
    for (std::size_t i = 0; i < kV; ++i) {
      xs[i] = x[static_cast<std::size_t>(order[i])];
      cs[i] = c[static_cast<std::size_t>(order[i])];
    }
    x = xs;
    c = cs;
  };
  while (r.evaluations < params.maxEvaluations) {
    sortVertices(); // x[0] best, x[6] worst
    double spread = 0;
    for (std::size_t v = 1; v < kV; ++v)
      for (std::size_t d = 0; d < kN; ++d)
        spread = std::max(spread, std::fabs(x[v][d] - x[0][d]) / params.step[d]);
    if (spread <= params.tolerance)
      break;
    core::Phi centroid;
    for (std::size_t d = 0; d < kN; ++d) {
      double s = 0;
      for (std::size_t v = 0; v < kN; ++v)
        s += x[v][d];
      centroid[d] = s / kN;
    }
    auto along = [&](double t) { // centroid + t (worst - centroid)
      core::Phi p;
      for (std::size_t d = 0; d < kN; ++d)
        p[d] = centroid[d] + t * (x[kN][d] - centroid[d]);
      return p;
    };
    const core::Phi reflected = along(-1);
    const double cr = cost(reflected);
    if (cr < c[0]) {
      const core::Phi expanded = along(-2);
      const double ce = r.evaluations < params.maxEvaluations ? cost(expanded) : std::numeric_limits<double>::infinity();
      x[kN] = ce < cr ? expanded : reflected;
      c[kN] = std::min(ce, cr);
    } else if (cr < c[kN - 1]) {
      x[kN] = reflected;
      c[kN] = cr;
    } else {
      if (r.evaluations >= params.maxEvaluations) { // no budget left to contract
        if (cr < c[kN]) {
          x[kN] = reflected;
          c[kN] = cr;
        }
        break;
      }
      const core::Phi contracted = along(cr < c[kN] ? -0.5 : 0.5);
      const double cc = cost(contracted);
      if (cc < std::min(cr, c[kN])) {
        x[kN] = contracted;
        c[kN] = cc;
      } else {
        for (std::size_t v = 1; v < kV && r.evaluations < params.maxEvaluations; ++v) {
          for (std::size_t d = 0; d < kN; ++d)
            x[v][d] = x[0][d] + 0.5 * (x[v][d] - x[0][d]);
          c[v] = cost(x[v]);
        }
      }
    }
  }
  const std::size_t b = static_cast<std::size_t>(std::min_element(c.begin(), c.end()) - c.begin());
  r.best = x[b];
  r.fitness = -c[b];
  return r;
}

} // namespace pm::rmga
