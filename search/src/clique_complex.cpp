#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/search/clique_complex.h>
#include <pcl/tda/search/youngest_edge_triangles.h>

#include <algorithm>
#include <numeric>

namespace pcl {
namespace tda {

std::vector<std::uint64_t>
countTriangles (const std::vector<FilteredEdge>& edges,
                const EdgeAdjacency& adjacency,
                unsigned int threads,
                const ProgressCallback& progress)
{
  auto offsets = largeVector<std::uint64_t> (edges.size() + 1, 0);
  forEachEdgeWithYoungestTriangles (
      adjacency, threads, progress, [&] (SimplexIndex e, const auto& triangles) {
        triangles ([&] (SimplexIndex, SimplexIndex) { ++offsets[e + 1]; });
      });
  std::partial_sum (offsets.begin(), offsets.end(), offsets.begin());
  return offsets;
}

std::vector<FilteredTriangle>
fillTriangles (const std::vector<FilteredEdge>& edges,
               const EdgeAdjacency& adjacency,
               const std::vector<std::uint64_t>& offsets,
               unsigned int threads,
               const ProgressCallback& progress)
{
  auto triangles = largeVector<FilteredTriangle> (offsets.back());
  forEachEdgeWithYoungestTriangles (
      adjacency, threads, progress, [&] (SimplexIndex e, const auto& youngest_at_e) {
        auto out = triangles.begin() + offsets[e];
        youngest_at_e ([&] (SimplexIndex uw, SimplexIndex vw) {
          *out++ = {{e, std::max (uw, vw), std::min (uw, vw)}, edges[e].value};
        });
        std::sort (triangles.begin() + offsets[e],
                   out,
                   [] (const FilteredTriangle& a, const FilteredTriangle& b) {
                     return a.edges[1] < b.edges[1];
                   });
      });
  return triangles;
}

} // namespace tda
} // namespace pcl
