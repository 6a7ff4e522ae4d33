#include <pcl/tda/common/persistence_result.h>

#include <algorithm>
#include <limits>

namespace pcl {
namespace tda {

std::vector<PersistencePair>
PersistenceResult::pairs (const FilteredComplex& complex, int max_dimension) const
{
  constexpr double INF = std::numeric_limits<double>::infinity();
  const auto& edges = complex.edges();
  const auto& triangles = complex.triangles();
  std::vector<PersistencePair> result;
  const std::vector<SimplexIndex> killed_vertex = killedVertices();
  for (SimplexIndex e = 0; e < killed_vertex.size(); ++e)
    if (killed_vertex[e] != INVALID_SIMPLEX)
      result.push_back ({0, killed_vertex[e], e, 0.0, edges[e].value});
  for (SimplexIndex v = 0; v < vertex_killer.size(); ++v)
    if (vertex_killer[v] == INVALID_SIMPLEX)
      result.push_back ({0, v, INVALID_SIMPLEX, 0.0, INF});
  if (std::min (max_dimension, this->max_dimension) < 1)
    return result;

  std::vector<SimplexIndex> killed_edge (triangles.size(), INVALID_SIMPLEX);
  for (SimplexIndex e = 0; e < edge_killer.size(); ++e)
    if (edge_killer[e] != INVALID_SIMPLEX)
      killed_edge[edge_killer[e]] = e;
  for (SimplexIndex t = 0; t < killed_edge.size(); ++t)
    if (killed_edge[t] != INVALID_SIMPLEX)
      result.push_back (
          {1, killed_edge[t], t, edges[killed_edge[t]].value, triangles[t].value});
  for (SimplexIndex e = 0; e < edge_killer.size(); ++e)
    if (edge_positive[e] && edge_killer[e] == INVALID_SIMPLEX)
      result.push_back ({1, e, INVALID_SIMPLEX, edges[e].value, INF});
  return result;
}

PersistenceDiagram
PersistenceResult::diagram (const FilteredComplex& complex, int max_dimension) const
{
  PersistenceDiagram intervals;
  for (const auto& pair : pairs (complex, max_dimension))
    if (pair.birth != pair.death)
      intervals.push_back ({pair.dimension, pair.birth, pair.death});
  return intervals;
}

std::vector<SimplexIndex>
PersistenceResult::negativeEdges() const
{
  std::vector<SimplexIndex> forest;
  for (SimplexIndex e = 0; e < edge_positive.size(); ++e)
    if (!edge_positive[e])
      forest.push_back (e);
  return forest;
}

std::vector<SimplexIndex>
PersistenceResult::killedVertices() const
{
  std::vector<SimplexIndex> killed_vertex (edge_positive.size(), INVALID_SIMPLEX);
  for (SimplexIndex v = 0; v < vertex_killer.size(); ++v)
    if (vertex_killer[v] != INVALID_SIMPLEX)
      killed_vertex[vertex_killer[v]] = v;
  return killed_vertex;
}

} // namespace tda
} // namespace pcl
