#pragma once

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>

#include <Eigen/Geometry>

#include <string>

namespace pcl {
namespace tda {

/** \brief Reads a PCD file for a tool, the one input layer of the tools: refuses
 * what is not a regular file, checks the header and the size of the data
 * (readPCDLayout()) before anything is allocated for the points, requires the fields
 * x, y and z of one value each, reads the points (readPCDData()) and gives x, y and
 * z as 32-bit floats (converting double and integer coordinates). Organized clouds
 * keep their width and height.
 * \throws pcl::IOException naming the file and saying what is wrong with it */
void
loadPointCloudFile (const std::string& path, pcl::PCLPointCloud2& cloud);

/** \brief loadPointCloudFile() converted to points of type \a PointT. */
template <typename PointT>
void
loadPointCloudFile (const std::string& path, pcl::PointCloud<PointT>& cloud)
{
  pcl::PCLPointCloud2 blob;
  loadPointCloudFile (path, blob);
  if (blob.data.empty()) // PCL's conversion reads the first point of any cloud
    cloud.clear();
  else
    pcl::fromPCLPointCloud2 (blob, cloud);
}

/** \brief Saves a cloud as a binary PCD file (writePCDBinary(), no PCL io library),
 * atomically: \a path never holds a partial file.
 * \throws pcl::IOException when the file cannot be written */
void
savePointCloudFile (const std::string& path,
                    const pcl::PCLPointCloud2& cloud,
                    const Eigen::Vector4f& origin,
                    const Eigen::Quaternionf& orientation);

/** \brief savePointCloudFile() of a cloud of points of type \a PointT. */
template <typename PointT>
void
savePointCloudFile (const std::string& path, const pcl::PointCloud<PointT>& cloud)
{
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (cloud, blob);
  savePointCloudFile (path, blob, cloud.sensor_origin_, cloud.sensor_orientation_);
}

} // namespace tda
} // namespace pcl
