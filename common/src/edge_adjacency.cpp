#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/large_vector.h>

namespace pcl {
namespace tda {

EdgeAdjacency
buildEdgeAdjacency (std::size_t num_vertices,
                    const std::vector<FilteredEdge>& edges,
                    const EdgeFilter& keep)
{
  EdgeAdjacency adjacency;
  adjacency.offsets = largeVector<std::uint64_t> (num_vertices + 1, 0);
  for (SimplexIndex e = 0; e < edges.size(); ++e)
    if (!keep || keep (e)) {
      ++adjacency.offsets[edges[e].source + 1];
      ++adjacency.offsets[edges[e].target + 1];
    }
  for (std::size_t v = 0; v < num_vertices; ++v)
    adjacency.offsets[v + 1] += adjacency.offsets[v];
  adjacency.entries = largeVector<EdgeAdjacency::Entry> (adjacency.offsets.back());
  std::vector<std::uint64_t> next (adjacency.offsets.begin(),
                                   adjacency.offsets.end() - 1);
  for (SimplexIndex e = 0; e < edges.size(); ++e) {
    if (keep && !keep (e))
      continue;
    const FilteredEdge& edge = edges[e];
    adjacency.entries[next[edge.source]++] = {edge.target, e};
    adjacency.entries[next[edge.target]++] = {edge.source, e};
  }
  return adjacency;
}

} // namespace tda
} // namespace pcl
