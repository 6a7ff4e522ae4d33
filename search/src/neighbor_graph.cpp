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
: points_ (points), radius_ (radius), origin_{0.0, 0.0, 0.0}
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
  point_ids_.reserve (points.size());
  for (std::size_t k = 0; k < cell_of_point.size(); ++k) {
    if (k == 0 || cell_of_point[k].first != cell_of_point[k - 1].first) {
      cell_keys_.push_back (cell_of_point[k].first);
      cell_offsets_.push_back (static_cast<std::uint32_t> (k));
    }
    point_ids_.push_back (cell_of_point[k].second);
  }
  cell_offsets_.push_back (static_cast<std::uint32_t> (points.size()));
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
  const CellKey center = cellOf (points_[vertex]);
  for (std::int64_t dx = -1; dx <= 1; ++dx)
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      // The three cells (x, y, z - 1 .. z + 1) are consecutive in key order.
      const CellKey first{center[0] + dx, center[1] + dy, center[2] - 1};
      const CellKey last{center[0] + dx, center[1] + dy, center[2] + 1};
      auto cell = std::lower_bound (cell_keys_.begin(), cell_keys_.end(), first);
      for (; cell != cell_keys_.end() && *cell <= last; ++cell) {
        const std::size_t c = cell - cell_keys_.begin();
        candidates.insert (candidates.end(),
                           point_ids_.begin() + cell_offsets_[c],
                           point_ids_.begin() + cell_offsets_[c + 1]);
      }
    }
}

namespace {

/** The neighbours j > \a vertex within \a radius, sorted, from the candidates. */
void
collectNeighbors (const std::vector<Point3d>& points,
                  double radius,
                  SimplexIndex vertex,
                  std::vector<SimplexIndex>& candidates)
{
  const auto outside = [&] (SimplexIndex j) {
    return j <= vertex || distance (points[vertex], points[j]) > radius;
  };
  candidates.erase (std::remove_if (candidates.begin(), candidates.end(), outside),
                    candidates.end());
  std::sort (candidates.begin(), candidates.end());
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
      collectNeighbors (points, radius, static_cast<SimplexIndex> (i), candidates);
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
      collectNeighbors (points, radius, static_cast<SimplexIndex> (i), candidates);
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
