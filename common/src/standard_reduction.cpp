#include <pcl/tda/common/cycle_set.h>
#include <pcl/tda/common/standard_reduction.h>

#include <algorithm>
#include <limits>

namespace pcl {
namespace tda {

namespace {

/** A column of the boundary matrix: the sorted global positions of its faces. */
using Column = CycleSet;
constexpr std::uint32_t NO_COLUMN = std::numeric_limits<std::uint32_t>::max();

} // namespace

PersistenceResult
computeStandardReduction (const FilteredComplex& complex,
                          const ProgressCallback& progress)
{
  const std::vector<SimplexRef> order = complex.filtrationOrder();
  const std::size_t num_columns = order.size();

  // Global filtration position of every edge (vertices come first, in order).
  std::vector<std::uint32_t> edge_position (complex.numEdges());
  for (std::uint32_t g = 0; g < num_columns; ++g)
    if (order[g].dimension == 1)
      edge_position[order[g].index] = g;

  std::vector<Column> reduced (num_columns);
  std::vector<std::uint32_t> pivot_owner (num_columns, NO_COLUMN);
  PersistenceResult result;
  result.max_dimension = 1;
  result.vertex_killer.assign (complex.numVertices(), INVALID_SIMPLEX);
  result.edge_positive.assign (complex.numEdges(), 0);
  result.edge_killer.assign (complex.numEdges(), INVALID_SIMPLEX);
  result.triangle_positive.assign (complex.numTriangles(), 0);

  Column column, buffer;
  for (std::uint32_t j = 0; j < num_columns; ++j) {
    const SimplexRef simplex = order[j];
    column.clear();
    if (simplex.dimension == 1) {
      const FilteredEdge& edge = complex.edges()[simplex.index];
      column = {edge.source, edge.target};
    }
    else if (simplex.dimension == 2) {
      const auto& ids = complex.triangles()[simplex.index].edges;
      column = {edge_position[ids[2]], edge_position[ids[1]], edge_position[ids[0]]};
    }
    while (!column.empty() && pivot_owner[column.back()] != NO_COLUMN)
      addCycle (column, reduced[pivot_owner[column.back()]], buffer);

    if (column.empty()) {
      if (simplex.dimension == 1)
        result.edge_positive[simplex.index] = 1;
      else if (simplex.dimension == 2)
        result.triangle_positive[simplex.index] = 1;
    }
    else {
      const SimplexRef birth = order[column.back()];
      pivot_owner[column.back()] = j;
      (birth.dimension == 0 ? result.vertex_killer : result.edge_killer)[birth.index] =
          simplex.index;
      reduced[j].swap (column);
    }
    reportProgress (progress, j, num_columns);
  }
  return result;
}

} // namespace tda
} // namespace pcl
