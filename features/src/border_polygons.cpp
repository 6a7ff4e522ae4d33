#include <pcl/tda/common/plane_fit.h>
#include <pcl/tda/features/border_polygons.h>
#include <pcl/tda/search/radius_edges.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pcl {
namespace tda {

namespace {

/** The smallest gap between the directions to a border vertex's neighbours. */
constexpr double BORDER_GAP = 0.75 * M_PI;
/** The fewest angle bins of a polygon. */
constexpr std::size_t MIN_POLYGON_BINS = 8;
/** How far, in edges, a polygon keeps from its border component. */
constexpr int POLYGON_MARGIN_EDGES = 2;
/** How many edges apart border vertices of one component may be. */
constexpr int BRIDGE_EDGES = 2;

Eigen::Vector3d
toEigen (const Point3d& p)
{
  return {p[0], p[1], p[2]};
}

/** True when the directions from \a v to its neighbours, in the plane fitted to them
 * and \a v, leave a gap wider than BORDER_GAP. */
bool
onBorder (SimplexIndex v,
          const std::vector<Point3d>& positions,
          const EdgeAdjacency& adjacency,
          std::vector<double>& angles)
{
  const EdgeAdjacency::Range neighbors = adjacency.neighbors (v);
  if (neighbors.end() - neighbors.begin() < 2)
    return false;
  PlaneFit plane (positions[v]);
  plane.add (positions[v]);
  for (const auto& entry : neighbors)
    plane.add (positions[entry.neighbor]);
  const Eigen::Matrix3d axes = plane.principalAxes();
  const Eigen::Vector3d origin = toEigen (positions[v]);
  angles.clear();
  for (const auto& entry : neighbors) {
    const Eigen::Vector3d d = toEigen (positions[entry.neighbor]) - origin;
    angles.push_back (std::atan2 (d.dot (axes.col (1)), d.dot (axes.col (0))));
  }
  std::sort (angles.begin(), angles.end());
  double widest = angles.front() + 2.0 * M_PI - angles.back();
  for (std::size_t k = 1; k < angles.size(); ++k)
    widest = std::max (widest, angles[k] - angles[k - 1]);
  return widest > BORDER_GAP;
}

/** The vertices within \a steps edges of \a component (itself included), using
 * \a seen (all 0 on entry and on return) as scratch. */
std::vector<SimplexIndex>
neighborhood (const std::vector<SimplexIndex>& component,
              const EdgeAdjacency& adjacency,
              std::vector<std::uint8_t>& seen,
              int steps)
{
  std::vector<SimplexIndex> reached = component;
  for (const SimplexIndex v : component)
    seen[v] = 1;
  std::size_t ring_begin = 0;
  for (int step = 0; step < steps; ++step) {
    const std::size_t ring_end = reached.size();
    for (std::size_t k = ring_begin; k < ring_end; ++k)
      for (const auto& entry : adjacency.neighbors (reached[k]))
        if (!seen[entry.neighbor]) {
          seen[entry.neighbor] = 1;
          reached.push_back (entry.neighbor);
        }
    ring_begin = ring_end;
  }
  for (const SimplexIndex v : reached)
    seen[v] = 0;
  return reached;
}

/** The polygon around \a component: the farthest vertex of its neighbourhood in
 * each angle bin around the component's centroid, in its plane. */
std::vector<SimplexIndex>
polygonAround (const std::vector<SimplexIndex>& component,
               const std::vector<Point3d>& positions,
               const EdgeAdjacency& adjacency,
               std::vector<std::uint8_t>& seen)
{
  PlaneFit plane (positions[component.front()]);
  for (const SimplexIndex v : component)
    plane.add (positions[v]);
  const Eigen::Matrix3d axes = plane.principalAxes();
  const Eigen::Vector3d centroid = plane.centroid();
  const std::size_t bins = std::max (MIN_POLYGON_BINS, component.size());
  struct Farthest {
    SimplexIndex vertex = INVALID_SIMPLEX;
    double squared_distance = -1.0;
  };
  std::vector<Farthest> farthest (bins);
  for (const SimplexIndex v :
       neighborhood (component, adjacency, seen, POLYGON_MARGIN_EDGES)) {
    const Eigen::Vector3d d = toEigen (positions[v]) - centroid;
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

} // namespace

std::vector<InitialCycle>
borderPolygons (const std::vector<Point3d>& positions,
                const EdgeAdjacency& adjacency,
                double radius,
                double min_clearance,
                unsigned int threads)
{
  const auto n = static_cast<std::int64_t> (positions.size());
  std::vector<std::uint8_t> border (positions.size(), 0);
#pragma omp parallel num_threads(resolveThreads(threads))
  {
    std::vector<double> angles;
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t v = 0; v < n; ++v)
      border[v] =
          onBorder (static_cast<SimplexIndex> (v), positions, adjacency, angles);
  }
  const auto min_size =
      static_cast<std::size_t> (std::ceil (2.0 * M_PI * min_clearance / radius));
  std::vector<InitialCycle> polygons;
  std::vector<std::uint8_t> seen (positions.size(), 0);
  std::vector<SimplexIndex> component;
  for (SimplexIndex root = 0; root < positions.size(); ++root) {
    if (!border[root])
      continue;
    // The component of border vertices of root, joined through paths of up to
    // BRIDGE_EDGES edges (rim points with narrower gaps do not cut it); taken
    // vertices lose their flag.
    border[root] = 0;
    component.assign (1, root);
    for (std::size_t head = 0; head < component.size(); ++head)
      for (const SimplexIndex v :
           neighborhood ({component[head]}, adjacency, seen, BRIDGE_EDGES))
        if (border[v]) {
          border[v] = 0;
          component.push_back (v);
        }
    if (component.size() < min_size)
      continue;
    std::vector<SimplexIndex> polygon =
        polygonAround (component, positions, adjacency, seen);
    if (polygon.size() >= 3)
      polygons.push_back ({std::move (polygon), INVALID_SIMPLEX});
  }
  return polygons;
}

} // namespace tda
} // namespace pcl
