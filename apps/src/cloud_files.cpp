#include <pcl/tda/apps/cloud_files.h>
#include <pcl/exceptions.h>

#include <fstream>

namespace pcl {
namespace tda {

void
loadPointCloudFile (const std::string& path, pcl::PCLPointCloud2& cloud)
{
  if (!std::ifstream (path).good())
    PCL_THROW_EXCEPTION (pcl::IOException, "cannot open " << path);
  pcl::PCDReader reader;
  pcl::PCLPointCloud2 header;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0, data_type = 0;
  unsigned int data_index = 0;
  if (reader.readHeader (
          path, header, origin, orientation, version, data_type, data_index) < 0 ||
      header.fields.empty())
    PCL_THROW_EXCEPTION (pcl::IOException, path << " is not a PCD file");
  for (const char* field : {"x", "y", "z"})
    if (pcl::getFieldIndex (header, field) < 0)
      PCL_THROW_EXCEPTION (pcl::IOException, path << " has no '" << field << "' field");
  if (header.width * header.height == 0) {
    cloud = header;
    return;
  }
  if (reader.read (path, cloud) < 0)
    PCL_THROW_EXCEPTION (pcl::IOException, "cannot read the points of " << path);
}

} // namespace tda
} // namespace pcl
