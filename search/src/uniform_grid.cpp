#include <pcl/tda/search/radius_edges.h>
#include <pcl/tda/search/uniform_grid.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl {
namespace tda {

UniformGrid::UniformGrid (const std::vector<Point3d>& points,
                          double cell_size,
                          unsigned int threads)
{
  if (!(cell_size > 0.0) || !std::isfinite (cell_size))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "the grid cell size must be positive and finite, not "
                             << cell_size);
  if (points.size() >= std::numeric_limits<std::uint32_t>::max())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "the grid holds fewer than 2^32 - 1 points, not "
                             << points.size());
  if (points.empty())
    return;
  Point3d low = points[0], high = points[0];
  for (const auto& point : points)
    for (int axis = 0; axis < 3; ++axis) {
      low[axis] = std::min (low[axis], point[axis]);
      high[axis] = std::max (high[axis], point[axis]);
    }
  // Cell coordinates are clamped to stay exact in int64: clamping is monotone and
  // moves no two points apart, so points within a cell size of each other stay in the
  // same or neighbouring cells; far outliers (a point at 1e30) share the last cells.
  constexpr double LAST_CELL = 4611686018427387904.0; // 2^62
  std::vector<std::pair<CellKey, std::uint32_t>> keyed (points.size());
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    CellKey key;
    for (int axis = 0; axis < 3; ++axis)
      key[axis] = static_cast<std::int64_t> (
          std::floor (std::min ((points[i][axis] - low[axis]) / cell_size, LAST_CELL)));
    keyed[i] = {key, i};
  }
  std::sort (keyed.begin(), keyed.end());
  std::vector<CellKey> cell_keys;
  point_ids_.resize (points.size());
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    if (k == 0 || keyed[k].first != keyed[k - 1].first) {
      cell_keys.push_back (keyed[k].first);
      cell_begin_.push_back (static_cast<std::uint32_t> (k));
    }
    point_ids_[k] = keyed[k].second;
  }
  cell_begin_.push_back (static_cast<std::uint32_t> (points.size()));

  // The positions of the cells with keys in [first, last], as a run of point_ids_.
  const auto run = [&] (const CellKey& first, const CellKey& last) {
    const auto begin = std::lower_bound (cell_keys.begin(), cell_keys.end(), first);
    const auto end = std::upper_bound (begin, cell_keys.end(), last);
    return std::make_pair (cell_begin_[begin - cell_keys.begin()],
                           cell_begin_[end - cell_keys.begin()]);
  };
  runs_.resize (cell_keys.size());
  const auto num_cells = static_cast<std::int64_t> (cell_keys.size());
#pragma omp parallel for schedule(static) num_threads(resolveThreads(threads))
  for (std::int64_t c = 0; c < num_cells; ++c) {
    const auto [x, y, z] = cell_keys[c];
    // Cell (x, y, z + 1), when there is one, is the next cell: its run ends the first.
    runs_[c][0] = {cell_begin_[c], run ({x, y, z + 1}, {x, y, z + 1}).second};
    runs_[c][1] = run ({x, y + 1, z - 1}, {x, y + 1, z + 1});
    for (std::int64_t dy = -1; dy <= 1; ++dy)
      runs_[c][dy + 3] = run ({x + 1, y + dy, z - 1}, {x + 1, y + dy, z + 1});
  }
}

std::uint64_t
UniformGrid::numCandidatePairs() const
{
  std::uint64_t pairs = 0;
  for (std::size_t c = 0; c < numCells(); ++c) {
    const std::uint64_t n = cellSize (c);
    std::uint64_t later = runs_[c][0].second - cell_begin_[c + 1];
    for (std::size_t run = 1; run < runs_[c].size(); ++run)
      later += runs_[c][run].second - runs_[c][run].first;
    pairs += n * (n - 1) / 2 + n * later;
  }
  return pairs;
}

} // namespace tda
} // namespace pcl
