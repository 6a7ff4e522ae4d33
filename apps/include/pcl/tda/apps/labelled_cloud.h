#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcl {
namespace tda {

/** \brief Reads a labelled PCD file, as pcl_tda_segment, pcl_tda_regions and
 * pcl_tda_holes write them, for the viewer's label modes: every point with its label
 * and, when the file has an rgb or rgba field, its colour (else black). Goes through
 * loadPointCloudFile(), so the file is checked as for every tool.
 * \throws pcl::IOException when the file cannot be read or has no label field */
pcl::PointCloud<pcl::PointXYZRGBL>
loadLabelledCloud (const std::string& path);

} // namespace tda
} // namespace pcl
