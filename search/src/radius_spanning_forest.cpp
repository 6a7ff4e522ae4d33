#include <pcl/tda/search/radius_spanning_forest.h>

namespace pcl {
namespace tda {

std::vector<double>
spanningForestScales (const std::vector<Point3d>& points,
                      double radius,
                      unsigned int threads)
{
  std::vector<double> scales{radius};
  const double sparse =
      SPANNING_FOREST_PAIRS_PER_POINT * static_cast<double> (points.size());
  while (scales.size() < MAX_SPANNING_FOREST_SCALES &&
         static_cast<double> (
             UniformGrid (points, scales.back(), threads).numCandidatePairs()) > sparse)
    scales.push_back (scales.back() / 2.0);
  std::reverse (scales.begin(), scales.end());
  return scales;
}

std::vector<std::uint32_t>
idsByPosition (const std::vector<Point3d>& points)
{
  std::vector<std::uint32_t> ids (points.size());
  std::iota (ids.begin(), ids.end(), std::uint32_t{0});
  std::sort (ids.begin(), ids.end(), [&points] (std::uint32_t a, std::uint32_t b) {
    return points[a] != points[b] ? points[a] < points[b] : a < b;
  });
  return ids;
}

ComponentRuns::ComponentRuns (const UniformGrid& grid,
                              UnionFind& components,
                              std::size_t num_points)
: grid_ (grid)
{
  std::vector<std::uint32_t> component (num_points); // per point
  for (std::uint32_t v = 0; v < num_points; ++v) {
    component[v] = components.find (v);
    all_apart_ = all_apart_ && component[v] == v;
  }
  const std::uint32_t n = grid.numCells() > 0 ? grid.cellBegin (grid.numCells()) : 0;
  component_at_.resize (n);
  run_end_.resize (n);
  for (std::uint32_t i = 0; i < n; ++i)
    component_at_[i] = component[grid.pointAt (i)];
  for (std::uint32_t i = n; i-- > 0;)
    run_end_[i] =
        i + 1 < n && component_at_[i + 1] == component_at_[i] ? run_end_[i + 1] : i + 1;
}

} // namespace tda
} // namespace pcl
