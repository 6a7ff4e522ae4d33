#include <pcl/tda/common/spanning_forest.h>

#include <algorithm>

namespace pcl {
namespace tda {

namespace {

/** Filter-Kruskal on edges[begin, end): appends the forest's edges to \a forest. */
void
filterKruskal (std::vector<FilteredEdge>& edges,
               std::size_t begin,
               std::size_t end,
               UnionFind& components,
               std::vector<FilteredEdge>& forest)
{
  constexpr std::size_t SMALL = 2048;
  if (end - begin <= SMALL) {
    std::sort (edges.begin() + begin, edges.begin() + end, edgeFiltrationLess);
    for (std::size_t e = begin; e < end; ++e) {
      const SimplexIndex a = components.find (edges[e].source);
      const SimplexIndex b = components.find (edges[e].target);
      if (a != b) {
        components.linkRoots (a, b);
        forest.push_back (edges[e]);
      }
    }
    return;
  }
  const std::size_t middle = begin + (end - begin) / 2;
  std::nth_element (edges.begin() + begin,
                    edges.begin() + middle,
                    edges.begin() + end,
                    edgeFiltrationLess);
  filterKruskal (edges, begin, middle, components, forest);
  const auto joined = [&components] (const FilteredEdge& edge) {
    return components.find (edge.source) == components.find (edge.target);
  };
  const auto rest =
      std::remove_if (edges.begin() + middle, edges.begin() + end, joined);
  filterKruskal (edges, middle, rest - edges.begin(), components, forest);
}

} // namespace

std::vector<FilteredEdge>
minimumSpanningForest (std::size_t num_vertices, std::vector<FilteredEdge>& edges)
{
  UnionFind components (num_vertices);
  std::vector<FilteredEdge> forest;
  forest.reserve (num_vertices > 0 ? num_vertices - 1 : 0);
  extendSpanningForest (edges, components, forest);
  return forest;
}

void
extendSpanningForest (std::vector<FilteredEdge>& edges,
                      UnionFind& components,
                      std::vector<FilteredEdge>& forest)
{
  filterKruskal (edges, 0, edges.size(), components, forest);
}

} // namespace tda
} // namespace pcl
