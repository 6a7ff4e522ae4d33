#include "triangle_deaths.h"

#include <pcl/tda/common/large_vector.h>

namespace pcl {
namespace tda {

void
addTriangleDeaths (const std::vector<SimplexIndex>& killed_edge,
                   PersistenceResult& result)
{
  result.max_dimension = 1;
  result.edge_killer =
      largeVector<SimplexIndex> (result.edge_positive.size(), INVALID_SIMPLEX);
  result.triangle_positive = largeVector<std::uint8_t> (killed_edge.size(), 1);
  for (SimplexIndex t = 0; t < killed_edge.size(); ++t)
    if (killed_edge[t] != INVALID_SIMPLEX) {
      result.triangle_positive[t] = 0;
      result.edge_killer[killed_edge[t]] = t;
    }
}

CycleSet
positiveBoundary (const FilteredComplex& complex,
                  const std::vector<std::uint8_t>& edge_positive,
                  SimplexIndex triangle)
{
  CycleSet boundary;
  const auto& ids = complex.triangles()[triangle].edges;
  for (int k = 2; k >= 0; --k)
    if (edge_positive[ids[k]])
      boundary.push_back (ids[k]);
  return boundary;
}

} // namespace tda
} // namespace pcl
