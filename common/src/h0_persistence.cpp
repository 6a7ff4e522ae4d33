#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/union_find.h>

#include <limits>

namespace pcl {
namespace tda {

PersistenceResult
computeH0Persistence (const FilteredComplex& complex)
{
  const std::size_t num_vertices = complex.numVertices();
  PersistenceResult result;
  result.positive_edges.assign (complex.numEdges(), false);

  UnionFind components (num_vertices);
  // The oldest (smallest) vertex of each component, stored at its representative.
  std::vector<SimplexIndex> oldest (num_vertices);
  for (SimplexIndex v = 0; v < num_vertices; ++v)
    oldest[v] = v;

  const auto& edges = complex.edges();
  for (SimplexIndex e = 0; e < edges.size(); ++e) {
    const SimplexIndex a = components.find (edges[e].source);
    const SimplexIndex b = components.find (edges[e].target);
    if (a == b) {
      result.positive_edges[e] = true;
      continue;
    }
    const SimplexIndex elder = std::min (oldest[a], oldest[b]);
    const SimplexIndex younger = std::max (oldest[a], oldest[b]);
    result.pairs.push_back ({0, younger, e, 0.0, edges[e].value});
    oldest[components.linkRoots (a, b)] = elder;
  }
  for (SimplexIndex v = 0; v < num_vertices; ++v)
    if (components.find (v) == v)
      result.pairs.push_back ({0,
                               oldest[v],
                               INVALID_SIMPLEX,
                               0.0,
                               std::numeric_limits<double>::infinity()});
  return result;
}

} // namespace tda
} // namespace pcl
