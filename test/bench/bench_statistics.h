#pragma once
// Timing and summary statistics shared by the benchmarks.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <vector>

namespace pcl {
namespace tda {
namespace bench {

/** The wall time of \a work, in seconds. */
inline double
seconds (const std::function<void()>& work)
{
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double> (std::chrono::steady_clock::now() - start)
      .count();
}

/** The median of \a values (the mean of the middle two for an even count); NaN
 * when there is none. */
inline double
median (std::vector<double> values)
{
  if (values.empty())
    return std::nan ("");
  std::sort (values.begin(), values.end());
  const std::size_t half = values.size() / 2;
  return values.size() % 2 ? values[half] : 0.5 * (values[half - 1] + values[half]);
}

/** The mean of \a values; NaN when there is none. */
inline double
mean (const std::vector<double>& values)
{
  double sum = 0.0;
  for (const double v : values)
    sum += v;
  return values.empty() ? std::nan ("") : sum / static_cast<double> (values.size());
}

} // namespace bench
} // namespace tda
} // namespace pcl
