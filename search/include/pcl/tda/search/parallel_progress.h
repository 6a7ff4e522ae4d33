#pragma once

#include <pcl/tda/common/progress.h>

#include <omp.h>

#include <atomic>
#include <cstddef>
#include <exception>

namespace pcl {
namespace tda {

/** \brief Reports the progress of a parallel loop to a ProgressCallback: any thread
 * may advance it, only OpenMP's master thread calls the callback (so a console
 * progress bar needs no lock), at most once per thousandth of the work. An exception
 * the callback throws (a caller cancelling the work) cannot leave the parallel loop:
 * it is kept, the callback is not called again, and rethrow() throws it once the
 * loop is over. */
class ParallelProgress {
public:
  /** \param[in] progress the callback (none: advancing costs one test)
   * \param[in] total the units of work of the loop */
  ParallelProgress (const ProgressCallback& progress, std::size_t total)
  : progress_ (progress), total_ (total)
  {}

  /** \brief Adds \a units done; call it every few thousand units, not every one. */
  void
  advance (std::size_t units)
  {
    if (!progress_)
      return;
    const std::size_t done = done_.fetch_add (units, std::memory_order_relaxed) + units;
    if (omp_get_thread_num() != 0 || total_ == 0)
      return;
    const std::size_t permille = std::min<std::size_t> (done, total_) * 1000 / total_;
    if (permille > reported_permille_ && !failure_) {
      reported_permille_ = permille;
      try {
        progress_ (std::min (done, total_), total_);
      }
      catch (...) {
        failure_ = std::current_exception();
      }
    }
  }

  /** \brief After the loop: throws what the callback threw in it, if anything. */
  void
  rethrow () const
  {
    if (failure_)
      std::rethrow_exception (failure_);
  }

private:
  const ProgressCallback& progress_;
  std::size_t total_;
  std::atomic<std::size_t> done_{0};
  // Read and written by the master thread only.
  std::size_t reported_permille_ = 0;
  std::exception_ptr failure_;
};

} // namespace tda
} // namespace pcl
