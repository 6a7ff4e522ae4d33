#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/search/neighbor_graph.h>

#include <array>
#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Every vertex's neighbours, each with the filtration id of the edge that
 * joins them, in filtration order of the edges: the neighbours of vertex v are
 * entries offsets[v] to offsets[v + 1] of \a entries. */
struct EdgeAdjacency {
  struct Entry {
    SimplexIndex neighbor;
    SimplexIndex edge;
  };
  std::vector<std::uint64_t> offsets;
  std::vector<Entry> entries;
  /** Position of every edge in the lists of its source and of its target: the
   * entries before it are the neighbours through older edges. */
  std::vector<std::array<std::uint64_t, 2>> positions;
};

/** \brief Edge list phase (thesis Alg 3.3): the edges of \a graph in filtration
 * order, i.e. sorted by (length, source, target). */
std::vector<FilteredEdge>
sortedEdges (const NeighborGraph& graph);

/** \brief The adjacency lists of the graph whose edges are \a edges. */
EdgeAdjacency
buildEdgeAdjacency (std::size_t num_vertices, const std::vector<FilteredEdge>& edges);

/** \brief Count pass of the triangle phase (thesis Alg 3.4): for every edge, the
 * number of triangles of the clique complex in which it is the youngest edge. */
std::vector<std::uint32_t>
countTriangles (const std::vector<FilteredEdge>& edges, const EdgeAdjacency& adjacency);

/** \brief Prefix sum and fill pass of the triangle phase (thesis Alg 3.5): all
 * triangles in filtration order, in parallel; edge e owns \a counts[e] of them. */
std::vector<FilteredTriangle>
fillTriangles (const std::vector<FilteredEdge>& edges,
               const EdgeAdjacency& adjacency,
               const std::vector<std::uint32_t>& counts);

} // namespace tda
} // namespace pcl
