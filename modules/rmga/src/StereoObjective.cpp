#include "pm/rmga/StereoObjective.h"

namespace pm {

void StereoObjective::evaluate(const Phi *poses, std::size_t n, double *fitness)
{
  if (m_score == Score::Fitness) {
    m_f.evaluate(poses, n, fitness);
    return;
  }
  for (std::size_t i = 0; i < n; ++i)
    fitness[i] = m_f.evaluateSmooth(poses[i]);
}

} // namespace pm
