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
  result.positive_edges.assign (complex.numEdges(), false);
  result.positive_triangles.assign (complex.numTriangles(), false);

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
        result.positive_edges[simplex.index] = true;
      else if (simplex.dimension == 2)
        result.positive_triangles[simplex.index] = true;
    }
    else {
      const SimplexRef birth = order[column.back()];
      pivot_owner[column.back()] = j;
      result.pairs.push_back ({birth.dimension,
                               birth.index,
                               simplex.index,
                               complex.value (birth),
                               complex.value (simplex)});
      reduced[j].swap (column);
    }
    if (progress && (j % 4096 == 0 || j + 1 == num_columns))
      progress (j + 1, num_columns);
  }

  for (std::uint32_t g = 0; g < num_columns; ++g)
    if (order[g].dimension < 2 && reduced[g].empty() && pivot_owner[g] == NO_COLUMN)
      result.pairs.push_back ({order[g].dimension,
                               order[g].index,
                               INVALID_SIMPLEX,
                               complex.value (order[g]),
                               std::numeric_limits<double>::infinity()});
  return result;
}

} // namespace tda
} // namespace pcl
