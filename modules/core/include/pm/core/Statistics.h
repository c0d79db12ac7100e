#pragma once
/*!
  \file Statistics.h
  The statistics every program reports the same way (one definition each): percentiles of frame
  times, medians.
*/
#include <vector>

namespace pm::core {

/*!
  The \e fraction percentile of \e values by the nearest-rank rule: the smallest value with at
  least fraction x n values at or below it (fraction in (0, 1]; 0.99 gives the p99 that every
  program reports). 0 for no values. Throws pm::core::Error for a fraction outside (0, 1].

  \code
    const double p99 = pm::core::percentile({1.0, 2.0, 3.0, 4.0}, 0.99); // 4
    const double median = pm::core::percentile({1.0, 2.0, 3.0, 4.0}, 0.5); // 2
  \endcode
*/
double percentile(std::vector<double> values, double fraction);

/*!
  The median of \e values: the middle value, or the mean of the two middle ones for an even count;
  0 for no values.

  \code
    const double m = pm::core::median({4.0, 1.0, 3.0, 2.0}); // 2.5
  \endcode
*/
double median(std::vector<double> values);

} // namespace pm::core
