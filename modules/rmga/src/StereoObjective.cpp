#include "pm/rmga/StereoObjective.h"

#include <algorithm>

namespace pm::rmga {

void StereoObjective::evaluate(const core::Phi *poses, std::size_t n, double *fitness)
{
  if (m_score == Score::Fitness) {
    m_scorer.evaluate(m_frame, poses, n, fitness);
    return;
  }
  double cost[64]; // Coarse
  for (std::size_t b = 0; b < n; b += 64) // no allocation: in blocks
    m_scorer.evaluate(m_frame, poses + b, std::min<std::size_t>(64, n - b), fitness + b, 1e300, cost);
}

void StereoObjective::evaluateOrReject(const core::Phi *poses, std::size_t n, double rejectBelow, double *fitness, double *cost)
{
  if (m_score == Score::Coarse)
    m_scorer.evaluate(m_frame, poses, n, fitness, 1e300, cost); // every pose on the first share of points
  else if (m_rejectMargin < 0 || !(rejectBelow > -1e300))
    FitnessFunction::evaluateOrReject(poses, n, rejectBelow, fitness, cost);
  else
    m_scorer.evaluate(m_frame, poses, n, fitness, rejectBelow - m_rejectMargin, cost);
}

} // namespace pm::rmga
