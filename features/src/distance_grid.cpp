#include <pcl/tda/features/distance_grid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace pcl {
namespace tda {

namespace {
constexpr std::uint32_t NO_SEED = std::numeric_limits<std::uint32_t>::max();
}

DistanceGrid::DistanceGrid (const Eigen::Vector2d& low,
                            const Eigen::Vector2d& high,
                            double cell,
                            const std::vector<Eigen::Vector2d>& seeds)
: low_ (low), cell_ (cell), seeds_ (seeds)
{
  nx_ = static_cast<int> ((high.x() - low.x()) / cell) + 1;
  ny_ = static_cast<int> ((high.y() - low.y()) / cell) + 1;
  nearest_.assign (static_cast<std::size_t> (nx_) * ny_, NO_SEED);
  squared_distance_.assign (nearest_.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    // A seed outside the box seeds the nearest cell of the border.
    const int ix = std::clamp (
        static_cast<int> (std::floor ((seeds[i].x() - low.x()) / cell)), 0, nx_ - 1);
    const int iy = std::clamp (
        static_cast<int> (std::floor ((seeds[i].y() - low.y()) / cell)), 0, ny_ - 1);
    offer (static_cast<std::uint32_t> (i), ix, iy);
  }
  for (int iy = 0; iy < ny_; ++iy) {
    for (int ix = 0; ix < nx_; ++ix)
      for (const auto& [dx, dy] : {std::pair{-1, -1}, {0, -1}, {1, -1}, {-1, 0}})
        offer (nearestAt (ix + dx, iy + dy), ix, iy);
    for (int ix = nx_ - 1; ix >= 0; --ix)
      offer (nearestAt (ix + 1, iy), ix, iy);
  }
  for (int iy = ny_ - 1; iy >= 0; --iy) {
    for (int ix = nx_ - 1; ix >= 0; --ix)
      for (const auto& [dx, dy] : {std::pair{1, 1}, {0, 1}, {-1, 1}, {1, 0}})
        offer (nearestAt (ix + dx, iy + dy), ix, iy);
    for (int ix = 0; ix < nx_; ++ix)
      offer (nearestAt (ix - 1, iy), ix, iy);
  }
}

bool
DistanceGrid::cellOf (const Eigen::Vector2d& q, int& ix, int& iy) const
{
  ix = static_cast<int> (std::floor ((q.x() - low_.x()) / cell_));
  iy = static_cast<int> (std::floor ((q.y() - low_.y()) / cell_));
  return ix >= 0 && iy >= 0 && ix < nx_ && iy < ny_;
}

double
DistanceGrid::distance (int ix, int iy) const
{
  return std::sqrt (squared_distance_[static_cast<std::size_t> (iy) * nx_ + ix]);
}

std::uint32_t
DistanceGrid::nearestAt (int ix, int iy) const
{
  return ix < 0 || iy < 0 || ix >= nx_ || iy >= ny_
             ? NO_SEED
             : nearest_[static_cast<std::size_t> (iy) * nx_ + ix];
}

void
DistanceGrid::offer (std::uint32_t seed, int ix, int iy)
{
  if (seed == NO_SEED)
    return;
  const std::size_t cell = static_cast<std::size_t> (iy) * nx_ + ix;
  if (nearest_[cell] == seed)
    return;
  const double squared = (seeds_[seed] - center (ix, iy)).squaredNorm();
  if (squared < squared_distance_[cell]) {
    squared_distance_[cell] = squared;
    nearest_[cell] = seed;
  }
}

} // namespace tda
} // namespace pcl
