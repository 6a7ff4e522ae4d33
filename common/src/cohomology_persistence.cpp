#include <pcl/tda/common/cohomology_persistence.h>
#include <pcl/tda/common/cycle_set.h>

#include "triangle_deaths.h"

namespace pcl {
namespace tda {

namespace {

/** The triangles containing each edge, in filtration order (compressed rows). */
struct Coboundaries {
  std::vector<std::uint64_t> offsets;
  std::vector<SimplexIndex> triangles;

  explicit Coboundaries (const FilteredComplex& complex)
  : offsets (complex.numEdges() + 1, 0), triangles (3 * complex.numTriangles())
  {
    for (const auto& triangle : complex.triangles())
      for (const auto e : triangle.edges)
        ++offsets[e + 1];
    for (std::size_t e = 0; e < complex.numEdges(); ++e)
      offsets[e + 1] += offsets[e];
    std::vector<std::uint64_t> next (offsets.begin(), offsets.end() - 1);
    for (SimplexIndex t = 0; t < complex.numTriangles(); ++t)
      for (const auto e : complex.triangles()[t].edges)
        triangles[next[e]++] = t;
  }

  CycleSet
  of (SimplexIndex edge) const
  {
    return CycleSet (triangles.begin() + offsets[edge],
                     triangles.begin() + offsets[edge + 1]);
  }

  bool
  empty (SimplexIndex edge) const
  {
    return offsets[edge] == offsets[edge + 1];
  }

  SimplexIndex
  oldest (SimplexIndex edge) const
  {
    return triangles[offsets[edge]];
  }
};

} // namespace

void
addCohomologyH1Persistence (const FilteredComplex& complex,
                            PersistenceResult& result,
                            const ProgressCallback& progress)
{
  const Coboundaries coboundaries (complex);
  const auto& triangles = complex.triangles();
  const std::size_t num_edges = complex.numEdges();

  // killed_edge[t]: the edge whose reduced coboundary has pivot t (owner of t).
  std::vector<SimplexIndex> killed_edge (triangles.size(), INVALID_SIMPLEX);
  // Reduced coboundaries of the edges that needed reduction and were paired; an
  // apparent pair's column is its coboundary, unchanged.
  std::vector<CycleSet> reduced (num_edges);
  CycleSet column, buffer, owner_column;

  for (std::size_t k = 0; k < num_edges; ++k) {
    const auto edge = static_cast<SimplexIndex> (num_edges - 1 - k);
    if (progress && (k % 65536 == 0 || k + 1 == num_edges))
      progress (k + 1, num_edges);
    if (!result.positive_edges[edge] || coboundaries.empty (edge))
      continue;
    const SimplexIndex oldest = coboundaries.oldest (edge);
    if (triangles[oldest].edges[0] == edge) { // apparent pair
      killed_edge[oldest] = edge;
      continue;
    }
    column = coboundaries.of (edge);
    while (!column.empty() && killed_edge[column.front()] != INVALID_SIMPLEX) {
      const SimplexIndex owner = killed_edge[column.front()];
      if (reduced[owner].empty()) {
        owner_column = coboundaries.of (owner);
        addCycle (column, owner_column, buffer);
      }
      else
        addCycle (column, reduced[owner], buffer);
    }
    if (!column.empty()) {
      killed_edge[column.front()] = edge;
      reduced[edge].swap (column);
    }
  }
  addTriangleDeaths (complex, killed_edge, result);
}

} // namespace tda
} // namespace pcl
