#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/common/spanning_forest.h>
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

/** \brief OpenMP threads for a parallel loop: \a threads, or OpenMP's default for 0.
 */
int
resolveThreads (unsigned int threads);

/** \brief Count pass over a grid of cell size >= \a radius: offsets[c] is the first
 * position of the edges found from cell c, offsets.back() the number of edges. */
template <typename Accept>
std::vector<std::uint64_t>
countRadiusEdges (const UniformGrid& grid,
                  const std::vector<Point3d>& points,
                  double radius,
                  const Accept& accept,
                  unsigned int threads)
{
  const auto num_cells = static_cast<std::int64_t> (grid.numCells());
  std::vector<std::uint64_t> offsets (grid.numCells() + 1, 0);
#pragma omp parallel for schedule(dynamic, 64) num_threads(resolveThreads(threads))
  for (std::int64_t c = 0; c < num_cells; ++c) {
    std::uint64_t count = 0;
    grid.forEachCandidatePair (c, [&] (std::uint32_t a, std::uint32_t b) {
      count += withinRadius (points[a], points[b], radius) && accept (a, b);
    });
    offsets[c + 1] = count;
  }
  std::partial_sum (offsets.begin(), offsets.end(), offsets.begin());
  return offsets;
}

/** \brief Fill pass: the edges counted by countRadiusEdges() (same arguments), in
 * the order of the cells, not sorted. */
template <typename Accept>
std::vector<FilteredEdge>
listRadiusEdges (const UniformGrid& grid,
                 const std::vector<Point3d>& points,
                 double radius,
                 const Accept& accept,
                 const std::vector<std::uint64_t>& offsets,
                 unsigned int threads)
{
  std::vector<FilteredEdge> edges (offsets.back());
  const auto num_cells = static_cast<std::int64_t> (grid.numCells());
#pragma omp parallel for schedule(dynamic, 64) num_threads(resolveThreads(threads))
  for (std::int64_t c = 0; c < num_cells; ++c) {
    std::uint64_t position = offsets[c];
    grid.forEachCandidatePair (c, [&] (std::uint32_t a, std::uint32_t b) {
      if (withinRadius (points[a], points[b], radius) && accept (a, b))
        edges[position++] = {
            std::min (a, b), std::max (a, b), distance (points[a], points[b])};
    });
  }
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

/** \brief The minimum spanning forest of the radius graph of \a points: the only
 * edges that H0 of the graph's filtration needs, since the negative edges of the
 * elder rule form that forest (thesis Sec 4.1.4). The edges are the pairs within
 * \a radius that pass \a accept (e.g. the colour and normal tests of region
 * growing), found on a UniformGrid of cell size \a radius; the forest is taken by
 * minimumSpanningForest().
 * \param[in] points the points, vertex v at points[v]
 * \param[in] radius the largest edge length (> 0)
 * \param[in] accept the extra test of a pair (a, b) of vertex ids within the radius
 * \param[in] threads OpenMP threads (0: OpenMP's default)
 * \param[out] num_graph_edges number of edges of the radius graph
 * \return the forest's edges in filtration order
 * \throws pcl::BadArgumentException as UniformGrid */
template <typename Accept>
std::vector<FilteredEdge>
radiusGraphSpanningForest (const std::vector<Point3d>& points,
                           double radius,
                           const Accept& accept,
                           unsigned int threads,
                           std::size_t& num_graph_edges)
{
  const UniformGrid grid (points, radius, threads);
  const std::vector<std::uint64_t> offsets =
      countRadiusEdges (grid, points, radius, accept, threads);
  num_graph_edges = offsets.back();
  std::vector<FilteredEdge> edges =
      listRadiusEdges (grid, points, radius, accept, offsets, threads);
  return minimumSpanningForest (points.size(), edges);
}

} // namespace tda
} // namespace pcl
