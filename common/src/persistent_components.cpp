#include <pcl/tda/common/persistent_components.h>
#include <pcl/tda/common/union_find.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pcl {
namespace tda {

std::vector<pcl::Indices>
persistentComponents (const FilteredComplex& complex,
                      const PersistenceResult& h0,
                      double cut)
{
  const std::size_t num_vertices = complex.numVertices();
  UnionFind components (num_vertices);
  for (const SimplexIndex e : h0.negativeEdges()) {
    const FilteredEdge& edge = complex.edges()[e];
    if (edge.value > cut)
      break;
    components.linkRoots (components.find (edge.source), components.find (edge.target));
  }

  // Number the components by their oldest vertex, then fill them in vertex order.
  constexpr std::uint32_t NONE = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> component_of_root (num_vertices, NONE);
  std::vector<pcl::Indices> result;
  const pcl::Indices& point_indices = complex.pointIndices();
  for (SimplexIndex v = 0; v < num_vertices; ++v) {
    const SimplexIndex root = components.find (v);
    if (component_of_root[root] == NONE) {
      component_of_root[root] = static_cast<std::uint32_t> (result.size());
      result.emplace_back();
      result.back().reserve (components.setSize (root));
    }
    result[component_of_root[root]].push_back (point_indices[v]);
  }
  for (auto& component : result)
    std::sort (component.begin(), component.end());
  std::sort (
      result.begin(), result.end(), [] (const pcl::Indices& a, const pcl::Indices& b) {
        return a.size() != b.size() ? a.size() > b.size() : a[0] < b[0];
      });
  return result;
}

PersistenceDiagram
steppedH0Diagram (const FilteredComplex& complex,
                  const PersistenceResult& h0,
                  double max_value,
                  unsigned int steps)
{
  PersistenceDiagram diagram = h0.diagram (complex, 0);
  if (steps == 0)
    return diagram;
  const double step = max_value / steps;
  PersistenceDiagram stepped;
  for (PersistenceInterval interval : diagram) {
    if (!interval.isEssential()) {
      const double k = std::ceil (interval.death / step);
      interval.death = k >= steps ? max_value : k * step;
    }
    stepped.push_back (interval);
  }
  return stepped;
}

} // namespace tda
} // namespace pcl
