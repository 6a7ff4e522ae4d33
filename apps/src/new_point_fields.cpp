#include <pcl/common/io.h>
#include <pcl/tda/apps/new_point_fields.h>
#include <pcl/exceptions.h>

#include <cstring>

namespace pcl {
namespace tda {

pcl::PCLPointCloud2
withNewPoints (const pcl::PCLPointCloud2& input,
               const pcl::PointCloud<pcl::PointXYZ>& positions,
               const pcl::Indices& sources)
{
  const std::size_t old_points = std::size_t{input.width} * input.height;
  if (positions.size() != old_points + sources.size())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "withNewPoints: " << positions.size() << " positions for "
                                           << old_points << " points and "
                                           << sources.size() << " new ones");
  int offsets[3];
  const char* names[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    const int field = pcl::getFieldIndex (input, names[axis]);
    if (field < 0 || input.fields[field].datatype != pcl::PCLPointField::FLOAT32)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "withNewPoints: the input has no float field "
                               << names[axis]);
    offsets[axis] = static_cast<int> (input.fields[field].offset);
  }
  pcl::PCLPointCloud2 output = input; // then one row, with room for the new points
  output.height = 1;
  output.width = static_cast<pcl::uindex_t> (positions.size());
  output.row_step = output.point_step * output.width;
  output.data.resize (std::size_t{output.row_step});
  for (std::size_t k = 0; k < sources.size(); ++k) {
    const auto source = static_cast<std::size_t> (sources[k]);
    if (source >= old_points)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "withNewPoints: source " << source << " of " << old_points
                                                    << " points");
    std::uint8_t* point = &output.data[(old_points + k) * output.point_step];
    std::memcpy (point, &input.data[source * input.point_step], input.point_step);
    const pcl::PointXYZ& position = positions[old_points + k];
    const float xyz[3] = {position.x, position.y, position.z};
    for (int axis = 0; axis < 3; ++axis)
      std::memcpy (point + offsets[axis], &xyz[axis], sizeof (float));
  }
  return output;
}

} // namespace tda
} // namespace pcl
