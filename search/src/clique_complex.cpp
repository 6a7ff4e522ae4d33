#include <pcl/tda/search/clique_complex.h>

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
  std::sort (
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
  std::vector<std::uint64_t> next (adjacency.offsets.begin(),
                                   adjacency.offsets.end() - 1);
  for (SimplexIndex e = 0; e < edges.size(); ++e) {
    adjacency.entries[next[edges[e].source]++] = {edges[e].target, e};
    adjacency.entries[next[edges[e].target]++] = {edges[e].source, e};
  }
  const auto n = static_cast<std::int64_t> (num_vertices);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t v = 0; v < n; ++v)
    std::sort (adjacency.entries.begin() + adjacency.offsets[v],
               adjacency.entries.begin() + adjacency.offsets[v + 1],
               [] (const EdgeAdjacency::Entry& a, const EdgeAdjacency::Entry& b) {
                 return a.neighbor < b.neighbor;
               });
  return adjacency;
}

namespace {

/** Calls \a visit(uw, vw) for every vertex w adjacent to both ends of edge \a e
 * through edges uw, vw older than \a e: the triangles whose youngest edge is e. */
template <typename Visit>
void
forEachTriangleOf (SimplexIndex e,
                   const std::vector<FilteredEdge>& edges,
                   const EdgeAdjacency& adjacency,
                   Visit visit)
{
  const auto& entries = adjacency.entries;
  std::uint64_t a = adjacency.offsets[edges[e].source];
  const std::uint64_t a_end = adjacency.offsets[edges[e].source + 1];
  std::uint64_t b = adjacency.offsets[edges[e].target];
  const std::uint64_t b_end = adjacency.offsets[edges[e].target + 1];
  while (a < a_end && b < b_end) {
    if (entries[a].neighbor < entries[b].neighbor)
      ++a;
    else if (entries[b].neighbor < entries[a].neighbor)
      ++b;
    else {
      if (entries[a].edge < e && entries[b].edge < e)
        visit (entries[a].edge, entries[b].edge);
      ++a;
      ++b;
    }
  }
}

} // namespace

std::vector<std::uint32_t>
countTriangles (const std::vector<FilteredEdge>& edges, const EdgeAdjacency& adjacency)
{
  std::vector<std::uint32_t> counts (edges.size(), 0);
  const auto m = static_cast<std::int64_t> (edges.size());
#pragma omp parallel for schedule(dynamic, 1024)
  for (std::int64_t e = 0; e < m; ++e)
    forEachTriangleOf (static_cast<SimplexIndex> (e),
                       edges,
                       adjacency,
                       [&] (SimplexIndex, SimplexIndex) { ++counts[e]; });
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
#pragma omp parallel for schedule(dynamic, 1024)
  for (std::int64_t e = 0; e < m; ++e) {
    const auto youngest = static_cast<SimplexIndex> (e);
    auto out = triangles.begin() + offsets[e];
    forEachTriangleOf (
        youngest, edges, adjacency, [&] (SimplexIndex uw, SimplexIndex vw) {
          *out++ = {{youngest, std::max (uw, vw), std::min (uw, vw)}, edges[e].value};
        });
    std::sort (triangles.begin() + offsets[e],
               out,
               [] (const FilteredTriangle& a, const FilteredTriangle& b) {
                 return a.edges[1] < b.edges[1];
               });
  }
  return triangles;
}

} // namespace tda
} // namespace pcl
