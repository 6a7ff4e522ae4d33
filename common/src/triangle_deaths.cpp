#include "triangle_deaths.h"

#include <algorithm>
#include <limits>

namespace pcl {
namespace tda {

void
addTriangleDeaths (const FilteredComplex& complex,
                   const std::vector<SimplexIndex>& killed_edge,
                   PersistenceResult& result)
{
  const auto& edges = complex.edges();
  const auto& triangles = complex.triangles();
  constexpr double INF = std::numeric_limits<double>::infinity();
  result.positive_triangles.assign (triangles.size(), false);
  std::vector<bool> killed (edges.size(), false);
  result.pairs.reserve (result.pairs.size() + std::count (result.positive_edges.begin(),
                                                          result.positive_edges.end(),
                                                          true));
  for (SimplexIndex t = 0; t < triangles.size(); ++t) {
    const SimplexIndex e = killed_edge[t];
    if (e == INVALID_SIMPLEX) {
      result.positive_triangles[t] = true;
      continue;
    }
    killed[e] = true;
    result.pairs.push_back ({1, e, t, edges[e].value, triangles[t].value});
  }
  for (SimplexIndex e = 0; e < edges.size(); ++e)
    if (result.positive_edges[e] && !killed[e])
      result.pairs.push_back ({1, e, INVALID_SIMPLEX, edges[e].value, INF});
}

CycleSet
positiveBoundary (const FilteredComplex& complex,
                  const std::vector<bool>& positive_edges,
                  SimplexIndex triangle)
{
  CycleSet boundary;
  const auto& ids = complex.triangles()[triangle].edges;
  for (int k = 2; k >= 0; --k)
    if (positive_edges[ids[k]])
      boundary.push_back (ids[k]);
  return boundary;
}

} // namespace tda
} // namespace pcl
