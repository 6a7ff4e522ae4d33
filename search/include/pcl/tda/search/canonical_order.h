#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/point_cloud.h>
#include <pcl/types.h>

#include <cstddef>
#include <vector>

namespace pcl {
namespace tda {

/** \brief A point as canonicalOrder() sorts it: its coordinates and its index. */
struct CanonicalPoint {
  float x, y, z;
  pcl::index_t index;
};

/** \brief Sorts \a points by (x, y, z), then by index, in linear time (a radix
 * sort: a comparison sort took a tenth of the Vietoris-Rips build of a 100k-point
 * scan). 0 and -0 are equal. The result does not depend on \a threads (OpenMP threads,
 * 0: OpenMP's default). */
void
sortCanonically (std::vector<CanonicalPoint>& points, unsigned int threads = 0);

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
  std::vector<CanonicalPoint> points;
  points.reserve (indices.size());
  for (const auto index : indices)
    if (pcl::isXYZFinite (cloud[index]))
      points.push_back ({cloud[index].x, cloud[index].y, cloud[index].z, index});
  skipped = indices.size() - points.size();
  sortCanonically (points);
  pcl::Indices order (points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    order[i] = points[i].index;
  return order;
}

} // namespace tda
} // namespace pcl
