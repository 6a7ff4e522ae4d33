#include <pcl/tda/common/plane_fit.h>
#include <pcl/tda/features/projected_polygon.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

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
  const std::size_t num_rows = std::max<std::size_t> (1, corners_.size() / 2);
  row_low_ = low;
  row_height_ = high > low ? (high - low) / static_cast<double> (num_rows) : 1.0;
  rows_.resize (num_rows);
  for (std::size_t i = 0, j = corners_.size() - 1; i < corners_.size(); j = i++) {
    const std::size_t a = rowOf (corners_[i].y()), b = rowOf (corners_[j].y());
    for (std::size_t row = std::min (a, b); row <= std::max (a, b); ++row)
      rows_[row].push_back (static_cast<std::uint32_t> (i));
  }
}

std::size_t
ProjectedPolygon::rowOf (double y) const
{
  const double row = std::floor ((y - row_low_) / row_height_);
  return static_cast<std::size_t> (
      std::clamp (row, 0.0, static_cast<double> (rows_.size() - 1)));
}

Eigen::Vector2d
ProjectedPolygon::project (const Point3d& p) const
{
  const Eigen::Vector3d d = Eigen::Vector3d (p[0], p[1], p[2]) - centroid_;
  return {d.dot (axis_u_), d.dot (axis_v_)};
}

bool
ProjectedPolygon::contains (const Eigen::Vector2d& q) const
{
  bool inside = false;
  for (const std::uint32_t i : rows_[rowOf (q.y())]) {
    const Eigen::Vector2d& a = corners_[i];
    const Eigen::Vector2d& b = corners_[i == 0 ? corners_.size() - 1 : i - 1];
    // The edge straddles the horizontal line through q (half-open, so that a vertex
    // on the line counts once) and crosses it right of q.
    if ((a.y() > q.y()) != (b.y() > q.y()) &&
        q.x() < a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
  }
  return inside;
}

std::vector<double>
ProjectedPolygon::crossings (double y) const
{
  std::vector<double> xs;
  for (const std::uint32_t i : rows_[rowOf (y)]) {
    const Eigen::Vector2d& a = corners_[i];
    const Eigen::Vector2d& b = corners_[i == 0 ? corners_.size() - 1 : i - 1];
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
