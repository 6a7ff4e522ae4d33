#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_diagram.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/common/progress.h>

#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief H1 of a clique complex computed from its edges alone. */
struct CliqueH1Persistence {
  /** The H1 intervals without the zero-length ones, in the order of
   * PersistenceResult::diagram() on the complex with its triangles listed: finite
   * intervals by killing triangle, then essential ones by edge. */
  PersistenceDiagram diagram;
  /** Per edge: the value at which the 1-class a positive edge creates dies (the
   * value of its killing triangle; the edge's own value for a zero-length pair;
   * infinity for an essential class), the pairing edge by edge; a negative edge,
   * which creates no 1-class, gets its own value. */
  std::vector<double> edge_death;
  /** The triangles of the clique complex (counted, never stored). */
  std::uint64_t num_triangles = 0;
};

/** \brief Edges per thread of the apparent-pair pass of computeCliqueH1Persistence()
 * when the threads are OpenMP's default: fewer edges take fewer threads, waking a
 * thread costing more than their work (bunny.pcd at 1,988 edges: 0.07 ms on one
 * thread, 0.14 ms on two; colored_cloud.pcd at 4,996 edges: 0.35 ms and 0.23 ms). */
constexpr std::uint64_t EDGES_PER_THREAD = 2048;

/** \brief Triangles per thread of the reduction of computeCliqueH1Persistence() when
 * the threads are OpenMP's default: on smaller complexes the columns of a batch meet
 * each other's pivots so often that the batches cost more than the threads gain
 * (milk.pcd at 118k triangles: 8.0 ms on two threads, 7.7 ms on one;
 * sac_plane_test.pcd at 116k: 3.9 ms and 4.2 ms). */
constexpr std::uint64_t TRIANGLES_PER_THREAD = 65536;

/** \brief H1 persistence of the clique complex of dimension 2 of \a skeleton's edges
 * (every three pairwise joined vertices span a triangle, at the value of its longest
 * edge: the Vietoris-Rips complex VietorisRipsBuilder builds with max dimension 2),
 * without listing its triangles.
 *
 * The same persistent cohomology as addCohomologyH1Persistence(), hence the same
 * diagram, with triangles named by their two youngest edges (the order of the
 * filtration) and enumerated from the edges' adjacency when a coboundary is needed,
 * as Ripser does. Build \a skeleton with max dimension 1: the triangles, three
 * quarters of a Vietoris-Rips complex, are then never counted into memory, listed
 * or sorted. A first parallel pass over the edges finds the apparent pairs (and
 * counts the triangles); the reduction goes in parallel batches
 * (reduceEdgeCoboundaries()).
 * \param[in] skeleton the edges in filtration order (its triangles are ignored)
 * \param[in] h0 computeH0Persistence() of \a skeleton: which edges are positive
 * \param[in] threads OpenMP threads (0: OpenMP's default, but at most one per
 * EDGES_PER_THREAD edges in the first pass and one per TRIANGLES_PER_THREAD
 * triangles in the reduction); the result does not depend on it
 * \param[in] progress optional callback (edges processed, edges) of the reduction
 */
CliqueH1Persistence
computeCliqueH1Persistence (const FilteredComplex& skeleton,
                            const PersistenceResult& h0,
                            unsigned int threads = 0,
                            const ProgressCallback& progress = {});

} // namespace tda
} // namespace pcl
