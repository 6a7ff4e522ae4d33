#pragma once

#include <pcl/tda/common/cycle_set.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/common/progress.h>

#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Completes \a result, which holds the H0 arrays, from the edge whose class
 * each triangle kills (INVALID_SIMPLEX for a positive triangle): the killer of every
 * edge and the triangle marks. Shared by the engines that compute H1 apart from H0.
 */
void
addTriangleDeaths (const std::vector<SimplexIndex>& killed_edge,
                   PersistenceResult& result);

/** \brief Completes \a result (the H0 arrays) by adding every triangle, in
 * filtration order, to a cycle table of the incremental engines (Alg 5.11 or
 * 5.12): \a Table is constructed from the complex and the edge marks and has
 * addTriangle(t) returning the edge t kills. */
template <typename Table>
void
addH1ByCycleTable (const FilteredComplex& complex,
                   PersistenceResult& result,
                   const ProgressCallback& progress)
{
  Table table (complex, result.edge_positive);
  const std::size_t num_triangles = complex.numTriangles();
  std::vector<SimplexIndex> killed_edge (num_triangles);
  for (SimplexIndex t = 0; t < num_triangles; ++t) {
    killed_edge[t] = table.addTriangle (t);
    reportProgress (progress, t, num_triangles);
  }
  addTriangleDeaths (killed_edge, result);
}

/** \brief The positive edges of the boundary of \a triangle, in increasing order:
 * the set Lambda of thesis Alg 5.10-5.13. */
CycleSet
positiveBoundary (const FilteredComplex& complex,
                  const std::vector<std::uint8_t>& edge_positive,
                  SimplexIndex triangle);

} // namespace tda
} // namespace pcl
