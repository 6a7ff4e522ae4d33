#include <pcl/tda/search/neighbor_graph.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <cmath>

namespace pcl {
namespace tda {

double
distance (const Point3d& a, const Point3d& b)
{
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt (dx * dx + dy * dy + dz * dz);
}

UniformGridSearch::UniformGridSearch (const std::vector<Point3d>& points, double radius)
: radius_ (radius), origin_{0.0, 0.0, 0.0}
{
  if (!(radius > 0.0))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "grid cell size must be positive, not " << radius);
  if (points.empty())
    return;
  Point3d high = points[0];
  origin_ = points[0];
  for (const auto& point : points)
    for (int axis = 0; axis < 3; ++axis) {
      origin_[axis] = std::min (origin_[axis], point[axis]);
      high[axis] = std::max (high[axis], point[axis]);
    }
  for (int axis = 0; axis < 3; ++axis)
    if ((high[axis] - origin_[axis]) / radius > 1e15)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "radius " << radius << " is too small for a cloud extent of "
                                     << high[axis] - origin_[axis]);

  std::vector<std::pair<CellKey, SimplexIndex>> cell_of_point (points.size());
  for (SimplexIndex i = 0; i < points.size(); ++i)
    cell_of_point[i] = {cellOf (points[i]), i};
  std::sort (cell_of_point.begin(), cell_of_point.end());
  std::vector<CellKey> cell_keys;
  std::vector<std::uint32_t> cell_offsets;
  point_ids_.reserve (points.size());
  cell_of_point_.resize (points.size());
  for (std::size_t k = 0; k < cell_of_point.size(); ++k) {
    if (k == 0 || cell_of_point[k].first != cell_of_point[k - 1].first) {
      cell_keys.push_back (cell_of_point[k].first);
      cell_offsets.push_back (static_cast<std::uint32_t> (k));
    }
    point_ids_.push_back (cell_of_point[k].second);
    cell_of_point_[cell_of_point[k].second] =
        static_cast<std::uint32_t> (cell_keys.size() - 1);
  }
  cell_offsets.push_back (static_cast<std::uint32_t> (points.size()));

  // The stencil of a cell: its column (x, y - 1 .. y + 1) and the next one in x.
  // Cells in key order are consecutive in z, so each (dx, dy) is one run of cells,
  // and so one run of point_ids_.
  stencils_.resize (cell_keys.size());
  const auto num_cells = static_cast<std::int64_t> (cell_keys.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t c = 0; c < num_cells; ++c) {
    const CellKey& center = cell_keys[c];
    std::size_t run = 0;
    for (std::int64_t dx = 0; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy, ++run) {
        const CellKey first{center[0] + dx, center[1] + dy, center[2] - 1};
        const CellKey last{center[0] + dx, center[1] + dy, center[2] + 1};
        const auto begin = std::lower_bound (cell_keys.begin(), cell_keys.end(), first);
        const auto end = std::upper_bound (begin, cell_keys.end(), last);
        stencils_[c][run] = {cell_offsets[begin - cell_keys.begin()],
                             cell_offsets[end - cell_keys.begin()]};
      }
  }
}

UniformGridSearch::CellKey
UniformGridSearch::cellOf (const Point3d& point) const
{
  CellKey key;
  for (int axis = 0; axis < 3; ++axis)
    key[axis] = static_cast<std::int64_t> (
        std::floor ((point[axis] - origin_[axis]) / radius_));
  return key;
}

void
UniformGridSearch::operator() (SimplexIndex vertex,
                               std::vector<SimplexIndex>& candidates) const
{
  candidates.clear();
  for (const auto& [begin, end] : stencils_[cell_of_point_[vertex]])
    candidates.insert (
        candidates.end(), point_ids_.begin() + begin, point_ids_.begin() + end);
}

namespace {

/** Whether distance(\a p, \a q) <= \a radius, deciding on the squared distance
 * where it is clear and taking the square root only near the boundary. */
bool
withinRadius (const Point3d& p, const Point3d& q, double radius)
{
  const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
  const double squared = dx * dx + dy * dy + dz * dz;
  const double squared_radius = radius * radius;
  if (squared < squared_radius * (1.0 - 1e-9))
    return true;
  if (squared > squared_radius * (1.0 + 1e-9))
    return false;
  return std::sqrt (squared) <= radius;
}

/** Keeps the candidates that are neighbours j > \a vertex within \a radius. */
void
keepLaterNeighbors (const std::vector<Point3d>& points,
                    double radius,
                    SimplexIndex vertex,
                    std::vector<SimplexIndex>& candidates)
{
  const auto outside = [&] (SimplexIndex j) {
    return j <= vertex || !withinRadius (points[vertex], points[j], radius);
  };
  candidates.erase (std::remove_if (candidates.begin(), candidates.end(), outside),
                    candidates.end());
}

} // namespace

std::vector<std::uint32_t>
countNeighbors (const std::vector<Point3d>& points,
                double radius,
                const CandidateSearch& search)
{
  const auto n = static_cast<std::int64_t> (points.size());
  std::vector<std::uint32_t> counts (points.size());
#pragma omp parallel
  {
    std::vector<SimplexIndex> candidates;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t i = 0; i < n; ++i) {
      search (static_cast<SimplexIndex> (i), candidates);
      keepLaterNeighbors (points, radius, static_cast<SimplexIndex> (i), candidates);
      counts[i] = static_cast<std::uint32_t> (candidates.size());
    }
  }
  return counts;
}

NeighborGraph
fillNeighborGraph (const std::vector<Point3d>& points,
                   double radius,
                   const CandidateSearch& search,
                   const std::vector<std::uint32_t>& counts)
{
  NeighborGraph graph;
  graph.offsets.assign (points.size() + 1, 0);
  for (std::size_t i = 0; i < points.size(); ++i)
    graph.offsets[i + 1] = graph.offsets[i] + counts[i];
  graph.neighbors.resize (graph.offsets.back());
  graph.lengths.resize (graph.offsets.back());

  const auto n = static_cast<std::int64_t> (points.size());
#pragma omp parallel
  {
    std::vector<SimplexIndex> candidates;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t i = 0; i < n; ++i) {
      search (static_cast<SimplexIndex> (i), candidates);
      keepLaterNeighbors (points, radius, static_cast<SimplexIndex> (i), candidates);
      std::sort (candidates.begin(), candidates.end());
      std::uint64_t position = graph.offsets[i];
      for (const SimplexIndex j : candidates) {
        graph.neighbors[position] = j;
        graph.lengths[position] = distance (points[i], points[j]);
        ++position;
      }
    }
  }
  return graph;
}

} // namespace tda
} // namespace pcl
