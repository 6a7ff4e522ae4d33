#pragma once

#include <pcl/tda/common/point3d.h>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace pcl {
namespace tda {

/** \brief A uniform grid of cubic cells over a point set, for fixed-radius search:
 * with the cell size at least the radius, the points within the radius of a point
 * lie in its cell or in one of the 26 around it.
 *
 * It lists candidate pairs with a half stencil: cells are ordered by their (x, y, z)
 * cell coordinates, and a cell is paired with itself and with the 13 neighbours that
 * come after it, so every pair of points of neighbouring cells is visited exactly
 * once, from the cell that comes first. The 13 cells form four runs of consecutive
 * cells (z - 1 .. z + 1 for four (x, y) columns) plus the cell after it in z, found
 * once at construction. Cells can be processed in parallel, one per task. The
 * Vietoris-Rips builder and the spanning forest of clustering read pairs this way;
 * it is the one grid the coming modules (region growing, the gpu/ mirror) build on.
 */
class UniformGrid {
public:
  /** \brief Sorts the points into cells of size \a cell_size, with \a threads
   * OpenMP threads (0: OpenMP's default).
   * \throws pcl::BadArgumentException when \a cell_size is not positive and finite,
   * or so small against the extent of the points that cells cannot be indexed */
  UniformGrid (const std::vector<Point3d>& points,
               double cell_size,
               unsigned int threads = 0);

  std::size_t
  numCells () const
  {
    return cell_begin_.empty() ? 0 : cell_begin_.size() - 1;
  }

  /** \brief Number of points of cell \a cell. */
  std::size_t
  cellSize (std::size_t cell) const
  {
    return cell_begin_[cell + 1] - cell_begin_[cell];
  }

  /** \brief Calls \a visit(a, b) for every candidate pair of cell \a cell: a in the
   * cell, b after a in the cell or in one of its 13 later neighbours; a and b are
   * indices into the points given at construction. Over all cells, every pair of
   * points in the same or neighbouring cells is visited once, in an order that does
   * not depend on anything but the points. */
  template <typename Visit>
  void
  forEachCandidatePair (std::size_t cell, Visit visit) const
  {
    const std::uint32_t begin = cell_begin_[cell], end = cell_begin_[cell + 1];
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t a = point_ids_[i];
      for (std::uint32_t j = i + 1; j < runs_[cell][0].second; ++j)
        visit (a, point_ids_[j]); // the cell's later points, then cell (x, y, z + 1)
      for (std::size_t run = 1; run < runs_[cell].size(); ++run)
        for (std::uint32_t j = runs_[cell][run].first; j < runs_[cell][run].second; ++j)
          visit (a, point_ids_[j]);
    }
  }

  /** \brief The number of candidate pairs of all cells: an upper bound on the
   * number of pairs within the cell size, known before any distance is computed. */
  std::uint64_t
  numCandidatePairs () const;

private:
  using CellKey = std::array<std::int64_t, 3>;
  /** Runs [begin, end) of point_ids_: the cell itself with cell (x, y, z + 1), then
   * the columns (x, y + 1), (x + 1, y - 1), (x + 1, y), (x + 1, y + 1), z - 1 .. z + 1.
   */
  using Stencil = std::array<std::pair<std::uint32_t, std::uint32_t>, 5>;

  std::vector<std::uint32_t> point_ids_;  // points grouped by cell, cells in key order
  std::vector<std::uint32_t> cell_begin_; // first position of every cell, and the end
  std::vector<Stencil> runs_;             // one per cell
};

} // namespace tda
} // namespace pcl
