#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/search/clique_complex.h>
#include <pcl/tda/search/parallel_progress.h>
#include <pcl/tda/search/radius_edges.h>

#include <algorithm>
#include <numeric>

namespace pcl {
namespace tda {

namespace {

/** Edges between two reports of progress. */
constexpr std::int64_t PROGRESS_STEP = 4096;

} // namespace

std::vector<std::uint64_t>
countTriangles (const std::vector<FilteredEdge>& edges,
                const EdgeAdjacency& adjacency,
                unsigned int threads,
                const ProgressCallback& progress)
{
  auto offsets = largeVector<std::uint64_t> (edges.size() + 1, 0);
  const auto m = static_cast<std::int64_t> (edges.size());
  ParallelProgress tracker (progress, edges.size());
#pragma omp parallel num_threads(resolveThreads(threads))
  {
    CommonNeighborSearch search (edges, adjacency);
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t e = 0; e < m; ++e) {
      search.forEach (static_cast<SimplexIndex> (e),
                      true,
                      [&] (SimplexIndex, SimplexIndex) { ++offsets[e + 1]; });
      if (e % PROGRESS_STEP == 0)
        tracker.advance (PROGRESS_STEP);
    }
  }
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
  const auto m = static_cast<std::int64_t> (edges.size());
  ParallelProgress tracker (progress, edges.size());
#pragma omp parallel num_threads(resolveThreads(threads))
  {
    CommonNeighborSearch search (edges, adjacency);
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t e = 0; e < m; ++e) {
      const auto youngest = static_cast<SimplexIndex> (e);
      auto out = triangles.begin() + offsets[e];
      search.forEach (youngest, true, [&] (SimplexIndex uw, SimplexIndex vw) {
        *out++ = {{youngest, std::max (uw, vw), std::min (uw, vw)}, edges[e].value};
      });
      std::sort (triangles.begin() + offsets[e],
                 out,
                 [] (const FilteredTriangle& a, const FilteredTriangle& b) {
                   return a.edges[1] < b.edges[1];
                 });
      if (e % PROGRESS_STEP == 0)
        tracker.advance (PROGRESS_STEP);
    }
  }
  return triangles;
}

} // namespace tda
} // namespace pcl
