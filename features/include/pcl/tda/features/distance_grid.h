#pragma once

#include <Eigen/Core>

#include <cstdint>
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
  void
  offer (std::uint32_t seed, int ix, int iy);

  std::uint32_t
  nearestAt (int ix, int iy) const;

  Eigen::Vector2d low_;
  double cell_;
  int nx_ = 0;
  int ny_ = 0;
  const std::vector<Eigen::Vector2d>& seeds_;
  std::vector<std::uint32_t> nearest_;
  std::vector<double> squared_distance_; // to the nearest seed
};

} // namespace tda
} // namespace pcl
