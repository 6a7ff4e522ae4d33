#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/exceptions.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace pcl {
namespace tda {

/** \brief Checks that pcl::VoxelGrid can apply the leaf \a leaf (> 0) to \a cloud.
 * PCL's grid keeps every point, saying no more than a warning, when its grid over
 * the bounding box of the finite points has more than 2^31 - 1 cells (its cell index
 * is 32-bit). Counts the cells as PCL does, in single precision. voxelGridFilter()
 * calls it before every grid.
 * \throws pcl::BadArgumentException giving the extent and the number of cells */
template <typename PointT>
void
checkVoxelGridLeaf (const pcl::PointCloud<PointT>& cloud, double leaf)
{
  Eigen::Array3f min = Eigen::Array3f::Constant (std::numeric_limits<float>::max());
  Eigen::Array3f max = -min;
  for (const auto& point : cloud)
    if (pcl::isXYZFinite (point)) {
      min = min.min (point.getArray3fMap());
      max = max.max (point.getArray3fMap());
    }
  if (!(min <= max).all())
    return; // no finite point: nothing to grid
  const float inverse_leaf = 1.0f / static_cast<float> (leaf);
  double cells = 1.0;
  for (int axis = 0; axis < 3; ++axis)
    cells *=
        std::floor (static_cast<double> ((max[axis] - min[axis]) * inverse_leaf)) + 1.0;
  if (!(cells <= std::numeric_limits<std::int32_t>::max()))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-leaf " << leaf << " is too small for the points' extent "
                                  << max[0] - min[0] << " x " << max[1] - min[1]
                                  << " x " << max[2] - min[2] << ": " << cells
                                  << " cells, PCL's voxel grid handles at most "
                                  << std::numeric_limits<std::int32_t>::max());
}

} // namespace tda
} // namespace pcl
