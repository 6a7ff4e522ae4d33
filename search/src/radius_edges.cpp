#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/common/resource_settings.h>
#include <pcl/tda/search/radius_edges.h>

#include <omp.h>

#include <algorithm>
#include <numeric>

namespace pcl {
namespace tda {

int
resolveThreads (unsigned int threads)
{
  return threads > 0 ? static_cast<int> (std::min (threads, MAX_THREADS))
                     : omp_get_max_threads();
}

unsigned int
threadsForPoints (unsigned int threads, std::size_t points)
{
  if (threads > 0)
    return std::min (threads, MAX_THREADS);
  const auto most = static_cast<std::size_t> (resolveThreads (0));
  return static_cast<unsigned int> (
      std::clamp<std::size_t> (points / POINTS_PER_THREAD, 1, most));
}

namespace {

/** The candidates of \a vertex that are later vertices within \a radius, sorted. */
void
findLaterNeighbors (const std::vector<Point3d>& points,
                    double radius,
                    const CandidateSearch& search,
                    SimplexIndex vertex,
                    std::vector<SimplexIndex>& neighbors)
{
  search (vertex, neighbors);
  const auto outside = [&] (SimplexIndex j) {
    return j <= vertex || !withinRadius (points[vertex], points[j], radius);
  };
  neighbors.erase (std::remove_if (neighbors.begin(), neighbors.end(), outside),
                   neighbors.end());
  std::sort (neighbors.begin(), neighbors.end());
}

} // namespace

std::vector<std::uint64_t>
countEdgesBySearch (const std::vector<Point3d>& points,
                    double radius,
                    const CandidateSearch& search,
                    unsigned int threads)
{
  const auto n = static_cast<std::int64_t> (points.size());
  std::vector<std::uint64_t> offsets (points.size() + 1, 0);
#pragma omp parallel num_threads(resolveThreads(threads))
  {
    std::vector<SimplexIndex> neighbors;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t i = 0; i < n; ++i) {
      findLaterNeighbors (
          points, radius, search, static_cast<SimplexIndex> (i), neighbors);
      offsets[i + 1] = neighbors.size();
    }
  }
  std::partial_sum (offsets.begin(), offsets.end(), offsets.begin());
  return offsets;
}

std::vector<FilteredEdge>
listEdgesBySearch (const std::vector<Point3d>& points,
                   double radius,
                   const CandidateSearch& search,
                   const std::vector<std::uint64_t>& offsets,
                   unsigned int threads)
{
  auto edges = largeVector<FilteredEdge> (offsets.back());
  const auto n = static_cast<std::int64_t> (points.size());
#pragma omp parallel num_threads(resolveThreads(threads))
  {
    std::vector<SimplexIndex> neighbors;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t i = 0; i < n; ++i) {
      const auto vertex = static_cast<SimplexIndex> (i);
      findLaterNeighbors (points, radius, search, vertex, neighbors);
      std::uint64_t position = offsets[i];
      for (const SimplexIndex j : neighbors)
        edges[position++] = {vertex, j, distance (points[i], points[j])};
    }
  }
  return edges;
}

} // namespace tda
} // namespace pcl
