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
  /** \brief Sorts the (finite) points into cells of size \a cell_size, with
   * \a threads OpenMP threads (0: OpenMP's default). Any extent works: cell
   * coordinates beyond 2^62 are clamped, which keeps every pair within the cell size
   * in the same or neighbouring cells.
   * \throws pcl::BadArgumentException when \a cell_size is not positive and finite,
   * or there are 2^32 - 1 points or more */
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

  /** \brief Runs [begin, end) of positions: the candidates after the point at
   * position \a position (in cell \a cell): the later points of its cell, and
   * the points of its 13 later neighbour cells. */
  using Runs = std::array<std::pair<std::uint32_t, std::uint32_t>, 5>;

  /** \brief The runs of positions of the candidates after position \a position,
   * which must lie in cell \a cell. */
  Runs
  laterCandidates (std::size_t cell, std::uint32_t position) const
  {
    Runs runs = runs_[cell];
    runs[0].first = position + 1; // the cell's later points, then cell (x, y, z + 1)
    return runs;
  }

  /** \brief The point (index into the points given at construction) at position
   * \a position of the cell order. */
  std::uint32_t
  pointAt (std::uint32_t position) const
  {
    return point_ids_[position];
  }

  /** \brief The first position of cell \a cell (cellBegin(numCells()) is the
   * number of points). */
  std::uint32_t
  cellBegin (std::size_t cell) const
  {
    return cell_begin_[cell];
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
    for (std::uint32_t i = cell_begin_[cell]; i < cell_begin_[cell + 1]; ++i) {
      const std::uint32_t a = point_ids_[i];
      for (const auto& [begin, end] : laterCandidates (cell, i))
        for (std::uint32_t j = begin; j < end; ++j)
          visit (a, point_ids_[j]);
    }
  }

  /** \brief The number of candidate pairs of all cells: an upper bound on the
   * number of pairs within the cell size, known before any distance is computed. */
  std::uint64_t
  numCandidatePairs () const;

private:
  using CellKey = std::array<std::int64_t, 3>;
  std::vector<std::uint32_t> point_ids_;  // points grouped by cell, cells in key order
  std::vector<std::uint32_t> cell_begin_; // first position of every cell, and the end
  // Per cell, runs of point_ids_: the cell itself with cell (x, y, z + 1), then the
  // columns (x, y + 1), (x + 1, y - 1), (x + 1, y), (x + 1, y + 1), z - 1 .. z + 1.
  std::vector<Runs> runs_;
};

} // namespace tda
} // namespace pcl
