#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/pcd_data.h>
#include <pcl/tda/apps/pcd_file_check.h>
#include <pcl/tda/common/atomic_file.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/exceptions.h>

#include <sys/stat.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>

namespace pcl {
namespace tda {

namespace {

/** The value of type \a datatype at \a bytes. */
double
fieldValue (const std::uint8_t* bytes, std::uint8_t datatype)
{
  const auto read = [bytes] (auto value) {
    std::memcpy (&value, bytes, sizeof (value));
    return static_cast<double> (value);
  };
  switch (datatype) {
  case pcl::PCLPointField::BOOL:
    return bytes[0] != 0;
  case pcl::PCLPointField::INT8:
    return read (std::int8_t{});
  case pcl::PCLPointField::UINT8:
    return read (std::uint8_t{});
  case pcl::PCLPointField::INT16:
    return read (std::int16_t{});
  case pcl::PCLPointField::UINT16:
    return read (std::uint16_t{});
  case pcl::PCLPointField::INT32:
    return read (std::int32_t{});
  case pcl::PCLPointField::UINT32:
    return read (std::uint32_t{});
  case pcl::PCLPointField::INT64:
    return read (std::int64_t{});
  case pcl::PCLPointField::UINT64:
    return read (std::uint64_t{});
  case pcl::PCLPointField::FLOAT32:
    return read (float{});
  default:
    return read (double{});
  }
}

/** Makes x, y and z 32-bit floats, the type PCL's point types need: puts new x, y
 * and z fields before each point and leaves the old bytes as unnamed padding.
 * Refuses (naming the file \a path) coordinates beyond the range of a float. */
void
makeCoordinatesFloat (pcl::PCLPointCloud2& cloud, const std::string& path)
{
  const std::array<int, 3> xyz = {pcl::getFieldIndex (cloud, "x"),
                                  pcl::getFieldIndex (cloud, "y"),
                                  pcl::getFieldIndex (cloud, "z")};
  bool all_float = true;
  for (const int field : xyz)
    all_float =
        all_float && cloud.fields[field].datatype == pcl::PCLPointField::FLOAT32;
  if (all_float)
    return;
  constexpr std::uint32_t XYZ_BYTES = 3 * sizeof (float);
  pcl::PCLPointCloud2 converted;
  converted.header = cloud.header;
  converted.width = cloud.width;
  converted.height = cloud.height;
  converted.is_bigendian = cloud.is_bigendian;
  converted.is_dense = cloud.is_dense;
  converted.point_step = cloud.point_step + XYZ_BYTES;
  converted.row_step = converted.point_step * converted.width;
  for (const char* name : {"x", "y", "z"}) {
    pcl::PCLPointField field;
    field.name = name;
    field.offset =
        static_cast<pcl::uindex_t> (converted.fields.size() * sizeof (float));
    field.datatype = pcl::PCLPointField::FLOAT32;
    field.count = 1;
    converted.fields.push_back (field);
  }
  for (std::size_t f = 0; f < cloud.fields.size(); ++f)
    if (f != static_cast<std::size_t> (xyz[0]) &&
        f != static_cast<std::size_t> (xyz[1]) &&
        f != static_cast<std::size_t> (xyz[2])) {
      converted.fields.push_back (cloud.fields[f]);
      converted.fields.back().offset += XYZ_BYTES;
    }
  const std::size_t points = std::size_t{cloud.width} * cloud.height;
  converted.data.resize (points * converted.point_step);
  for (std::size_t p = 0; p < points; ++p) {
    const std::uint8_t* in = &cloud.data[p * cloud.point_step];
    std::uint8_t* out = &converted.data[p * converted.point_step];
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const auto& field = cloud.fields[xyz[axis]];
      const double value = fieldValue (in + field.offset, field.datatype);
      if (std::isfinite (value) && std::abs (value) > std::numeric_limits<float>::max())
        PCL_THROW_EXCEPTION (pcl::IOException,
                             path << ": point " << p << " has " << field.name << " = "
                                  << value << ", beyond the range of a float");
      const auto single = static_cast<float> (value);
      std::memcpy (out + axis * sizeof (float), &single, sizeof (float));
    }
    std::memcpy (out + XYZ_BYTES, in, cloud.point_step);
  }
  cloud = std::move (converted);
}

/** Opens the PCD file at \a path into \a file and checks its header and the size of
 * its data (readPCDLayout()).
 * \throws pcl::IOException naming the file and saying what is wrong with it */
PCDLayout
openPCDFile (const std::string& path, std::ifstream& file)
{
  struct stat status;
  if (::stat (path.c_str(), &status) != 0)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot open " << path << ": " << std::strerror (errno));
  if (S_ISDIR (status.st_mode))
    PCL_THROW_EXCEPTION (pcl::IOException, path << " is a directory, not a PCD file");
  if (!S_ISREG (status.st_mode))
    PCL_THROW_EXCEPTION (pcl::IOException,
                         path << " is not a regular file (a device, pipe or socket)");
  file.open (path, std::ios::binary);
  if (!file)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "cannot open " << path << ": " << std::strerror (errno));
  try {
    return readPCDLayout (file, static_cast<std::uint64_t> (status.st_size));
  }
  catch (const pcl::IOException& error) {
    PCL_THROW_EXCEPTION (pcl::IOException,
                         path << " is not a valid PCD file: " << errorMessage (error));
  }
}

} // namespace

void
loadPointCloudFile (const std::string& path, pcl::PCLPointCloud2& cloud)
{
  std::ifstream file;
  const PCDLayout layout = openPCDFile (path, file);
  for (const char* name : {"x", "y", "z"}) {
    const int field = pcl::getFieldIndex (layout.header, name);
    if (field < 0)
      PCL_THROW_EXCEPTION (pcl::IOException, path << " has no '" << name << "' field");
    if (layout.header.fields[field].count != 1)
      PCL_THROW_EXCEPTION (pcl::IOException,
                           path << ": field '" << name << "' has "
                                << layout.header.fields[field].count
                                << " values per point (COUNT), not 1");
  }
  if (layout.header.width * layout.header.height == 0) {
    cloud = layout.header;
    return;
  }
  try {
    readPCDData (file, layout, cloud);
  }
  catch (const pcl::IOException& error) {
    PCL_THROW_EXCEPTION (pcl::IOException,
                         path << " is not a valid PCD file: " << errorMessage (error));
  }
  makeCoordinatesFloat (cloud, path);
}

void
savePointCloudFile (const std::string& path,
                    const pcl::PCLPointCloud2& cloud,
                    const Eigen::Vector4f& origin,
                    const Eigen::Quaternionf& orientation)
{
  replaceFileAtomically (path, [&] (const std::string& temporary) {
    std::ofstream out (temporary, std::ios::binary);
    return out && writePCDBinary (out, cloud, origin, orientation);
  });
}

} // namespace tda
} // namespace pcl
