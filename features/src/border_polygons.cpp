#include <pcl/tda/common/angular_gap.h>
#include <pcl/tda/common/plane_fit.h>
#include <pcl/tda/features/border_polygons.h>
#include <pcl/tda/features/star_polygon.h>
#include <pcl/tda/search/radius_edges.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

namespace pcl {
namespace tda {

namespace {

/** The smallest gap between the directions to a border vertex's neighbours. */
constexpr double BORDER_GAP = 0.75 * M_PI;
/** How many edges apart border vertices of one component may be. */
constexpr int BRIDGE_EDGES = 2;
/** The smallest eigenvalue, per vertex, of the sum of the projections across the
 * gap directions of a component whose lines are taken to meet: 0 when they are
 * parallel; (1 - sin(a) / a) / 2 for directions spread evenly over an angle a: 0.18
 * over a quarter turn, 0.5 over a half. */
constexpr double MIN_SPREAD = 0.1;

Eigen::Vector3d
toEigen (const Point3d& p)
{
  return {p[0], p[1], p[2]};
}

/** When the directions from \a v to its neighbours, in the plane fitted to them and
 * \a v, leave a gap wider than BORDER_GAP: the unit direction that halves the gap
 * (towards the empty side); otherwise zero. */
Eigen::Vector3d
borderGap (SimplexIndex v,
           const std::vector<Point3d>& positions,
           const EdgeAdjacency& adjacency,
           std::vector<double>& angles)
{
  const EdgeAdjacency::Range neighbors = adjacency.neighbors (v);
  if (neighbors.end() - neighbors.begin() < 2)
    return Eigen::Vector3d::Zero();
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
  const AngularGap gap = widestAngularGap (angles);
  if (gap.width <= BORDER_GAP)
    return Eigen::Vector3d::Zero();
  return std::cos (gap.middle) * axes.col (0) + std::sin (gap.middle) * axes.col (1);
}

/** Admits every vertex (reachFrom()). */
bool
anyVertex (SimplexIndex)
{
  return true;
}

/** The centre of the hole a border component goes around, where the lines from its
 * vertices along their gap directions meet (least squares), with its median
 * distance to them; none when the lines do not meet on the gap side within the
 * component's extent (a straight border, scattered noise). A part of a rim does:
 * every line points at the hole's centre. */
std::optional<std::pair<Eigen::Vector3d, double>>
holeCentre (const std::vector<SimplexIndex>& component,
            const std::vector<Point3d>& positions,
            const std::vector<Eigen::Vector3d>& gaps)
{
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right_side = Eigen::Vector3d::Zero();
  const Eigen::Vector3d origin = toEigen (positions[component.front()]);
  Eigen::Vector3d low = Eigen::Vector3d::Zero(), high = low;
  for (const SimplexIndex v : component) {
    const Eigen::Vector3d p = toEigen (positions[v]) - origin;
    const Eigen::Matrix3d across =
        Eigen::Matrix3d::Identity() - gaps[v] * gaps[v].transpose();
    normal_matrix += across;
    right_side += across * p;
    low = low.cwiseMin (p);
    high = high.cwiseMax (p);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (normal_matrix);
  // The lines' directions must spread: a quarter turn at least on a round rim.
  if (!(solver.eigenvalues()[0] >= MIN_SPREAD * static_cast<double> (component.size())))
    return std::nullopt;
  const Eigen::Vector3d centre = normal_matrix.ldlt().solve (right_side);
  std::vector<double> distances;
  double ahead = 0.0;
  for (const SimplexIndex v : component) {
    const Eigen::Vector3d to_centre = centre - (toEigen (positions[v]) - origin);
    distances.push_back (to_centre.norm());
    ahead += gaps[v].dot (to_centre);
  }
  const auto middle =
      distances.begin() + static_cast<std::ptrdiff_t> (distances.size() / 2);
  std::nth_element (distances.begin(), middle, distances.end());
  if (!(ahead > 0.0) || !(*middle <= (high - low).norm()))
    return std::nullopt;
  return std::make_pair (centre + origin, *middle);
}

/** The polygon around \a component: around the centre of its hole when its gap
 * directions meet (holeCentre()), the vertices reached within the hole's radius
 * and STAR_POLYGON_MARGIN_EDGES edges of it; otherwise around its centroid, the
 * vertices within STAR_POLYGON_MARGIN_EDGES edges of it. */
std::vector<SimplexIndex>
polygonAround (const std::vector<SimplexIndex>& component,
               const std::vector<Point3d>& positions,
               const std::vector<Eigen::Vector3d>& gaps,
               const EdgeAdjacency& adjacency,
               double radius,
               std::vector<std::uint8_t>& seen)
{
  const auto hole = holeCentre (component, positions, gaps);
  if (hole)
    return starPolygonAround (hole->first,
                              hole->second + STAR_POLYGON_MARGIN_EDGES * radius,
                              component,
                              positions,
                              adjacency,
                              radius,
                              seen);
  const std::vector<SimplexIndex> vertices =
      reachFrom (component, adjacency, seen, STAR_POLYGON_MARGIN_EDGES, anyVertex);
  PlaneFit plane (positions[component.front()]);
  for (const SimplexIndex v : component)
    plane.add (positions[v]);
  return starPolygon (vertices,
                      positions,
                      plane.centroid(),
                      plane.principalAxes(),
                      std::max (MIN_STAR_POLYGON_BINS, component.size()));
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
  std::vector<Eigen::Vector3d> gaps (positions.size());
#pragma omp parallel num_threads(resolveThreads(threads))
  {
    std::vector<double> angles;
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t v = 0; v < n; ++v)
      gaps[v] = borderGap (static_cast<SimplexIndex> (v), positions, adjacency, angles);
  }
  std::vector<std::uint8_t> border (positions.size(), 0);
  for (std::size_t v = 0; v < positions.size(); ++v)
    border[v] = !gaps[v].isZero();
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
           reachFrom ({component[head]}, adjacency, seen, BRIDGE_EDGES, anyVertex))
        if (border[v]) {
          border[v] = 0;
          component.push_back (v);
        }
    if (component.size() < min_size)
      continue;
    std::vector<SimplexIndex> polygon =
        polygonAround (component, positions, gaps, adjacency, radius, seen);
    if (polygon.size() >= 3)
      polygons.push_back ({std::move (polygon), INVALID_SIMPLEX});
  }
  return polygons;
}

} // namespace tda
} // namespace pcl
