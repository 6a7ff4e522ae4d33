#include <pcl/common/io.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/labelled_cloud.h>
#include <pcl/exceptions.h>

namespace pcl {
namespace tda {

pcl::PointCloud<pcl::PointXYZRGBL>
loadLabelledCloud (const std::string& path)
{
  pcl::PCLPointCloud2 blob;
  loadPointCloudFile (path, blob);
  if (pcl::getFieldIndex (blob, "label") < 0)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         path << " has no label field: -clusters, -regions and -holes "
                                 "show the labelled clouds that pcl_tda_segment, "
                                 "pcl_tda_regions and pcl_tda_holes write (-barcode "
                                 "shows any cloud).");
  pcl::PointCloud<pcl::PointXYZRGBL> cloud;
  if (blob.data.empty()) // PCL's conversion reads the first point of any cloud
    return cloud;
  if (pcl::getFieldIndex (blob, "rgb") >= 0 || pcl::getFieldIndex (blob, "rgba") >= 0)
    pcl::fromPCLPointCloud2 (blob, cloud);
  else {
    // Converted without the colour fields, which PCL would warn are missing.
    pcl::PointCloud<pcl::PointXYZL> plain;
    pcl::fromPCLPointCloud2 (blob, plain);
    pcl::copyPointCloud (plain, cloud);
  }
  return cloud;
}

} // namespace tda
} // namespace pcl
