#pragma once

#include <pcl/point_cloud.h>

#include <algorithm>
#include <cstddef>

namespace pcl {
namespace tda {

/** \brief The output of a descriptor of the whole cloud (STPPEstimation,
 * TopologicalCovarianceEstimation) from its computeFeature(): \a output becomes one
 * point, whose first \a size histogram values are zeroed and then filled by
 * \a compute(values) (pcl::Feature::compute() sized it for every indexed point); when
 * \a compute returns false, \a output is left empty and false is returned. */
template <typename PointOutT, typename Compute>
bool
computeWholeCloudSignature (pcl::PointCloud<PointOutT>& output,
                            std::size_t size,
                            Compute compute)
{
  output.width = output.height = 1;
  output.is_dense = true;
  output.resize (1);
  float* values = output[0].histogram;
  std::fill (values, values + size, 0.0f);
  if (compute (values))
    return true;
  output.width = output.height = 0;
  output.clear();
  return false;
}

} // namespace tda
} // namespace pcl
