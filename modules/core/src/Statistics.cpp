#include "pm/core/Statistics.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::core {

double percentile(std::vector<double> values, double fraction)
{
  if (!(fraction > 0 && fraction <= 1))
    throw Error("percentile: the fraction must be in (0, 1]");
  if (values.empty())
    return 0;
  const std::size_t rank = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(values.size())));
  const std::size_t k = std::min(values.size(), std::max<std::size_t>(rank, 1)) - 1;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

double median(std::vector<double> values)
{
  if (values.empty())
    return 0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

} // namespace pm::core
