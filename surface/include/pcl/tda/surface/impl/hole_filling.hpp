#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/search/kdtree.h>
#include <pcl/tda/common/coordinate_scale.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/features/distance_grid.h>
#include <pcl/tda/features/hole_boundary_estimation.h>
#include <pcl/tda/features/projected_polygon.h>
#include <pcl/tda/surface/hole_filling.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl {
namespace tda {

namespace hole_filling_detail {

/** The input points within this many spacings of a rim point are the hole's
 * surroundings, to which the surface is fitted. */
constexpr double SURROUNDING_SPACINGS = 3.0;
/** A new point keeps at least this many spacings from every surrounding point. */
constexpr double MIN_GAP_SPACINGS = 0.7;

/** Whether \a indices are 0, 1, ..., \a size - 1. */
inline bool
isIdentity (const pcl::Indices& indices, std::size_t size)
{
  if (indices.size() != size)
    return false;
  for (std::size_t i = 0; i < size; ++i)
    if (indices[i] != static_cast<pcl::index_t> (i))
      return false;
  return true;
}

} // namespace hole_filling_detail

template <typename PointT>
bool
HoleFilling<PointT>::reconstruct (pcl::PointCloud<PointT>& output)
{
  output.clear();
  new_point_counts_.clear();
  new_point_sources_.clear();
  if (!initCompute()) {
    PCL_ERROR ("[pcl::tda::%s::reconstruct] No input cloud: call setInputCloud().\n",
               class_name_.c_str());
    return false;
  }
  if (mode_ != Mode::CENTROID && mode_ != Mode::SURFACE) {
    PCL_ERROR ("[pcl::tda::%s::reconstruct] Unknown mode %d: CENTROID or SURFACE.\n",
               class_name_.c_str(),
               static_cast<int> (mode_));
    deinitCompute();
    return false;
  }
  if (!this->fake_indices_ &&
      !hole_filling_detail::isIdentity (*indices_, input_->size())) {
    PCL_ERROR ("[pcl::tda::%s::reconstruct] Indices are not supported: the output is "
               "the whole input cloud and the new points. Fill a cloud of the indexed "
               "points (pcl::copyPointCloud) with the holes found on it.\n",
               class_name_.c_str());
    deinitCompute();
    return false;
  }
  for (const HoleRim& hole : holes_)
    for (const SimplexIndex index : hole.rim)
      if (index >= input_->size() || !pcl::isXYZFinite ((*input_)[index])) {
        PCL_ERROR ("[pcl::tda::%s::reconstruct] A rim point (index %u) is not a finite "
                   "point of the input (%zu points): the holes come from another "
                   "cloud.\n",
                   class_name_.c_str(),
                   index,
                   input_->size());
        deinitCompute();
        return false;
      }
  // The spacing places SURFACE mode's new points; without holes to fill so, it is
  // not needed (a segment too small to measure it is returned as it is).
  const bool fills_surfaces = mode_ == Mode::SURFACE && !holes_.empty();
  double spacing = spacing_;
  if (spacing == 0.0 && fills_surfaces)
    spacing = surfaceSpacing (*input_);
  if ((fills_surfaces || spacing_ != 0.0) &&
      (!(spacing > 0.0) || !std::isfinite (spacing))) {
    PCL_ERROR ("[pcl::tda::%s::reconstruct] The spacing must be positive and finite "
               "(got %g; 0 measures it, which needs %zu distinct finite points).\n",
               class_name_.c_str(),
               spacing,
               SURFACE_SPACING_NEIGHBORS + 1);
    deinitCompute();
    return false;
  }
  if (fills_surfaces && !gridsFitMemory (spacing)) {
    deinitCompute();
    return false;
  }
  output = *input_;
  // One search tree and one set of marks for all holes (SURFACE mode only).
  ScaledSearch search;
  std::vector<std::uint8_t> taken;
  if (fills_surfaces) {
    buildScaledSearch (search);
    taken.assign (input_->size(), 0);
  }
  for (const HoleRim& hole : holes_) {
    const std::size_t before = output.size();
    if (hole.rim.size() >= 3)
      fillHole (hole, spacing, search, taken, output);
    new_point_counts_.push_back (output.size() - before);
  }
  output.width = static_cast<std::uint32_t> (output.size());
  output.height = 1;
  output.is_dense = input_->is_dense;
  deinitCompute();
  return true;
}

template <typename PointT>
void
HoleFilling<PointT>::buildScaledSearch (ScaledSearch& search) const
{
  search.scale = cloudScale (*input_);
  search.tree.setInputCloud (scaledPositions (*input_, search.scale));
}

template <typename PointT>
ProjectedPolygon
HoleFilling<PointT>::rimPolygon (const HoleRim& hole,
                                 std::vector<Point3d>& rim_points,
                                 Eigen::Vector2d& low,
                                 Eigen::Vector2d& high) const
{
  rim_points.clear();
  std::vector<SimplexIndex> cycle;
  for (const SimplexIndex index : hole.rim) {
    const PointT& p = (*input_)[index];
    cycle.push_back (static_cast<SimplexIndex> (rim_points.size()));
    rim_points.push_back ({p.x, p.y, p.z});
  }
  ProjectedPolygon polygon (rim_points, cycle);
  low = high = polygon.project (rim_points.front());
  for (const Point3d& p : rim_points) {
    low = low.cwiseMin (polygon.project (p));
    high = high.cwiseMax (polygon.project (p));
  }
  return polygon;
}

template <typename PointT>
bool
HoleFilling<PointT>::gridsFitMemory (double spacing) const
{
  double largest_grid = 0.0, new_points = 0.0;
  std::vector<Point3d> rim_points;
  Eigen::Vector2d low, high;
  for (const HoleRim& hole : holes_) {
    if (hole.rim.size() < 3)
      continue;
    rimPolygon (hole, rim_points, low, high);
    const Eigen::Vector2d extent = high - low;
    largest_grid =
        std::max (largest_grid, DistanceGrid::bytesFor (extent, spacing / 4.0));
    new_points += (extent.x() / spacing + 1.0) * (extent.y() / spacing + 1.0);
  }
  const double bytes = largest_grid + new_points * sizeof (PointT);
  const std::size_t limit = defaultMemoryLimit();
  if (bytes <= static_cast<double> (limit))
    return true;
  PCL_ERROR ("[pcl::tda::%s::reconstruct] At the spacing %g the holes would take up "
             "to %.0f new points and grids of %s, over the memory limit of %s (half of "
             "the usable memory). Use a larger spacing (0: the cloud's).\n",
             class_name_.c_str(),
             spacing,
             new_points,
             formatBytes (bytes).c_str(),
             formatBytes (static_cast<double> (limit)).c_str());
  return false;
}

template <typename PointT>
void
HoleFilling<PointT>::fillHole (const HoleRim& hole,
                               double spacing,
                               const ScaledSearch& search,
                               std::vector<std::uint8_t>& taken,
                               pcl::PointCloud<PointT>& output)
{
  using namespace hole_filling_detail;
  std::vector<Point3d> rim_points;
  Eigen::Vector2d low, high;
  const ProjectedPolygon polygon = rimPolygon (hole, rim_points, low, high);
  const auto nearestRimPoint = [&] (const Eigen::Vector3d& position) {
    std::size_t nearest = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < rim_points.size(); ++i) {
      const double d =
          (Eigen::Vector3d (rim_points[i][0], rim_points[i][1], rim_points[i][2]) -
           position)
              .squaredNorm();
      if (d < best) {
        best = d;
        nearest = i;
      }
    }
    return static_cast<pcl::index_t> (hole.rim[nearest]);
  };
  const auto append = [&] (const Eigen::Vector3d& position) {
    new_point_sources_.push_back (nearestRimPoint (position));
    PointT point = (*input_)[new_point_sources_.back()];
    point.x = static_cast<float> (position.x());
    point.y = static_cast<float> (position.y());
    point.z = static_cast<float> (position.z());
    output.push_back (point);
  };
  if (mode_ == Mode::CENTROID) {
    append (polygon.centroid());
    return;
  }

