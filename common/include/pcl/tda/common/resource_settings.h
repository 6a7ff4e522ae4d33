#pragma once

#include <pcl/tda/common/system_memory.h>

#include <cstddef>

namespace pcl {
namespace tda {

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

  /** \brief Sets the number of OpenMP threads (0: OpenMP's default). */
  void
  setNumberOfThreads (unsigned int threads)
  {
    threads_ = threads;
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
