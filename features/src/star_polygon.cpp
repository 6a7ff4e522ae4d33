#include <pcl/tda/common/plane_fit.h>
#include <pcl/tda/features/star_polygon.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl {
namespace tda {

std::vector<SimplexIndex>
starPolygon (const std::vector<SimplexIndex>& vertices,
             const std::vector<Point3d>& positions,
             const Eigen::Vector3d& centre,
             const Eigen::Matrix3d& axes,
             std::size_t bins)
{
  struct Farthest {
    SimplexIndex vertex = INVALID_SIMPLEX;
    double squared_distance = -1.0;
  };
  std::vector<Farthest> farthest (bins);
  for (const SimplexIndex v : vertices) {
    const Eigen::Vector3d d =
        Eigen::Vector3d (positions[v][0], positions[v][1], positions[v][2]) - centre;
    const double x = d.dot (axes.col (0)), y = d.dot (axes.col (1));
    const double angle = std::atan2 (y, x) + M_PI; // in [0, 2 pi]
    const auto bin = std::min (
        bins - 1,
        static_cast<std::size_t> (angle / (2.0 * M_PI) * static_cast<double> (bins)));
    const double squared_distance = x * x + y * y;
    Farthest& best = farthest[bin];
    if (squared_distance > best.squared_distance ||
        (squared_distance == best.squared_distance && v < best.vertex))
      best = {v, squared_distance};
  }
  std::vector<SimplexIndex> polygon;
  for (const Farthest& best : farthest)
    if (best.vertex != INVALID_SIMPLEX)
      polygon.push_back (best.vertex);
  return polygon;
}

std::vector<SimplexIndex>
starPolygonAround (const Eigen::Vector3d& centre,
                   double reach,
                   const std::vector<SimplexIndex>& start,
                   const std::vector<Point3d>& positions,
                   const EdgeAdjacency& adjacency,
                   double edge_length,
                   std::vector<std::uint8_t>& seen)
{
  const std::vector<SimplexIndex> vertices = reachFrom (
      start, adjacency, seen, std::numeric_limits<int>::max(), [&] (SimplexIndex v) {
        const Point3d& p = positions[v];
        return (Eigen::Vector3d (p[0], p[1], p[2]) - centre).norm() <= reach;
      });
  if (vertices.empty())
    return {};
  PlaneFit plane (positions[vertices.front()]);
  for (const SimplexIndex v : vertices)
    plane.add (positions[v]);
  const std::size_t bins = std::max (
      MIN_STAR_POLYGON_BINS,
      static_cast<std::size_t> (std::ceil (2.0 * M_PI * reach / edge_length)));
  return starPolygon (vertices, positions, centre, plane.principalAxes(), bins);
}

} // namespace tda
} // namespace pcl
