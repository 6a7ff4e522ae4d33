#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/point_cloud.h>
#include <pcl/types.h>

#include <algorithm>
#include <cstddef>
#include <tuple>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The canonical vertex order of the complex builders (thesis Alg 3.2): the
 * finite points among \a indices, sorted by (x, y, z) and then by index, so that a
 * complex does not depend on the order of its input.
 * \param[in] cloud the input cloud
 * \param[in] indices the points to order
 * \param[out] skipped number of non-finite points left out
 * \return the input indices of the points in canonical order
 */
template <typename PointT>
pcl::Indices
canonicalOrder (const pcl::PointCloud<PointT>& cloud,
                const pcl::Indices& indices,
                std::size_t& skipped)
{
  pcl::Indices order;
  order.reserve (indices.size());
  for (const auto index : indices)
    if (pcl::isXYZFinite (cloud[index]))
      order.push_back (index);
  skipped = indices.size() - order.size();
  std::sort (order.begin(), order.end(), [&cloud] (pcl::index_t a, pcl::index_t b) {
    const PointT& p = cloud[a];
    const PointT& q = cloud[b];
    return std::tie (p.x, p.y, p.z, a) < std::tie (q.x, q.y, q.z, b);
  });
  return order;
}

} // namespace tda
} // namespace pcl
