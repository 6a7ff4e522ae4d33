#include <pcl/tda/search/radius_edges.h>
#include <pcl/tda/search/uniform_grid.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pcl {
namespace tda {

namespace {

using CellKey = std::array<std::int64_t, 3>;

/** Cells per block of the pass that finds every cell's neighbour runs. */
constexpr std::int64_t CELLS_PER_BLOCK = 4096;

/** The rows (x + dx, y + dy) of the later neighbour cells of a cell (x, y, z) that
 * lie outside its own row. */
constexpr std::array<std::array<std::int64_t, 2>, 4> NEIGHBOR_ROWS{
    {{0, 1}, {1, -1}, {1, 0}, {1, 1}}};

/** The first key of neighbour row \a row of cell \a key: (x + dx, y + dy, z - 1). */
CellKey
rowStart (const CellKey& key, std::size_t row)
{
  return {key[0] + NEIGHBOR_ROWS[row][0], key[1] + NEIGHBOR_ROWS[row][1], key[2] - 1};
}

/** The last key of neighbour row \a row of cell \a key: (x + dx, y + dy, z + 1). */
CellKey
rowEnd (const CellKey& key, std::size_t row)
{
  return {key[0] + NEIGHBOR_ROWS[row][0], key[1] + NEIGHBOR_ROWS[row][1], key[2] + 1};
}

/** The cells with keys in a range [low, high], for ranges that only move forward: a
 * cursor over sorted keys. */
class KeyRangeCursor {
public:
  KeyRangeCursor() = default;

  /** Starts at the first of \a keys not below \a low. */
  KeyRangeCursor (const std::vector<CellKey>& keys, const CellKey& low)
  : keys_ (&keys)
  , begin_ (std::lower_bound (keys.begin(), keys.end(), low) - keys.begin())
  , end_ (begin_)
  {}

  /** The positions [begin, end) of the keys in [\a low, \a high], for \a low and
   * \a high not below those of the call before. */
  std::pair<std::size_t, std::size_t>
  advance (const CellKey& low, const CellKey& high)
  {
    const std::vector<CellKey>& keys = *keys_;
    while (begin_ < keys.size() && keys[begin_] < low)
      ++begin_;
    end_ = std::max (end_, begin_);
    while (end_ < keys.size() && !(high < keys[end_]))
      ++end_;
    return {begin_, end_};
  }

private:
  const std::vector<CellKey>* keys_ = nullptr;
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
};

} // namespace

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

  // Cells are in the order of their keys, and so are the rows of cells that a fixed
  // offset takes them to: a cursor per neighbour row only moves forward, over a block
  // of cells after a binary search at the block's first cell.
  runs_.resize (cell_keys.size());
  const auto num_cells = static_cast<std::int64_t> (cell_keys.size());
  const std::int64_t num_blocks = (num_cells + CELLS_PER_BLOCK - 1) / CELLS_PER_BLOCK;
#pragma omp parallel for schedule(static) num_threads(resolveThreads(threads))
  for (std::int64_t block = 0; block < num_blocks; ++block) {
    const std::int64_t first = block * CELLS_PER_BLOCK;
    const std::int64_t last = std::min (num_cells, first + CELLS_PER_BLOCK);
    std::array<KeyRangeCursor, NEIGHBOR_ROWS.size()> rows;
    for (std::size_t row = 0; row < rows.size(); ++row)
      rows[row] = KeyRangeCursor (cell_keys, rowStart (cell_keys[first], row));
    for (std::int64_t c = first; c < last; ++c) {
      // Cell (x, y, z + 1), when there is one, is the next: the first run ends with it.
      const auto [x, y, z] = cell_keys[c];
      const bool next_above =
          c + 1 < num_cells && cell_keys[c + 1] == CellKey{x, y, z + 1};
      runs_[c][0] = {cell_begin_[c], cell_begin_[c + 1 + (next_above ? 1 : 0)]};
      for (std::size_t row = 0; row < rows.size(); ++row) {
        const auto [begin, end] = rows[row].advance (rowStart (cell_keys[c], row),
                                                     rowEnd (cell_keys[c], row));
        runs_[c][row + 1] = {cell_begin_[begin], cell_begin_[end]};
      }
    }
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
