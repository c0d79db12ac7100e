#include "pm/tracker/FramePlan.h"

#include <algorithm>
#include <cmath>

#include "pm/tracker/LockVerifier.h"
#include "pm/tracker/PoseSearch.h"
#include "pm/tracker/SteadyFramePolicy.h"

namespace pm::tracker {

rmga::FrameBudget budgetPart(const rmga::FrameBudget &b, double fraction, int population)
{
  if (b.evaluations > 0)
    return rmga::FrameBudget::evals(std::max<long>(population, std::lround(fraction * static_cast<double>(b.evaluations))));
  return rmga::FrameBudget::ms(fraction * b.milliseconds);
}

void FramePlan::setBudgets(const SearchParams &search, const SteadyParams &steadyParams, const VerifierParams &verifier)
{
  const int population = search.ga.population;
  rmga::FrameBudget whole = search.budget();
  if (whole.milliseconds > 0) // the hue planes are part of the frame's time
    whole.milliseconds = std::max(0.05, whole.milliseconds - hueMs);
  mainWhole = verifying ? budgetPart(whole, 1.0 - verifier.budgetFraction, population) : whole;
  main = steady ? budgetPart(search.budget(), steadyParams.budgetFraction, population) : mainWhole;
  challenger = budgetPart(whole, verifier.budgetFraction, population);
}

} // namespace pm::tracker
