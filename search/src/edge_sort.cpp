#include <pcl/tda/search/radius_edges.h>

#include "stable_radix_sort.h"

#include <algorithm>

namespace pcl {
namespace tda {

void
sortEdges (std::vector<FilteredEdge>& edges, unsigned int threads)
{
  // By value (stableRadixSort()), then the runs of equal values by their ends. The
  // order is strict and total, so the result does not depend on the threads.
  std::vector<FilteredEdge> scratch;
  stableRadixSort (
      edges,
      [] (const FilteredEdge& edge) { return orderedBits (edge.value); },
      threads,
      scratch);
  const std::size_t n = edges.size();
  for (std::size_t first = 0, last = 0; first < n; first = last) {
    for (last = first + 1; last < n && edges[last].value == edges[first].value;)
      ++last;
    if (last - first > 1)
      std::sort (edges.begin() + first, edges.begin() + last, edgeFiltrationLess);
  }
}

} // namespace tda
} // namespace pcl
