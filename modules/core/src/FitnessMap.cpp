#include "pm/core/FitnessMap.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::core {

FitnessMap computeFitnessMap(const StereoFitness &fitness, const Phi &reference, const FitnessMapSpec &spec,
                             double topFraction)
{
  if (spec.a > 5 || spec.b > 5 || spec.a == spec.b || !(spec.step > 0) || !(spec.hiA > spec.loA) ||
      !(spec.hiB > spec.loB) || (spec.hiA - spec.loA) / spec.step > 1e5 || (spec.hiB - spec.loB) / spec.step > 1e5)
    throw Error("fitness map: two different variables of phi, increasing ranges and a positive step are needed");
  if (!(topFraction >= 0 && topFraction < 1))
    throw Error("fitness map: the top fraction must lie in [0, 1)");
  FitnessMap m;
  m.spec = spec;
  m.nA = static_cast<int>(std::lround((spec.hiA - spec.loA) / spec.step)) + 1;
  m.nB = static_cast<int>(std::lround((spec.hiB - spec.loB) / spec.step)) + 1;
  m.values.assign(static_cast<std::size_t>(m.nA) * m.nB, 0.0);
  const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(dynamic, 4)
  for (int j = 0; j < m.nB; ++j) {
    Phi p = reference;
    p[spec.b] = m.coordB(j);
    for (int i = 0; i < m.nA; ++i) {
      p[spec.a] = m.coordA(i);
      m.values[static_cast<std::size_t>(j) * m.nA + i] = p.isValid() ? fitness.evaluate(p) : 0.0;
    }
  }
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto [lo, hi] = std::minmax_element(m.values.begin(), m.values.end());
  m.maxFitness = *hi;
  const double level = *hi - topFraction * (*hi - *lo);
  double sa = 0, sb = 0;
  bool first = true;
  for (int j = 0; j < m.nB; ++j)
    for (int i = 0; i < m.nA; ++i) {
      const double f = m.at(i, j);
      if (f == *hi && first) {
        m.argmaxA = m.coordA(i);
        m.argmaxB = m.coordB(j);
        first = false;
      }
      if (f >= level) {
        sa += m.coordA(i);
        sb += m.coordB(j);
        ++m.topCells;
      }
    }
  m.peakA = sa / m.topCells;
  m.peakB = sb / m.topCells;
  return m;
}

std::vector<FitnessMapSpec> paperFitnessMaps(double posStep, double epsStep)
{
  return {{0, 1, -180, 180, -180, 180, posStep},
          {1, 2, -180, 180, 320, 680, posStep},
          {3, 4, -0.37, 0.37, -0.37, 0.37, epsStep},
          {4, 5, -0.37, 0.37, -0.37, 0.37, epsStep}};
}

} // namespace pm::core
