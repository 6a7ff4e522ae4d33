#pragma once

#include <pcl/tda/apps/voxel_grid_filter.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>

namespace pcl {
namespace tda {

/** \brief The preprocessing of a tabletop frame before object segmentation (thesis
 * Sec 4.4.1); each step is off when its value is 0. */
struct ScenePreprocessing {
  /** \brief Keep the points of depth z <= max_depth (sensor frame), 0: all. */
  double max_depth = 0.0;
  /** \brief Remove the dominant plane (the table) found by PCL's RANSAC. */
  bool remove_plane = true;
  /** \brief Largest distance of a point to the plane for it to be removed, in
   * metres. */
  double plane_distance = 0.01;
  /** \brief Leaf of the voxel grid applied last, in metres; 0: none. */
  double leaf = 0.0;
};

/** \brief What preprocessScene() removed, step by step. */
struct PreprocessingCounts {
  std::size_t non_finite = 0;
  std::size_t beyond_depth = 0;
  std::size_t plane = 0;
  std::size_t after_voxel_grid = 0;
};

/** \brief Drops the non-finite points (organized frames have NaNs), then the points
 * beyond max_depth, then the dominant plane (pcl::SACSegmentation, RANSAC plane
 * model, fixed seed), then applies a voxel grid. Defined for pcl::PointXYZ and
 * pcl::PointXYZRGBL (whose labels survive all steps but the voxel grid).
 * \throws pcl::BadArgumentException on a negative value, when no plane is found, or
 * when no point is left after a step */
template <typename PointT>
typename pcl::PointCloud<PointT>::Ptr
preprocessScene (const pcl::PointCloud<PointT>& cloud,
                 const ScenePreprocessing& options,
                 PreprocessingCounts* counts = nullptr);

} // namespace tda
} // namespace pcl
