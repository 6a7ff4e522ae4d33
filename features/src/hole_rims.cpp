#include <pcl/tda/common/plane_fit.h>
#include <pcl/tda/features/distance_grid.h>
#include <pcl/tda/features/hole_rims.h>
#include <pcl/tda/features/projected_polygon.h>
#include <pcl/tda/search/point_spacing.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace pcl {
namespace tda {

namespace {

/** How far rimBand() erodes, then widens, a hole's empty region, in spacings: slivers
 * of it narrower than twice this go. Half a spacing: a gap between two neighbouring
 * points at the hole's edge, not the hole. */
constexpr double EMPTY_OPENING_PER_SPACING = 0.5;

/** The plane of the surface at \a v: fitted to v and its neighbours. */
Eigen::Vector3f
surfaceNormal (SimplexIndex v,
               const std::vector<Point3d>& positions,
               const EdgeAdjacency& adjacency)
{
  PlaneFit plane (positions[v]);
  plane.add (positions[v]);
  for (const auto& entry : adjacency.neighbors (v))
    plane.add (positions[entry.neighbor]);
  return plane.normal();
}

/** The median of \a values (not empty), reordering them. */
double
median (std::vector<double>& values)
{
  const auto middle = values.begin() + static_cast<std::ptrdiff_t> (values.size() / 2);
  std::nth_element (values.begin(), middle, values.end());
  return *middle;
}

double
medianTilt (const std::vector<SimplexIndex>& rim,
            const Eigen::Vector3f& rim_normal,
            const std::vector<Point3d>& positions,
            const EdgeAdjacency& adjacency)
{
  std::vector<double> tilts;
  tilts.reserve (rim.size());
  for (const SimplexIndex v : rim) {
    const double cosine = std::min (
        1.0f, std::abs (surfaceNormal (v, positions, adjacency).dot (rim_normal)));
    tilts.push_back (std::acos (cosine) * 180.0 / M_PI);
  }
  return median (tilts);
}

/** The median of \a sparseness over the points of \a rim; 1 when it is empty. */
double
medianSparseness (const std::vector<SimplexIndex>& rim,
                  const std::vector<double>& sparseness)
{
  if (sparseness.empty())
    return 1.0;
  std::vector<double> values;
  values.reserve (rim.size());
  for (const SimplexIndex v : rim)
    values.push_back (sparseness[v]);
  return median (values);
}

} // namespace

std::vector<HoleRim>
holeRims (const std::vector<MinimalCycle>& cycles,
          const std::vector<Point3d>& positions,
          const EdgeAdjacency& adjacency,
          double max_tilt_degrees,
          std::size_t max_cycle_length,
          double min_clearance,
          const std::vector<double>& sparseness)
{
  struct Found {
    const MinimalCycle* cycle;
    ProjectedPolygon polygon;
    double reach; // the farthest rim point from the centroid
    HoleRim hole;

    /** True when \a point lies inside the rim seen along its normal, no farther
     * from its plane than the rim reaches: not a point across a tube or a closed
     * surface, whose holes can line up along the normal. */
    bool
    surrounds (const Point3d& point) const
    {
      const Eigen::Vector3d offset =
          Eigen::Vector3d (point[0], point[1], point[2]) - polygon.centroid();
      return std::abs (offset.dot (polygon.normal())) <= reach &&
             polygon.contains (polygon.project (point));
    }

    Point3d
    center () const
    {
      return {polygon.centroid().x(), polygon.centroid().y(), polygon.centroid().z()};
    }
  };
  std::vector<Found> found;
  for (const MinimalCycle& cycle : cycles) {
    const std::vector<SimplexIndex>& rim = cycle.vertices;
    if (rim.size() < 3 || (max_cycle_length > 0 && rim.size() > max_cycle_length) ||
        cycle.clearance < min_clearance * medianSparseness (rim, sparseness))
      continue;
    const ProjectedPolygon polygon (positions, rim);
    HoleRim hole;
    hole.normal = polygon.normal().cast<float>();
    hole.tilt_degrees = medianTilt (rim, hole.normal, positions, adjacency);
    if (hole.tilt_degrees > max_tilt_degrees)
      continue;
    hole.rim = rim;
    for (std::size_t i = 0; i < rim.size(); ++i) {
      const double length =
          distance (positions[rim[i]], positions[rim[(i + 1) % rim.size()]]);
      hole.perimeter += length;
      hole.birth = std::max (hole.birth, length);
    }
    hole.area = polygon.area();
    hole.clearance = cycle.clearance;
    hole.centroid = polygon.centroid().cast<float>();
    Found& added = found.emplace_back (Found{&cycle, polygon, 0.0, std::move (hole)});
    const Point3d centre = added.center();
    for (const SimplexIndex v : rim)
      added.reach = std::max (added.reach, distance (positions[v], centre));
  }
  // Several classes can go around the same empty region: keep its shortest rim.
  const auto byPerimeter = [] (const Found& a, const Found& b) {
    return std::tie (a.hole.perimeter, a.cycle->class_edge) <
           std::tie (b.hole.perimeter, b.cycle->class_edge);
  };
  std::sort (found.begin(), found.end(), byPerimeter);
  std::vector<Found> kept;
  for (Found& candidate : found) {
    const bool same_hole = std::any_of (kept.begin(), kept.end(), [&] (const Found& k) {
      return k.surrounds (candidate.cycle->hole_center) ||
             candidate.surrounds (k.cycle->hole_center) ||
             k.surrounds (candidate.center()) || candidate.surrounds (k.center());
    });
    if (!same_hole)
      kept.push_back (std::move (candidate));
  }
  std::sort (kept.begin(), kept.end(), [] (const Found& a, const Found& b) {
    return std::make_tuple (b.hole.rim.size(), a.cycle->class_edge) <
           std::make_tuple (a.hole.rim.size(), b.cycle->class_edge);
  });
  std::vector<HoleRim> holes;
  holes.reserve (kept.size());
  for (Found& k : kept)
    holes.push_back (std::move (k.hole));
  return holes;
}

std::vector<double>
cycleSparseness (const std::vector<MinimalCycle>& cycles,
                 const std::vector<Point3d>& positions,
                 double spacing,
                 unsigned int threads)
{
  std::vector<std::uint32_t> vertices;
  for (const MinimalCycle& cycle : cycles)
    vertices.insert (vertices.end(), cycle.vertices.begin(), cycle.vertices.end());
  std::sort (vertices.begin(), vertices.end());
  vertices.erase (std::unique (vertices.begin(), vertices.end()), vertices.end());
  const std::vector<double> local = localSurfaceSpacings (positions, vertices, threads);
  std::vector<double> sparseness (positions.size(), 1.0);
  for (std::size_t i = 0; i < vertices.size(); ++i)
    sparseness[vertices[i]] = std::max (1.0, local[i] / spacing);
  return sparseness;
}

std::vector<std::uint32_t>
rimBand (const std::vector<HoleRim>& holes,
         const std::vector<Point3d>& positions,
         const EdgeAdjacency& adjacency,
         double band_width,
         double spacing)
{
  std::vector<std::uint32_t> band (positions.size(), 0);
  std::vector<std::uint8_t> seen (positions.size(), 0);
  for (std::size_t h = holes.size(); h-- > 0;) { // earlier holes win shared points
    const HoleRim& hole = holes[h];
    const ProjectedPolygon polygon (positions, hole.rim);
    // The points within two edges of the rim: every point between the rim and the
    // hole, and the surface beside the rim.
    std::vector<SimplexIndex> near = hole.rim;
    for (const SimplexIndex v : near)
      seen[v] = 1;
    for (std::size_t head = 0, end = near.size(), hop = 0; hop < 2;
         ++hop, end = near.size())
      for (; head < end; ++head)
        for (const auto& entry : adjacency.neighbors (near[head]))
          if (!seen[entry.neighbor]) {
            seen[entry.neighbor] = 1;
            near.push_back (entry.neighbor);
          }
    std::vector<Eigen::Vector2d> projected;
    projected.reserve (near.size());
    for (const SimplexIndex v : near) {
      projected.push_back (polygon.project (positions[v]));
      seen[v] = 0;
    }
    // The hole's empty region: the cells inside the rim at least a spacing away
    // from every point.
    Eigen::Vector2d low = projected.front(), high = projected.front();
    for (std::size_t i = 0; i < hole.rim.size(); ++i) {
      low = low.cwiseMin (projected[i]);
      high = high.cwiseMax (projected[i]);
    }
    const double margin = band_width + spacing;
    low -= Eigen::Vector2d::Constant (margin);
    high += Eigen::Vector2d::Constant (margin);
    const double cell = std::max (spacing / 4.0, (high - low).maxCoeff() / 256.0);
    const DistanceGrid emptiness (low, high, cell, projected);
    std::vector<std::pair<Eigen::Vector2d, double>> clear_cells; // centre, clearance
    double deepest = 0.0;
    for (int iy = 0; iy < emptiness.height(); ++iy)
      for (int ix = 0; ix < emptiness.width(); ++ix)
        if (emptiness.distance (ix, iy) >= spacing &&
            polygon.contains (emptiness.center (ix, iy))) {
          clear_cells.emplace_back (emptiness.center (ix, iy),
                                    emptiness.distance (ix, iy));
          deepest = std::max (deepest, clear_cells.back().second);
        }
    // The empty region, opened: the places at least `clearance` from every point
    // (the region eroded by clearance - spacing), widened again by as much when the
    // band is measured. Where two points at the edge stand a little apart, the
    // region reaches out between them; the opening cuts such slivers, which would
    // otherwise carry the band that far beyond the edge.
    const double clearance =
        std::clamp (deepest, spacing, (1.0 + EMPTY_OPENING_PER_SPACING) * spacing);
    std::vector<Eigen::Vector2d> empty;
    for (const auto& [center, distance] : clear_cells)
      if (distance >= clearance)
        empty.push_back (center);
    // A point is in the band when it is within the band width of the hole's edge,
    // which lies about half a spacing outside the empty region.
    const DistanceGrid to_empty (low, high, cell, empty);
    const double reach = band_width + spacing / 2.0 + (clearance - spacing);
    for (std::size_t i = 0; i < near.size(); ++i) {
      int ix, iy;
      if (to_empty.cellOf (projected[i], ix, iy) && to_empty.distance (ix, iy) <= reach)
        band[near[i]] = static_cast<std::uint32_t> (h + 1);
    }
  }
  return band;
}

} // namespace tda
} // namespace pcl
