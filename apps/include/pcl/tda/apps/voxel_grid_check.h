#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace pcl {
namespace tda {

/** \brief Checks the tools' -leaf option: that pcl::VoxelGrid can apply the leaf
 * \a leaf (> 0) to \a cloud. It keeps every point, saying no more than a warning,
 * when its grid over the bounding box of the finite points has more than 2^31 - 1
 * cells (its cell index is 32-bit). Counts the cells as PCL does, in single
 * precision.
 * \throws pcl::BadArgumentException giving the extent and the number of cells */
void
checkVoxelGridLeaf (const pcl::PointCloud<pcl::PointXYZ>& cloud, double leaf);

/** \brief The tools' -leaf step: voxelGridFilter() once checkVoxelGridLeaf() passed.
 * \throws pcl::BadArgumentException when the leaf is too small */
pcl::PointCloud<pcl::PointXYZ>::Ptr
checkedVoxelGridFilter (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                        double leaf);

} // namespace tda
} // namespace pcl
