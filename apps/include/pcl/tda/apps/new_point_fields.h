#pragma once

#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

namespace pcl {
namespace tda {

/** \brief The points of \a input followed by new points, in one row (width the total,
 * height 1): new point k at the position of point input.width * input.height + k of
 * \a positions, with every other field (colour, normal, label, ...) of the input
 * point sources[k]. Carries the fields of any PCD file to the points a filter adds
 * (HoleFilling::getNewPointSources()) when it ran on x, y and z only. The x, y and z
 * of \a input must be 32-bit floats, as loadPointCloudFile() gives them.
 * \throws pcl::BadArgumentException when the sizes or the fields do not fit */
pcl::PCLPointCloud2
withNewPoints (const pcl::PCLPointCloud2& input,
               const pcl::PointCloud<pcl::PointXYZ>& positions,
               const pcl::Indices& sources);

} // namespace tda
} // namespace pcl
