// PCL's plane segmentation and index extraction compiled from their template
// headers, so that the tools do not load libpcl_segmentation and libpcl_features.
#include <pcl/common/point_tests.h>
#include <pcl/filters/impl/extract_indices.hpp>
#include <pcl/filters/impl/filter_indices.hpp>
#include <pcl/segmentation/impl/sac_segmentation.hpp>
#include <pcl/tda/apps/scene_preprocessing.h>
#include <pcl/tda/common/coordinate_scale.h>
#include <pcl/tda/search/canonical_order.h>
#include <pcl/exceptions.h>

#include <cmath>
#include <numeric>

namespace pcl {
namespace tda {

namespace {

template <typename PointT>
void
requirePoints (const pcl::PointCloud<PointT>& cloud, const char* after)
{
  if (cloud.empty())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException, "no point is left " << after);
}

} // namespace

template <typename PointT>
typename pcl::PointCloud<PointT>::Ptr
preprocessScene (const pcl::PointCloud<PointT>& cloud,
                 const ScenePreprocessing& options,
                 PreprocessingCounts* counts)
{
  if (!(options.max_depth >= 0.0) || !(options.leaf >= 0.0) ||
      !(options.plane_distance > 0.0))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "the depth cut-off and the leaf must be >= 0 and the plane "
                         "distance > 0");
  using Cloud = pcl::PointCloud<PointT>;
  PreprocessingCounts removed;
  typename Cloud::Ptr result (new Cloud);
  result->header = cloud.header;
  result->sensor_origin_ = cloud.sensor_origin_;
  result->sensor_orientation_ = cloud.sensor_orientation_;
  // In canonical order (sorted by x, y, z), so that RANSAC (PCL seeds it with a
  // fixed seed) samples the
  // same points, and the whole preprocessing gives the same points, for any order of
  // the input.
  pcl::Indices all (cloud.size());
  std::iota (all.begin(), all.end(), 0);
  for (const auto index : canonicalOrder (cloud, all, removed.non_finite)) {
    const PointT& point = cloud[index];
    if (options.max_depth > 0.0 && point.z > options.max_depth)
      ++removed.beyond_depth;
    else
      result->push_back (point);
  }
  requirePoints (*result,
                 options.max_depth > 0.0 ? "within the depth cut-off"
                                         : "(all are NaN or infinite)");

  if (options.remove_plane) {
    // RANSAC on the points scaled by a power of two to unit size (exact in float):
    // PCL's test of a sample for collinear points has an absolute threshold, which
    // took every sample of a scene a few centimetres wide for collinear.
    const double scale = cloudScale (*result);
    typename Cloud::Ptr scaled (new Cloud (*result));
    for (PointT& point : *scaled)
      point.getVector3fMap() /= static_cast<float> (scale);
    pcl::SACSegmentation<PointT> segmentation;
    segmentation.setOptimizeCoefficients (true);
    segmentation.setModelType (pcl::SACMODEL_PLANE);
    segmentation.setMethodType (pcl::SAC_RANSAC);
    segmentation.setMaxIterations (200);
    segmentation.setDistanceThreshold (options.plane_distance / scale);
    segmentation.setInputCloud (scaled);
    pcl::PointIndices::Ptr inliers (new pcl::PointIndices);
    pcl::ModelCoefficients coefficients;
    segmentation.segment (*inliers, coefficients);
    if (inliers->indices.empty())
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "no plane found among the " << result->size()
                                                       << " points (use -plane 0)");
    removed.plane = inliers->indices.size();
    pcl::ExtractIndices<PointT> extract;
    extract.setInputCloud (result);
    extract.setIndices (inliers);
    extract.setNegative (true);
    typename Cloud::Ptr rest (new Cloud);
    extract.filter (*rest);
    result = rest;
    requirePoints (*result, "after removing the plane");
  }

  if (options.leaf > 0.0) {
    result = voxelGridFilter<PointT> (result, options.leaf);
    requirePoints (*result, "after the voxel grid (is the leaf too small?)");
  }
  removed.after_voxel_grid = result->size();
  if (counts)
    *counts = removed;
  return result;
}

template pcl::PointCloud<pcl::PointXYZ>::Ptr
preprocessScene (const pcl::PointCloud<pcl::PointXYZ>&,
                 const ScenePreprocessing&,
                 PreprocessingCounts*);
template pcl::PointCloud<pcl::PointXYZRGBL>::Ptr
preprocessScene (const pcl::PointCloud<pcl::PointXYZRGBL>&,
                 const ScenePreprocessing&,
                 PreprocessingCounts*);

} // namespace tda
} // namespace pcl
