#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace pcl {
namespace tda {

/** \brief A step of a count that changes with a scale (a distance, a colour
 * threshold): the count is constant on [low, high). */
struct StableStep {
  double low = 0.0;
  double high = 0.0;
  std::size_t count = 0;
  /** \brief Whether the step spans a factor of at least the gap ratio q and is at
   * least q times as long (in log) as every other step of a count of two or more. */
  bool clear = false;
};

/** \brief The automatic choice of the clustering distance and of the region colour
 * threshold: the step of a count of components over a scale that is stable over the
 * widest range of scales. The count starts at 0 and changes by the \a events (scale,
 * +1 or -1); its steps over [\a floor, \a max_scale) are compared by their length
 * on a logarithmic scale, log(high / low), so that only ratios of scales enter. The
 * longest step of a count of two or more is taken when it spans a factor of at least
 * \a gap_ratio, otherwise the longest step of a count of one, if any; the earliest
 * of equally long steps wins.
 * \param[in] events the changes of the count, in any order
 * \param[in] floor the smallest scale (> 0)
 * \param[in] max_scale the end of the scales (> floor)
 * \param[in] gap_ratio the ratio q (> 1)
 * \param[in] censor_last when true, a step that ends at \a max_scale, cut short so
 * that its true length is unknown, is taken only when no other step of a count of
 * two or more spans the gap ratio
 * \param[out] step the chosen step
 * \return false when no step has a positive count */
bool
longestStableStep (std::vector<std::pair<double, int>> events,
                   double floor,
                   double max_scale,
                   double gap_ratio,
                   bool censor_last,
                   StableStep& step);

} // namespace tda
} // namespace pcl
