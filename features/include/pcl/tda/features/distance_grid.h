#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace pcl {
namespace tda {

/** \brief A grid over a box of a plane that knows, for every cell, the nearest of a
 * set of seed points and the distance from the cell's centre to it: how empty the
 * plane is there. Hole detection finds a hole's empty region with it, and measures
 * how far points are from that region.
 *
 * The nearest seeds come from a two-pass propagation (each cell takes the nearest of
 * its neighbours' nearest seeds, forwards then backwards), exact up to a fraction of
 * a cell. Building costs the number of cells plus the number of seeds. */
class DistanceGrid {
public:
  /** \param[in] low the box's lower corner
   * \param[in] high the box's upper corner
   * \param[in] cell the cells' side (> 0)
   * \param[in] seeds the points (those outside the box still count), kept by
   * reference: they must outlive the grid */
  DistanceGrid (const Eigen::Vector2d& low,
                const Eigen::Vector2d& high,
                double cell,
                const std::vector<Eigen::Vector2d>& seeds);

  /** \brief The bytes of a grid over a box of size \a extent with cells of side
   * \a cell, as a double (it may not fit the memory, or a size_t). */
  static double
  bytesFor (const Eigen::Vector2d& extent, double cell)
  {
    return (std::floor (extent.x() / cell) + 3.0) *
           (std::floor (extent.y() / cell) + 3.0) *
           static_cast<double> (sizeof (std::uint32_t) + sizeof (double));
  }

  int
  width () const
  {
    return nx_;
  }

  int
  height () const
  {
    return ny_;
  }

  /** \brief The centre of cell (\a ix, \a iy). */
  Eigen::Vector2d
  center (int ix, int iy) const
  {
    return low_ + cell_ * Eigen::Vector2d (ix + 0.5, iy + 0.5);
  }

  /** \brief The cell holding \a q; false when \a q is outside the grid. */
  bool
  cellOf (const Eigen::Vector2d& q, int& ix, int& iy) const;

  /** \brief The distance from the centre of cell (\a ix, \a iy) to the nearest seed
   * (infinity without seeds). */
  double
  distance (int ix, int iy) const;

private:
  static constexpr std::uint32_t NO_SEED = std::numeric_limits<std::uint32_t>::max();

  /** The cells take their neighbours' nearest seeds, in two passes. */
  void
  propagate ();

  /** The position of cell (\a ix, \a iy) in the arrays, which have a border of
   * cells without a seed around the grid. */
  std::size_t
  index (int ix, int iy) const
  {
    return (static_cast<std::size_t> (iy) + 1) * stride_ +
           static_cast<std::size_t> (ix) + 1;
  }

  /** Makes \a seed the nearest seed of the cell at \a cell (centred at \a at) when
   * it is nearer than the cell's. */
  void
  offer (std::uint32_t seed, std::size_t cell, const Eigen::Vector2d& at)
  {
    if (seed == nearest_[cell] || seed == NO_SEED)
      return;
    const double squared = (seeds_[seed] - at).squaredNorm();
    if (squared < squared_distance_[cell]) {
      squared_distance_[cell] = squared;
      nearest_[cell] = seed;
    }
  }

  Eigen::Vector2d low_;
  double cell_;
  int nx_ = 0;
  int ny_ = 0;
  std::size_t stride_ = 0; // cells per row of the arrays
  const std::vector<Eigen::Vector2d>& seeds_;
  std::vector<std::uint32_t> nearest_;   // or NO_SEED
  std::vector<double> squared_distance_; // to the nearest seed
};

} // namespace tda
} // namespace pcl
