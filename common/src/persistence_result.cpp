#include <pcl/tda/common/persistence_result.h>

#include <algorithm>
#include <limits>

namespace pcl {
namespace tda {

namespace {

/** Calls \a visit with every pair of \a result of dimension <= \a max_dimension, in
 * the order PersistenceResult::pairs() documents: the one walk that pairs() and
 * diagram() share. */
template <typename Visit>
void
forEachPair (const PersistenceResult& result,
             const FilteredComplex& complex,
             int max_dimension,
             Visit visit)
{
  constexpr double INF = std::numeric_limits<double>::infinity();
  const auto& edges = complex.edges();
  const auto& triangles = complex.triangles();
  const std::vector<SimplexIndex> killed_vertex = result.killedVertices();
  for (SimplexIndex e = 0; e < killed_vertex.size(); ++e)
    if (killed_vertex[e] != INVALID_SIMPLEX)
      visit (PersistencePair{0, killed_vertex[e], e, 0.0, edges[e].value});
  for (SimplexIndex v = 0; v < result.vertex_killer.size(); ++v)
    if (result.vertex_killer[v] == INVALID_SIMPLEX)
      visit (PersistencePair{0, v, INVALID_SIMPLEX, 0.0, INF});
  if (std::min (max_dimension, result.max_dimension) < 1)
    return;

  std::vector<SimplexIndex> killed_edge (triangles.size(), INVALID_SIMPLEX);
  for (SimplexIndex e = 0; e < result.edge_killer.size(); ++e)
    if (result.edge_killer[e] != INVALID_SIMPLEX)
      killed_edge[result.edge_killer[e]] = e;
  for (SimplexIndex t = 0; t < killed_edge.size(); ++t)
    if (killed_edge[t] != INVALID_SIMPLEX)
      visit (PersistencePair{
          1, killed_edge[t], t, edges[killed_edge[t]].value, triangles[t].value});
  for (SimplexIndex e = 0; e < result.edge_killer.size(); ++e)
    if (result.edge_positive[e] && result.edge_killer[e] == INVALID_SIMPLEX)
      visit (PersistencePair{1, e, INVALID_SIMPLEX, edges[e].value, INF});
}

} // namespace

std::vector<PersistencePair>
PersistenceResult::pairs (const FilteredComplex& complex, int max_dimension) const
{
  std::vector<PersistencePair> result;
  result.reserve (vertex_killer.size()); // one H0 pair per vertex
  forEachPair (*this, complex, max_dimension, [&result] (const PersistencePair& pair) {
    result.push_back (pair);
  });
  return result;
}

PersistenceDiagram
PersistenceResult::diagram (const FilteredComplex& complex, int max_dimension) const
{
  PersistenceDiagram intervals;
  intervals.reserve (vertex_killer.size()); // at most one H0 interval per vertex
  forEachPair (
      *this, complex, max_dimension, [&intervals] (const PersistencePair& pair) {
        if (pair.birth != pair.death)
          intervals.push_back ({pair.dimension, pair.birth, pair.death});
      });
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
