#pragma once

#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/search/parallel_progress.h>
#include <pcl/tda/search/radius_edges.h>

#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The triangles of a clique complex grouped by their youngest edge (the
 * triangle phase of thesis Alg 3.4-3.5, and the apparent pairs of the H1 engine),
 * found vertex by vertex rather than edge by edge.
 *
 * For each vertex u the neighbours of u are marked once; then for each edge e = uv
 * with u < v, the neighbours w of v through edges older than e (a prefix of v's
 * list) whose mark says uw is older than e close the triangles uvw whose youngest
 * edge is e. Against marking and scanning both ends of every edge in filtration order
 * this reads half the lists, and the lists and marks it reads stay in the caches
 * while one vertex's edges are searched.
 *
 * Calls \a visit_edge(e, triangles) once for every edge e of \a adjacency, in
 * parallel (the edges of one vertex on one thread, one after the other), where
 * \a triangles(visit) calls visit(uw, vw) for each triangle uvw whose youngest
 * edge is e, with the ids of its two other edges, in no particular order.
 * \param[in] adjacency the adjacency lists of the edges, sorted by edge id
 * \param[in] threads OpenMP threads (0: OpenMP's default)
 * \param[in] progress told the vertices done, when set
 * \return the number of triangles visited: all of them when every visit_edge()
 * enumerates its edge's triangles
 */
template <typename VisitEdge>
std::uint64_t
forEachEdgeWithYoungestTriangles (const EdgeAdjacency& adjacency,
                                  unsigned int threads,
                                  const ProgressCallback& progress,
                                  VisitEdge visit_edge)
{
  // Per vertex w: the last vertex u whose neighbours were marked, if w is one of
  // them, and the edge uw.
  struct Mark {
    SimplexIndex vertex;
    SimplexIndex edge;
  };
  constexpr std::int64_t PROGRESS_STEP = 1024;
  const auto n = static_cast<std::int64_t> (adjacency.numVertices());
  ParallelProgress tracker (progress, adjacency.numVertices());
  std::uint64_t num_triangles = 0;
#pragma omp parallel num_threads(resolveThreads(threads)) reduction(+ : num_triangles)
  {
    std::vector<Mark> marks (adjacency.numVertices(), {INVALID_SIMPLEX, 0});
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t i = 0; i < n; ++i) {
      const auto u = static_cast<SimplexIndex> (i);
      for (const auto& entry : adjacency.neighbors (u))
        marks[entry.neighbor] = {u, entry.edge};
      for (const auto& uv : adjacency.neighbors (u)) {
        if (uv.neighbor < u)
          continue;
        const SimplexIndex e = uv.edge;
        visit_edge (e, [&] (auto visit) {
          for (const auto& vw : adjacency.neighbors (uv.neighbor)) {
            if (vw.edge >= e)
              break;
            const Mark& mark = marks[vw.neighbor];
            if (mark.vertex == u && mark.edge < e) {
              ++num_triangles;
              visit (mark.edge, vw.edge);
            }
          }
        });
      }
      if (i % PROGRESS_STEP == 0)
        tracker.advance (PROGRESS_STEP);
    }
  }
  tracker.rethrow();
  return num_triangles;
}

} // namespace tda
} // namespace pcl
