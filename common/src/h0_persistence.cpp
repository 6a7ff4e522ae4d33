#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/common/union_find.h>

#include <algorithm>

namespace pcl {
namespace tda {

PersistenceResult
computeH0Persistence (const FilteredComplex& complex)
{
  const std::size_t num_vertices = complex.numVertices();
  PersistenceResult result;
  result.vertex_killer = largeVector<SimplexIndex> (num_vertices, INVALID_SIMPLEX);
  result.edge_positive = largeVector<std::uint8_t> (complex.numEdges(), 1);

  UnionFind components (num_vertices);
  // The oldest (smallest) vertex of each component, stored at its representative.
  std::vector<SimplexIndex> oldest (num_vertices);
  for (SimplexIndex v = 0; v < num_vertices; ++v)
    oldest[v] = v;

  const auto& edges = complex.edges();
  for (SimplexIndex e = 0; e < edges.size(); ++e) {
    const SimplexIndex a = components.find (edges[e].source);
    const SimplexIndex b = components.find (edges[e].target);
    if (a == b)
      continue;
    result.edge_positive[e] = 0;
    result.vertex_killer[std::max (oldest[a], oldest[b])] = e;
    oldest[components.linkRoots (a, b)] = std::min (oldest[a], oldest[b]);
  }
  return result;
}

} // namespace tda
} // namespace pcl
