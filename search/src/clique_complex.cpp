#include <pcl/tda/search/clique_complex.h>

#include <parallel/algorithm>

#include <algorithm>
#include <tuple>

namespace pcl {
namespace tda {

std::vector<FilteredEdge>
sortedEdges (const NeighborGraph& graph)
{
  std::vector<FilteredEdge> edges (graph.numEdges());
  const auto n = static_cast<std::int64_t> (graph.numVertices());
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t u = 0; u < n; ++u)
    for (std::uint64_t k = graph.offsets[u]; k < graph.offsets[u + 1]; ++k)
      edges[k] = {static_cast<SimplexIndex> (u), graph.neighbors[k], graph.lengths[k]};
  // A strict total order (no two edges compare equal): the parallel sort's result
  // does not depend on the number of threads.
  __gnu_parallel::sort (
      edges.begin(), edges.end(), [] (const FilteredEdge& a, const FilteredEdge& b) {
        return std::tie (a.value, a.source, a.target) <
               std::tie (b.value, b.source, b.target);
      });
  return edges;
}

EdgeAdjacency
buildEdgeAdjacency (std::size_t num_vertices, const std::vector<FilteredEdge>& edges)
{
  EdgeAdjacency adjacency;
  adjacency.offsets.assign (num_vertices + 1, 0);
  for (const auto& edge : edges) {
    ++adjacency.offsets[edge.source + 1];
    ++adjacency.offsets[edge.target + 1];
  }
  for (std::size_t v = 0; v < num_vertices; ++v)
    adjacency.offsets[v + 1] += adjacency.offsets[v];
  adjacency.entries.resize (adjacency.offsets.back());
  adjacency.positions.resize (edges.size());
  std::vector<std::uint64_t> next (adjacency.offsets.begin(),
                                   adjacency.offsets.end() - 1);
  for (SimplexIndex e = 0; e < edges.size(); ++e) {
    adjacency.positions[e] = {next[edges[e].source], next[edges[e].target]};
    adjacency.entries[next[edges[e].source]++] = {edges[e].target, e};
    adjacency.entries[next[edges[e].target]++] = {edges[e].source, e};
  }
  return adjacency;
}

namespace {

/** Finds the triangles of a clique complex by their youngest edge. Per thread: it
 * keeps a mark per vertex, so each search costs the older neighbourhoods of the
 * edge's two ends, not their whole adjacency lists. */
class TriangleFinder {
public:
  TriangleFinder (const std::vector<FilteredEdge>& edges,
                  const EdgeAdjacency& adjacency,
                  std::size_t num_vertices)
  : edges_ (edges), adjacency_ (adjacency), marks_ (num_vertices, {INVALID_SIMPLEX, 0})
  {}

  /** Calls \a visit(uw, vw) for every vertex w adjacent to both ends u, v of edge
   * \a e through edges uw, vw older than \a e: the triangles whose youngest edge
   * is e. */
  template <typename Visit>
  void
  forEachTriangleOf (SimplexIndex e, Visit visit)
  {
    for (const auto& entry : olderNeighbors (edges_[e].source, e, 0))
      marks_[entry.neighbor] = {e, entry.edge};
    for (const auto& entry : olderNeighbors (edges_[e].target, e, 1)) {
      const Mark& mark = marks_[entry.neighbor];
      if (mark.edge_searched == e)
        visit (mark.edge_to_source, entry.edge);
    }
  }

private:
  struct Mark {
    SimplexIndex edge_searched;  // the edge whose search marked the vertex last
    SimplexIndex edge_to_source; // the edge from the vertex to its source
  };

  struct Range {
    const EdgeAdjacency::Entry* first;
    const EdgeAdjacency::Entry* last;
    const EdgeAdjacency::Entry*
    begin () const
    {
      return first;
    }
    const EdgeAdjacency::Entry*
    end () const
    {
      return last;
    }
  };

  /** The neighbours of \a vertex, end \a side (0: source, 1: target) of edge \a e,
   * through edges older than \a e: a prefix of its adjacency list, which is sorted
   * by edge. */
  Range
  olderNeighbors (SimplexIndex vertex, SimplexIndex e, int side) const
  {
    const EdgeAdjacency::Entry* entries = adjacency_.entries.data();
    return {entries + adjacency_.offsets[vertex],
            entries + adjacency_.positions[e][side]};
  }

  const std::vector<FilteredEdge>& edges_;
  const EdgeAdjacency& adjacency_;
  std::vector<Mark> marks_;
};

} // namespace

std::vector<std::uint32_t>
countTriangles (const std::vector<FilteredEdge>& edges, const EdgeAdjacency& adjacency)
{
  std::vector<std::uint32_t> counts (edges.size(), 0);
  const auto m = static_cast<std::int64_t> (edges.size());
#pragma omp parallel
  {
    TriangleFinder finder (edges, adjacency, adjacency.offsets.size() - 1);
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t e = 0; e < m; ++e)
      finder.forEachTriangleOf (static_cast<SimplexIndex> (e),
                                [&] (SimplexIndex, SimplexIndex) { ++counts[e]; });
  }
  return counts;
}

std::vector<FilteredTriangle>
fillTriangles (const std::vector<FilteredEdge>& edges,
               const EdgeAdjacency& adjacency,
               const std::vector<std::uint32_t>& counts)
{
  std::vector<std::uint64_t> offsets (edges.size() + 1, 0);
  for (std::size_t e = 0; e < edges.size(); ++e)
    offsets[e + 1] = offsets[e] + counts[e];
  std::vector<FilteredTriangle> triangles (offsets.back());

  const auto m = static_cast<std::int64_t> (edges.size());
#pragma omp parallel
  {
    TriangleFinder finder (edges, adjacency, adjacency.offsets.size() - 1);
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t e = 0; e < m; ++e) {
      const auto youngest = static_cast<SimplexIndex> (e);
      auto out = triangles.begin() + offsets[e];
      finder.forEachTriangleOf (youngest, [&] (SimplexIndex uw, SimplexIndex vw) {
        *out++ = {{youngest, std::max (uw, vw), std::min (uw, vw)}, edges[e].value};
      });
      std::sort (triangles.begin() + offsets[e],
                 out,
                 [] (const FilteredTriangle& a, const FilteredTriangle& b) {
                   return a.edges[1] < b.edges[1];
                 });
    }
  }
  return triangles;
}

} // namespace tda
} // namespace pcl
