#pragma once

#include <cstddef>
#include <functional>

namespace pcl {
namespace tda {

/** \brief Called now and then by long computations with the units of work done so
 * far and the total (never 0), e.g. to drive a ProgressBar. It may throw to cancel
 * the computation: the exception reaches the caller (from a parallel pass, when the
 * pass is over: ParallelProgress). */
using ProgressCallback = std::function<void (std::size_t done, std::size_t total)>;

/** \brief Tells \a progress (when set) that unit \a index of \a total is done, every
 * 4096 units and at the last one, so that a tight loop can call it every time; with
 * no units (\a total 0) there is nothing to report. */
inline void
reportProgress (const ProgressCallback& progress, std::size_t index, std::size_t total)
{
  if (progress && total > 0 && (index % 4096 == 0 || index + 1 == total))
    progress (index + 1, total);
}

} // namespace tda
} // namespace pcl
