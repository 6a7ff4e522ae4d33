#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/search/parallel_progress.h>
#include <pcl/tda/search/uniform_grid.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <numeric>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The edges of radius graphs (thesis Sec 3.3, Alg 3.2-3.3): every pair of
 * points at distance <= r (withinRadius()) that passes an extra test, as
 * FilteredEdge (ends in increasing order, value = length), listed in two parallel
 * passes. The count pass gives exact offsets, so a caller can check the size before
 * the fill pass allocates; both passes are deterministic, whatever the number of
 * threads. Vertex ids are positions in the point vector. */

/** \brief The extra test that accepts every pair within the radius. */
struct AcceptAllPairs {
  bool
  operator() (SimplexIndex, SimplexIndex) const
  {
    return true;
  }
};

/** \brief OpenMP threads for a parallel loop: \a threads (at most MAX_THREADS), or
 * OpenMP's default for 0. */
int
resolveThreads (unsigned int threads);

/** \brief Points per thread below which threadsForPoints() takes fewer threads. */
constexpr std::size_t POINTS_PER_THREAD = 8192;

/** \brief The threads of a one-off run over \a points points, e.g. a command-line
 * tool's: \a threads when it is set (> 0); for 0, OpenMP's default, but at most one
 * per POINTS_PER_THREAD points and at least one. Where a process starts its threads
 * for one short run, starting them and their spinning between the parallel passes
 * cost more than the passes gain on fewer points (on 2 busy cores, pcl_tda_barcode
 * on 397 points took 9-14 ms with two threads and 5.5-6 ms with one; on 10,031
 * points, 32-39 ms and 29-32 ms); on one thread OpenMP starts none. (In a process
 * whose threads run already, two threads are faster on 10,031 points.) */
unsigned int
threadsForPoints (unsigned int threads, std::size_t points);

/** \brief What the count pass of the radius edges finds. */
struct RadiusEdgeCounts {
  /** offsets[c]: the first position of the edges found from cell c; offsets.back():
   * the number of edges. */
  std::vector<std::uint64_t> offsets;
  /** The sum over the points of (later neighbours choose 2): an upper bound on the
   * triangles of the clique complex, each counted from its first vertex. */
  std::uint64_t triangle_bound = 0;
};

/** \brief Count pass over a grid of cell size >= \a radius, in parallel, telling
 * \a progress (when set) the points done. */
template <typename Accept>
RadiusEdgeCounts
countRadiusEdges (const UniformGrid& grid,
                  const std::vector<Point3d>& points,
                  double radius,
                  const Accept& accept,
                  unsigned int threads,
                  const ProgressCallback& progress = {})
{
  const auto num_cells = static_cast<std::int64_t> (grid.numCells());
  ParallelProgress tracker (progress, points.size());
  RadiusEdgeCounts counts;
  counts.offsets.assign (grid.numCells() + 1, 0);
  std::uint64_t triangle_bound = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : triangle_bound)           \
    num_threads(resolveThreads (threads))
  for (std::int64_t c = 0; c < num_cells; ++c) {
    std::uint64_t count = 0, of_point = 0;
    std::uint32_t current = grid.pointAt (grid.cellBegin (c));
    grid.forEachCandidatePair (c, [&] (std::uint32_t a, std::uint32_t b) {
      if (a != current) { // the pairs come point by point
        triangle_bound += of_point * (of_point - 1) / 2;
        current = a;
        of_point = 0;
      }
      const std::uint64_t edge =
          withinRadius (points[a], points[b], radius) && accept (a, b);
      count += edge;
      of_point += edge;
    });
    triangle_bound += of_point * (of_point - 1) / 2;
    counts.offsets[c + 1] = count;
    tracker.advance (grid.cellSize (c));
  }
  tracker.rethrow();
  std::partial_sum (
      counts.offsets.begin(), counts.offsets.end(), counts.offsets.begin());
  counts.triangle_bound = triangle_bound;
  return counts;
}

/** \brief Fill pass: the edges counted by countRadiusEdges() (same arguments, and
 * its offsets), in the order of the cells, not sorted. */
template <typename Accept>
std::vector<FilteredEdge>
listRadiusEdges (const UniformGrid& grid,
                 const std::vector<Point3d>& points,
                 double radius,
                 const Accept& accept,
                 const std::vector<std::uint64_t>& offsets,
                 unsigned int threads,
                 const ProgressCallback& progress = {})
{
  auto edges = largeVector<FilteredEdge> (offsets.back());
  const auto num_cells = static_cast<std::int64_t> (grid.numCells());
  ParallelProgress tracker (progress, points.size());
#pragma omp parallel for schedule(dynamic, 64) num_threads(resolveThreads(threads))
  for (std::int64_t c = 0; c < num_cells; ++c) {
    std::uint64_t position = offsets[c];
    grid.forEachCandidatePair (c, [&] (std::uint32_t a, std::uint32_t b) {
      if (withinRadius (points[a], points[b], radius) && accept (a, b))
        edges[position++] = {
            std::min (a, b), std::max (a, b), distance (points[a], points[b])};
    });
    tracker.advance (grid.cellSize (c));
  }
  tracker.rethrow();
  return edges;
}

/** \brief Lists candidate neighbours of a vertex for countEdgesBySearch(): any set of
 * vertices that holds all later vertices (larger ids) within the radius; the exact
 * test is made afterwards. Must be callable from several threads at once. */
using CandidateSearch =
    std::function<void (SimplexIndex vertex, std::vector<SimplexIndex>& candidates)>;

/** \brief Count pass with a search per vertex (e.g. a PCL k-d tree): offsets[v] is
 * the first position of the edges from vertex v to later vertices within \a radius,
 * offsets.back() the number of edges. */
std::vector<std::uint64_t>
countEdgesBySearch (const std::vector<Point3d>& points,
                    double radius,
                    const CandidateSearch& search,
                    unsigned int threads);

/** \brief Fill pass of countEdgesBySearch() (same arguments), in vertex order. */
std::vector<FilteredEdge>
listEdgesBySearch (const std::vector<Point3d>& points,
                   double radius,
                   const CandidateSearch& search,
                   const std::vector<std::uint64_t>& offsets,
                   unsigned int threads);

/** \brief Sorts \a edges into filtration order (edgeFiltrationLess()), in parallel;
 * the result does not depend on the number of threads. */
void
sortEdges (std::vector<FilteredEdge>& edges, unsigned int threads);

} // namespace tda
} // namespace pcl
