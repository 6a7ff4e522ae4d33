#include <pcl/tda/search/radius_spanning_forest.h>

namespace pcl {
namespace tda {

SpanningForestScales
spanningForestScales (const std::vector<Point3d>& points,
                      double radius,
                      unsigned int threads)
{
  SpanningForestScales scales{{radius}, UniformGrid (points, radius, threads)};
  const double sparse =
      SPANNING_FOREST_PAIRS_PER_POINT * static_cast<double> (points.size());
  while (scales.scales.size() < MAX_SPANNING_FOREST_SCALES &&
         static_cast<double> (scales.finest.numCandidatePairs()) > sparse) {
    scales.scales.push_back (scales.scales.back() / 2.0);
    scales.finest = UniformGrid (points, scales.scales.back(), threads);
  }
  std::reverse (scales.scales.begin(), scales.scales.end());
  return scales;
}

ComponentRuns::ComponentRuns (const UniformGrid& grid, UnionFind& components)
: grid_ (grid)
{
  const std::uint32_t n = grid.numCells() > 0 ? grid.cellBegin (grid.numCells()) : 0;
  component_at_.resize (n);
  run_end_.resize (n);
  for (std::uint32_t i = 0; i < n; ++i)
    component_at_[i] = components.find (grid.pointAt (i));
  for (std::uint32_t i = n; i-- > 0;)
    run_end_[i] =
        i + 1 < n && component_at_[i + 1] == component_at_[i] ? run_end_[i + 1] : i + 1;
}

} // namespace tda
} // namespace pcl
