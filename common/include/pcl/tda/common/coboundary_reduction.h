#pragma once

#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/common/progress.h>
#include <pcl/tda/common/reduction_column.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <ctime>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace pcl {
namespace tda {

/** \brief The OpenMP thread number of the caller (0 without OpenMP). */
inline int
currentThread ()
{
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

/** \brief The processor time the calling thread has used, in seconds. */
inline double
threadProcessorSeconds ()
{
  timespec now;
  clock_gettime (CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double> (now.tv_sec) + 1e-9 * static_cast<double> (now.tv_nsec);
}

/** \brief The columns a coboundary reduction keeps for later additions, the reduced
 * columns of the edges it pairs, one after another in a few large blocks. A column is
 * stored once and never changes, so blocks and a pointer per edge replace a map of
 * vectors (tens of thousands of allocations on a real scan); a block is never moved
 * (a full one is followed by a new one), so that storing costs no copy of the columns
 * stored before. One thread stores, between the parallel phases that read. \a Key
 * names a triangle. */
template <typename Key>
class StoredColumns {
public:
  /** \param[in] num_edges the edges, ids 0 to num_edges - 1 */
  explicit StoredColumns (std::size_t num_edges)
  : column_ (largeVector<const Key*> (num_edges, nullptr))
  {}

  bool
  has (SimplexIndex edge) const
  {
    return column_[edge] != nullptr;
  }

  /** \brief Stores \a column (its keys) as the column of \a edge. */
  void
  store (SimplexIndex edge, const std::vector<Key>& column)
  {
    const std::size_t size = column.size() + 1; // the keys after their number
    if (blocks_.empty() || blocks_.back().capacity() - blocks_.back().size() < size) {
      blocks_.emplace_back();
      blocks_.back().reserve (std::max (BLOCK_KEYS, size));
    }
    std::vector<Key>& block = blocks_.back();
    column_[edge] = block.data() + block.size();
    block.push_back (static_cast<Key> (column.size()));
    block.insert (block.end(), column.begin(), column.end());
  }

  /** The stored column of \a edge as [first, last). */
  std::pair<const Key*, const Key*>
  column (SimplexIndex edge) const
  {
    const Key* stored = column_[edge];
    return {stored + 1, stored + 1 + static_cast<std::size_t> (*stored)};
  }

private:
  /** Keys per block: 8 MiB, whole huge pages where malloc takes them. Not 2 MiB:
   * freeing the first block, malloc raises the size it asks the system for memory
   * by (and, twice as much, the free memory at the top of its heap that it gives
   * back) to the block's; at 2 MiB, a pipeline that runs again and again on a scan
   * like milk.pcd gave back and faulted in its 3 MB again on every run, and took
   * twice as long. Pages never written are never taken. */
  static constexpr std::size_t BLOCK_KEYS = (std::size_t{8} << 20) / sizeof (Key);
  /** Per edge: its column's number of keys, followed by the keys; or nullptr. */
  std::vector<const Key*> column_;
  std::vector<std::vector<Key>> blocks_;
};

/** \brief Columns per batch of reduceEdgeCoboundaries(). */
constexpr std::size_t BATCH_COLUMNS = 256;

/** \brief The share of a batch's wall time below which the threads of
 * reduceEdgeCoboundaries() ran too little (one waited for another that the system
 * did not run), and how many such batches, if more than one in ten, make it go on
 * one thread. Measured on two cores: quietly 0-1.3 % of the batches of real scans
 * fall below, with a busy process beside 20-28 %. */
constexpr double BUSY_EFFICIENCY = 0.5;
constexpr std::size_t MIN_SLOW_BATCHES = 3;

/** \brief Persistent cohomology of the edges (H1): the reduction loop of the
 * cohomology engines, whichever way they name and enumerate triangles.
 *
 * The coboundary of every positive edge (the triangles containing it, in filtration
 * order) is reduced over Z2, youngest edge first, with the oldest triangle as
 * pivot; negative edges need no column (clearing). A positive edge whose oldest
 * coboundary triangle has it as youngest edge forms an apparent pair with that
 * triangle and needs no reduction: in a Vietoris-Rips complex most pairs are such.
 * Of the others, an edge whose oldest coboundary triangle no column has as pivot yet
 * forms an emergent pair with it: its column is reduced as it is, so it is neither
 * sorted nor stored (as Ripser does). Cohomology pairs the same simplices as
 * homology. The column under reduction is a ReductionColumn: a heap once long.
 *
 * The columns to reduce go in batches of BATCH_COLUMNS, in order. Within a batch,
 * first in parallel, every column is reduced by the columns paired before the
 * batch (the apparent pairs, all known from the start, and the earlier batches),
 * as far as they reach; then, one after the other, each is reduced on by the
 * columns of the batch paired before it, and paired. Every addition is of a column
 * of a younger edge, as in the serial order, and a reduced matrix has the same
 * pivots whichever such additions made it (Edelsbrunner and Harer, Sec VII.1): the
 * pairs, hence the diagram, are those of the serial reduction, whatever the number
 * of threads. On one thread a batch is one column: the serial loop. Where another
 * process holds a core, a batch waits for the thread the system does not run: from
 * MIN_SLOW_BATCHES such batches (threads running less than BUSY_EFFICIENCY of the
 * time), if more than one in ten, the rest goes on one thread.
 *
 * \a Coboundaries names a triangle by a \c Key ordered as the filtration and
 * provides:
 * - `bool claimApparentPair (SimplexIndex edge)`: true when the positive \a edge
 *   forms an apparent pair, which it then records;
 * - `CommonNeighborSearch commonNeighborSearch () const`: a search for one thread;
 * - `void coboundary (SimplexIndex edge, CommonNeighborSearch& search,
 *   std::vector<Key>& column) const`: the coboundary of \a edge, in any order,
 *   found with \a search; called from several threads at once;
 * - `SimplexIndex owner (Key triangle) const`: the edge paired with \a triangle so
 *   far (apparent pairs included), or INVALID_SIMPLEX; called from several threads
 *   at once, never while setOwner() runs;
 * - `void setOwner (Key triangle, SimplexIndex edge)`: pairs them.
 * \param[in] edge_positive per edge, 1 when it is positive (from H0)
 * \param[in,out] coboundaries the triangles and the pairing
 * \param[in] threads OpenMP threads of the parallel phases (at least 1; without
 * OpenMP, one)
 * \param[in] progress optional callback (edges processed, edges)
 */
template <typename Coboundaries>
void
reduceEdgeCoboundaries (const std::vector<std::uint8_t>& edge_positive,
                        Coboundaries& coboundaries,
                        int threads,
                        const ProgressCallback& progress)
{
  using Key = typename Coboundaries::Key;
  const std::size_t num_edges = edge_positive.size();
  // The apparent pairs first: then every pair a reduction may meet before the
  // batch is known (an apparent pair's edge is younger than every other edge of its
  // triangle, so it comes before any column that meets that triangle).
  std::vector<SimplexIndex> columns; // the other positive edges, youngest first
  for (std::size_t k = 0; k < num_edges; ++k) {
    const auto edge = static_cast<SimplexIndex> (num_edges - 1 - k);
    if (edge_positive[edge] && !coboundaries.claimApparentPair (edge))
      columns.push_back (edge);
  }

  // A cache line of its own: the vectors of one thread change at every key.
  struct alignas (64) Thread {
    CommonNeighborSearch search;
    ReductionColumn<Key> column;
    std::vector<Key> keys, scratch;
  };
  std::vector<Thread> workers;
  for (int t = 0; t < threads; ++t)
    workers.push_back ({coboundaries.commonNeighborSearch(), {}, {}, {}});
  // The reduced columns of the edges whose columns were added to. An apparent or
  // emergent pair's column is its coboundary, found again each time it is added: on
  // real scans such a column is added little more than once (at most 1.14 times on
  // average on a 100k-point scan at degree 20, 1.25 on kinect_frame.pcd whole), and
  // storing it cost more in memory written than finding it again.
  StoredColumns<Key> stored (num_edges);
  // Adds to \a worker's column the columns of the owners of its pivots while they
  // have one.
  const auto reduce = [&] (Thread& worker) {
    SimplexIndex owner;
    while (worker.column.findPivot() &&
           (owner = coboundaries.owner (worker.column.pivot())) != INVALID_SIMPLEX) {
      if (stored.has (owner)) {
        const auto [first, last] = stored.column (owner);
        worker.column.add (first, last);
        continue;
      }
      coboundaries.coboundary (owner, worker.search, worker.scratch);
      std::sort (worker.scratch.begin(), worker.scratch.end());
      worker.column.add (worker.scratch.data(),
                         worker.scratch.data() + worker.scratch.size());
    }
  };

  // The coboundary of the column at \a position, reduced by the pairs made so far
  // as far as they reach, into \a keys (swapped in: the threads would write the
  // neighbouring vectors of a batch at every key otherwise). Returns whether it is
  // sorted: not when its oldest triangle had no owner (maybe an emergent pair), nor
  // when it has no triangle (an essential class).
  const auto reduce_ahead = [&] (std::size_t position,
                                 int thread,
                                 std::vector<Key>& keys) {
    Thread& worker = workers[static_cast<std::size_t> (thread)];
    coboundaries.coboundary (columns[position], worker.search, worker.keys);
    // The oldest triangle first, so that the pass in order finds it again.
    if (!worker.keys.empty())
      std::iter_swap (worker.keys.begin(),
                      std::min_element (worker.keys.begin(), worker.keys.end()));
    const bool unreduced = worker.keys.empty() ||
                           coboundaries.owner (worker.keys.front()) == INVALID_SIMPLEX;
    if (!unreduced) {
      std::sort (worker.keys.begin(), worker.keys.end());
      worker.column.assign (worker.keys);
      reduce (worker);
      worker.column.release (worker.keys);
    }
    keys.swap (worker.keys);
    return !unreduced;
  };

  std::size_t batches = 0, slow_batches = 0;
  // Per column of a batch: its keys, sorted or not.
  std::vector<std::vector<Key>> batch (BATCH_COLUMNS);
  std::vector<std::uint8_t> sorted (BATCH_COLUMNS);
  for (std::size_t begin = 0, size; begin < columns.size(); begin += size) {
    reportProgress (progress, num_edges - 1 - columns[begin], num_edges);
    // On one thread, batches of one column: the serial loop.
    size = std::min (threads > 1 ? BATCH_COLUMNS : 1, columns.size() - begin);
    if (threads == 1)
      sorted[0] = reduce_ahead (begin, 0, batch[0]);
    else {
      // In parallel: the columns reduced by the pairs made before the batch.
      const auto started = std::chrono::steady_clock::now();
      double working = 0.0; // the threads' processor time
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) reduction(+ : working)
#endif
      {
        const double processor_time = threadProcessorSeconds();
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 4) nowait
#endif
        for (std::int64_t i = 0; i < static_cast<std::int64_t> (size); ++i)
          sorted[i] = reduce_ahead (begin + i, currentThread(), batch[i]);
        working += threadProcessorSeconds() - processor_time;
      }
      // A batch whose threads ran less than half the time waited for a thread the
      // system did not run: another process holds a core.
      const double wall =
          std::chrono::duration<double> (std::chrono::steady_clock::now() - started)
              .count();
      ++batches;
      slow_batches += working < BUSY_EFFICIENCY * threads * wall;
      if (slow_batches >= MIN_SLOW_BATCHES && slow_batches * 10 > batches)
        threads = 1;
    }

    // In order: reduced on by the columns of the batch paired before it, and paired.
    Thread& worker = workers.front();
    for (std::size_t i = 0; i < size; ++i) {
      std::vector<Key>& keys = batch[i];
      const SimplexIndex edge = columns[begin + i];
      if (keys.empty())
        continue; // an essential class
      if (!sorted[i]) {
        if (coboundaries.owner (keys.front()) == INVALID_SIMPLEX) {
          coboundaries.setOwner (keys.front(), edge); // an emergent pair
          continue;
        }
        std::sort (keys.begin(), keys.end());
      }
      worker.column.assign (keys);
      reduce (worker);
      if (worker.column.findPivot()) {
        coboundaries.setOwner (worker.column.pivot(), edge);
        stored.store (edge, worker.column.sum());
      }
    }
  }
  reportProgress (progress, num_edges - 1, num_edges);
}

} // namespace tda
} // namespace pcl
