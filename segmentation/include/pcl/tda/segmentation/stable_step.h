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

/** \brief Which split chooseStableStep() takes. */
enum class StableStepPreference {
  /** The longest split when it is clear (at least the gap ratio times as long, in log,
   * as every other split), otherwise the finest split that is stable: region colours,
   * where regions of close colours merge at the later steps, which may well be a
   * little longer than the step where they are apart. */
  CLEAR_OR_FINEST,
  /** The finest split that is stable, whatever the steps after it: clusters, where
   * pieces of objects are not counted (see chooseClusterDistance()) and objects
   * standing close together merge at the later steps, which may well be much longer
   * than the step where they are apart. */
  FINEST,
};

/** \brief The automatic choice of the clustering distance and of the region colour
 * threshold: a step of a count of components over a scale that is stable over a
 * wide range of scales. The count starts at 0 and changes by the \a events (scale,
 * +1 or -1); its steps over [\a floor, \a max_scale) are measured on a logarithmic
 * scale, log(high / low), so that only ratios of scales enter. A step of a count of
 * two or more (a split) is stable when it spans a factor of at least \a gap_ratio,
 * and clear when it is also at least \a gap_ratio times as long, in log, as every
 * other split. Of the splits, \a preference says which is taken. When no split is
 * stable, the longest step of a count of one, if any, and otherwise the longest
 * split. Of equally long steps, the earliest wins.
 * \param[in] events the changes of the count, in any order
 * \param[in] floor the smallest scale (> 0)
 * \param[in] max_scale the end of the scales (> floor)
 * \param[in] gap_ratio the ratio q (> 1)
 * \param[out] step the chosen step
 * \param[in] preference which stable split is taken
 * \return false when no step has a positive count */
bool
chooseStableStep (
    std::vector<std::pair<double, int>> events,
    double floor,
    double max_scale,
    double gap_ratio,
    StableStep& step,
    StableStepPreference preference = StableStepPreference::CLEAR_OR_FINEST);

} // namespace tda
} // namespace pcl
