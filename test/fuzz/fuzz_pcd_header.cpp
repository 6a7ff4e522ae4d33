// libFuzzer target of the PCD header check and data reader: on any bytes,
// readPCDLayout() returns a layout whose points fit in the bytes, or throws
// pcl::IOException, and readPCDData() then reads exactly those points or throws; they
// never crash, hang or allocate for points the file does not hold.

#include <pcl/tda/apps/pcd_data.h>
#include <pcl/tda/apps/pcd_file_check.h>
#include <pcl/exceptions.h>

#include <cstdint>
#include <sstream>
#include <string>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  std::istringstream file (std::string (reinterpret_cast<const char*> (data), size));
  try {
    const pcl::tda::PCDLayout layout = pcl::tda::readPCDLayout (file, size);
    const auto& header = layout.header;
    const std::uint64_t points = std::uint64_t{header.width} * header.height;
    const std::uint64_t bytes = points * header.point_step;
    std::uint64_t values = 0;
    for (const auto& field : header.fields)
      values += field.count;
    const bool binary_fits =
        layout.data != pcl::tda::PCDData::BINARY || layout.data_offset + bytes <= size;
    const bool ascii_fits = layout.data != pcl::tda::PCDData::ASCII ||
                            2 * points * values <= size - layout.data_offset + 1;
    if (points > 0 &&
        (layout.data_offset > size || bytes > pcl::tda::MAX_PCD_DATA_BYTES ||
         !binary_fits || !ascii_fits))
      __builtin_trap();
    pcl::PCLPointCloud2 cloud;
    pcl::tda::readPCDData (file, layout, cloud);
    if (cloud.data.size() != bytes)
      __builtin_trap();
  }
  catch (const pcl::IOException&) {
  }
  return 0;
}
