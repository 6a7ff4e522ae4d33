#pragma once

#include <pcl/console/print.h>
#include <pcl/tda/common/system_memory.h>

#include <algorithm>
#include <cstddef>

namespace pcl {
namespace tda {

/** \brief The most OpenMP threads a computation of this library starts: more gain
 * nothing, and a count near 2^31 (-1 given as an unsigned count) had OpenMP ask for
 * terabytes and end the process. */
constexpr unsigned int MAX_THREADS = 256;

/** \brief What a computation of this library may use, with PCL-style setters: the
 * memory of its largest structure and the number of threads. One set for every
 * class that builds a complex or a neighbour graph (the Vietoris-Rips builders,
 * PersistentEuclideanClusterExtraction, PersistentRegionGrowingRGB,
 * HoleBoundaryEstimation, STPPEstimation, TopologicalCovarianceEstimation). The
 * results never depend on either. */
class ResourceSettings {
public:
  /** \brief Sets the memory the largest structure of a computation (its complex or
   * neighbour graph) may take, in bytes: a larger one is refused, with a message
   * giving its size, before it is stored; far over the limit, in bounded time, from
   * a sample of the points. Default: half of the memory this process may use:
   * the physical memory, or less under `ulimit -v` or a container's limit
   * (defaultMemoryLimit(); no limit where none can be read). */
  void
  setMemoryLimit (std::size_t bytes)
  {
    memory_limit_ = bytes;
  }

  std::size_t
  getMemoryLimit () const
  {
    return memory_limit_;
  }

  /** \brief Sets the number of OpenMP threads (0: OpenMP's default), at most
   * MAX_THREADS: a larger count is taken as MAX_THREADS, with a PCL_WARN. */
  void
  setNumberOfThreads (unsigned int threads)
  {
    if (threads > MAX_THREADS)
      PCL_WARN ("[pcl::tda::setNumberOfThreads] %u threads asked for: %u are used "
                "(at most %u; 0 chooses OpenMP's default).\n",
                threads,
                MAX_THREADS,
                MAX_THREADS);
    threads_ = std::min (threads, MAX_THREADS);
  }

  unsigned int
  getNumberOfThreads () const
  {
    return threads_;
  }

protected:
  std::size_t memory_limit_ = defaultMemoryLimit();
  unsigned int threads_ = 0;
};

} // namespace tda
} // namespace pcl
