#pragma once

#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/progress.h>

#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Count pass of the triangle phase (thesis Alg 3.4): for every edge of
 * \a edges (in filtration order, with their \a adjacency), the number of triangles
 * of the clique complex in which it is the youngest edge; offsets[e] is the first
 * position of edge e's triangles, offsets.back() the number of triangles.
 * \param[in] threads OpenMP threads (0: OpenMP's default)
 * \param[in] progress told the edges done, when set */
std::vector<std::uint64_t>
countTriangles (const std::vector<FilteredEdge>& edges,
                const EdgeAdjacency& adjacency,
                unsigned int threads,
                const ProgressCallback& progress = {});

/** \brief Fill pass of the triangle phase (thesis Alg 3.5): all triangles of the
 * clique complex in filtration order, in parallel, at the \a offsets of
 * countTriangles(). */
std::vector<FilteredTriangle>
fillTriangles (const std::vector<FilteredEdge>& edges,
               const EdgeAdjacency& adjacency,
               const std::vector<std::uint64_t>& offsets,
               unsigned int threads,
               const ProgressCallback& progress = {});

} // namespace tda
} // namespace pcl
