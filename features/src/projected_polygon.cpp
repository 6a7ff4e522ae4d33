#include <pcl/tda/common/plane_fit.h>
#include <pcl/tda/features/projected_polygon.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>

namespace pcl {
namespace tda {

ProjectedPolygon::ProjectedPolygon (const std::vector<Point3d>& points,
                                    const std::vector<SimplexIndex>& cycle)
{
  PlaneFit plane (points[cycle.front()]);
  for (const SimplexIndex v : cycle)
    plane.add (points[v]);
  centroid_ = plane.centroid();
  normal_ = plane.normal().cast<double>();
  // Any unit vector across the normal, then the third axis.
  const Eigen::Vector3d helper = std::abs (normal_.x()) < 0.9
                                     ? Eigen::Vector3d::UnitX()
                                     : Eigen::Vector3d::UnitY();
  axis_u_ = normal_.cross (helper).normalized();
  axis_v_ = normal_.cross (axis_u_);
  corners_.reserve (cycle.size());
  for (const SimplexIndex v : cycle)
    corners_.push_back (project (points[v]));
  double low = corners_.front().y(), high = low;
  for (const Eigen::Vector2d& c : corners_) {
    low = std::min (low, c.y());
    high = std::max (high, c.y());
  }
  // About two edges per row on a round polygon.
  num_rows_ = std::max<std::size_t> (1, corners_.size() / 2);
  row_low_ = low;
  row_height_ = high > low ? (high - low) / static_cast<double> (num_rows_) : 1.0;
  // Each edge in every row its span in y meets: counted, then placed.
  const auto forEachRow = [&] (auto visit) {
    for (std::size_t i = 0, j = corners_.size() - 1; i < corners_.size(); j = i++) {
      const std::size_t a = rowOf (corners_[i].y()), b = rowOf (corners_[j].y());
      for (std::size_t row = std::min (a, b); row <= std::max (a, b); ++row)
        visit (row, i, j);
    }
  };
  row_offsets_.assign (num_rows_ + 1, 0);
  forEachRow (
      [&] (std::size_t row, std::size_t, std::size_t) { ++row_offsets_[row + 1]; });
  std::partial_sum (row_offsets_.begin(), row_offsets_.end(), row_offsets_.begin());
  row_edges_.resize (row_offsets_.back());
  std::vector<std::size_t> next (row_offsets_.begin(), row_offsets_.end() - 1);
  forEachRow ([&] (std::size_t row, std::size_t i, std::size_t j) {
    row_edges_[next[row]++] = {corners_[i], corners_[j]};
  });
}

std::vector<double>
ProjectedPolygon::crossings (double y) const
{
  std::vector<double> xs;
  const std::size_t row = rowOf (y);
  for (std::size_t k = row_offsets_[row]; k < row_offsets_[row + 1]; ++k) {
    const Eigen::Vector2d& a = row_edges_[k].a;
    const Eigen::Vector2d& b = row_edges_[k].b;
    if ((a.y() > y) != (b.y() > y))
      xs.push_back (a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
  }
  std::sort (xs.begin(), xs.end());
  return xs;
}

double
ProjectedPolygon::area() const
{
  double twice_area = 0.0;
  for (std::size_t i = 0, j = corners_.size() - 1; i < corners_.size(); j = i++)
    twice_area += corners_[j].x() * corners_[i].y() - corners_[i].x() * corners_[j].y();
  return std::abs (twice_area) / 2.0;
}

} // namespace tda
} // namespace pcl
