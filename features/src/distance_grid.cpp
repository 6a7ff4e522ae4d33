#include <pcl/tda/features/distance_grid.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl {
namespace tda {

DistanceGrid::DistanceGrid (const Eigen::Vector2d& low,
                            const Eigen::Vector2d& high,
                            double cell,
                            const std::vector<Eigen::Vector2d>& seeds)
: low_ (low), cell_ (cell), seeds_ (seeds)
{
  nx_ = static_cast<int> ((high.x() - low.x()) / cell) + 1;
  ny_ = static_cast<int> ((high.y() - low.y()) / cell) + 1;
  stride_ = static_cast<std::size_t> (nx_) + 2;
  nearest_.assign (stride_ * (static_cast<std::size_t> (ny_) + 2), NO_SEED);
  squared_distance_.assign (nearest_.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    // A seed outside the box seeds the nearest cell of the border.
    const int ix = std::clamp (
        static_cast<int> (std::floor ((seeds[i].x() - low.x()) / cell)), 0, nx_ - 1);
    const int iy = std::clamp (
        static_cast<int> (std::floor ((seeds[i].y() - low.y()) / cell)), 0, ny_ - 1);
    offer (static_cast<std::uint32_t> (i), index (ix, iy), center (ix, iy));
  }
  propagate();
}

void
DistanceGrid::propagate()
{
  // The cells' centres, as center() gives them.
  std::vector<double> xs (nx_), ys (ny_);
  for (int ix = 0; ix < nx_; ++ix)
    xs[ix] = center (ix, 0).x();
  for (int iy = 0; iy < ny_; ++iy)
    ys[iy] = center (0, iy).y();
  // Each cell is offered its neighbours' nearest seeds: those of the row above and
  // the cell before it forwards, then backwards. The border around the grid has
  // no seed.
  const std::size_t up = stride_;
  for (int iy = 0; iy < ny_; ++iy) {
    for (int ix = 0; ix < nx_; ++ix) {
      const std::size_t c = index (ix, iy);
      const Eigen::Vector2d at (xs[ix], ys[iy]);
      for (const std::size_t from : {c - up - 1, c - up, c - up + 1, c - 1})
        offer (nearest_[from], c, at);
    }
    for (int ix = nx_ - 1; ix >= 0; --ix) {
      const std::size_t c = index (ix, iy);
      offer (nearest_[c + 1], c, Eigen::Vector2d (xs[ix], ys[iy]));
    }
  }
  for (int iy = ny_ - 1; iy >= 0; --iy) {
    for (int ix = nx_ - 1; ix >= 0; --ix) {
      const std::size_t c = index (ix, iy);
      const Eigen::Vector2d at (xs[ix], ys[iy]);
      for (const std::size_t from : {c + up + 1, c + up, c + up - 1, c + 1})
        offer (nearest_[from], c, at);
    }
    for (int ix = 0; ix < nx_; ++ix) {
      const std::size_t c = index (ix, iy);
      offer (nearest_[c - 1], c, Eigen::Vector2d (xs[ix], ys[iy]));
    }
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
  return std::sqrt (squared_distance_[index (ix, iy)]);
}

} // namespace tda
} // namespace pcl
