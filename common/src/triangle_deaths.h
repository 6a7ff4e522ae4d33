#pragma once

#include <pcl/tda/common/cycle_set.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_diagram.h>

#include <vector>

namespace pcl {
namespace tda {

/** \brief Completes \a result, which holds H0 pairs and edge marks, from the edge
 * whose class each triangle kills (INVALID_SIMPLEX for a positive triangle): H1
 * pairs, the triangle marks and the essential classes of dimension 1 (positive edges
 * never killed). Shared by the engines that compute H1 apart
 * from H0. */
void
addTriangleDeaths (const FilteredComplex& complex,
                   const std::vector<SimplexIndex>& killed_edge,
                   PersistenceResult& result);

/** \brief Completes \a result (H0 pairs and edge marks) by adding every triangle, in
 * filtration order, to a cycle table of the incremental engines (Alg 5.11 or
 * 5.12): \a Table is constructed from the complex and the edge marks and has
 * addTriangle(t) returning the edge t kills. */
template <typename Table>
void
addH1ByCycleTable (const FilteredComplex& complex, PersistenceResult& result)
{
  Table table (complex, result.positive_edges);
  std::vector<SimplexIndex> killed_edge (complex.numTriangles());
  for (SimplexIndex t = 0; t < complex.numTriangles(); ++t)
    killed_edge[t] = table.addTriangle (t);
  addTriangleDeaths (complex, killed_edge, result);
}

/** \brief The positive edges of the boundary of \a triangle, in increasing order:
 * the set Lambda of thesis Alg 5.10-5.13. */
CycleSet
positiveBoundary (const FilteredComplex& complex,
                  const std::vector<bool>& positive_edges,
                  SimplexIndex triangle);

} // namespace tda
} // namespace pcl