  // The surroundings, in the rim's frame: plane coordinates and height.
  pcl::Indices surroundings;
  std::vector<Eigen::Vector2d> around;
  std::vector<double> heights;
  pcl::Indices neighbors;
  std::vector<float> squared_distances;
  for (const SimplexIndex index : hole.rim) {
    search.tree.radiusSearch (static_cast<pcl::index_t> (index),
                              SURROUNDING_SPACINGS * spacing / search.scale,
                              neighbors,
                              squared_distances);
    for (const auto n : neighbors) {
      if (taken[n])
        continue;
      taken[n] = 1;
      surroundings.push_back (n);
      const PointT& p = (*input_)[n];
      const Point3d q{p.x, p.y, p.z};
      around.push_back (polygon.project (q));
      heights.push_back ((Eigen::Vector3d (q[0], q[1], q[2]) - polygon.centroid())
                             .dot (polygon.normal()));
    }
  }
  for (const auto n : surroundings)
    taken[n] = 0; // clean for the next hole
  // The quadratic height field (a plane when there are too few points for it), in
  // plane coordinates of spacings: its terms are of one size in any unit.
  const Eigen::Index terms = around.size() >= 12 ? 6 : 3;
  const auto monomials = [&] (const Eigen::Vector2d& position) {
    const double u = position.x() / spacing, v = position.y() / spacing;
    Eigen::Matrix<double, 6, 1> row;
    row << 1.0, u, v, u * u, u * v, v * v;
    return row;
  };
  Eigen::MatrixXd design (around.size(), terms);
  Eigen::VectorXd values (around.size());
  for (std::size_t i = 0; i < around.size(); ++i) {
    const auto row = static_cast<Eigen::Index> (i);
    design.row (row) = monomials (around[i]).head (terms).transpose();
    values (row) = heights[i];
  }
  const Eigen::VectorXd c = design.colPivHouseholderQr().solve (values);
  const auto height = [&] (const Eigen::Vector2d& position) {
    return monomials (position).head (terms).dot (c);
  };

  // The nodes of a grid of one spacing inside the rim, away from every point.
  const DistanceGrid gaps (low, high, spacing / 4.0, around);
  const auto first = [&] (double coordinate) {
    return static_cast<long> (std::ceil (coordinate / spacing));
  };
  for (long j = first (low.y()); j * spacing <= high.y(); ++j)
    for (long i = first (low.x()); i * spacing <= high.x(); ++i) {
      const Eigen::Vector2d node (i * spacing, j * spacing);
      int gx, gy;
      if (!polygon.contains (node) || !gaps.cellOf (node, gx, gy) ||
          gaps.distance (gx, gy) < MIN_GAP_SPACINGS * spacing)
        continue;
      append (polygon.centroid() + node.x() * polygon.axisU() +
              node.y() * polygon.axisV() + height (node) * polygon.normal());
    }
}

} // namespace tda
} // namespace pcl

#define PCL_INSTANTIATE_HoleFilling(T)                                                 \
  template class PCL_EXPORTS pcl::tda::HoleFilling<T>;
