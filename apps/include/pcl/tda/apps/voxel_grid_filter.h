#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace pcl {
namespace tda {

/** \brief The centroids of the occupied cells of a voxel grid of leaf \a leaf
 * (pcl::VoxelGrid), the same for any order of the points: the subsampling of the
 * tools' -leaf options. Defined for pcl::PointXYZ and pcl::PointXYZRGBL. */
template <typename PointT>
typename pcl::PointCloud<PointT>::Ptr
voxelGridFilter (const typename pcl::PointCloud<PointT>::ConstPtr& cloud, double leaf);

} // namespace tda
} // namespace pcl
