#include <pcl/filters/impl/voxel_grid.hpp>
#include <pcl/filters/voxel_grid.h>
#include <pcl/tda/apps/voxel_grid_check.h>
#include <pcl/tda/apps/voxel_grid_filter.h>
#include <pcl/tda/search/canonical_order.h>

#include <numeric>

// Apart from scene_preprocessing.cpp: a tool that only grids its input
// (pcl_tda_barcode) then does not load PCL's segmentation library and the libraries it
// needs, which take most of a process' start-up. PCL's VoxelGrid is compiled here from
// its template (the impl header), as PCL does for custom point types, so that the tools
// do not load libpcl_filters and libpcl_sample_consensus either: with them a process
// takes twice as long to start (0.036 s against 0.019 s for one that loads libpcl_io
// alone; the dynamic loader binds 50k of their symbols).

namespace pcl {
namespace tda {

template <typename PointT>
typename pcl::PointCloud<PointT>::Ptr
voxelGridFilter (const typename pcl::PointCloud<PointT>::ConstPtr& cloud, double leaf)
{
  checkVoxelGridLeaf (*cloud, leaf); // PCL's grid ignores a leaf that is too small
  // The points in canonical order: a cell's centroid sums its points in the order
  // given, and float sums depend on it (shuffled copies of a scan differed in 1e-7).
  pcl::Indices all (cloud->size());
  std::iota (all.begin(), all.end(), 0);
  std::size_t non_finite = 0;
  pcl::IndicesPtr order (new pcl::Indices (canonicalOrder (*cloud, all, non_finite)));
  pcl::VoxelGrid<PointT> grid;
  grid.setInputCloud (cloud);
  grid.setIndices (order);
  const auto size = static_cast<float> (leaf);
  grid.setLeafSize (size, size, size);
  typename pcl::PointCloud<PointT>::Ptr filtered (new pcl::PointCloud<PointT>);
  grid.filter (*filtered);
  return filtered;
}

template pcl::PointCloud<pcl::PointXYZ>::Ptr
voxelGridFilter<pcl::PointXYZ> (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr&,
                                double);
template pcl::PointCloud<pcl::PointXYZRGBL>::Ptr
voxelGridFilter<pcl::PointXYZRGBL> (const pcl::PointCloud<pcl::PointXYZRGBL>::ConstPtr&,
                                    double);

} // namespace tda
} // namespace pcl
