#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/search/kdtree.h>
#include <pcl/point_cloud.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The spacing of a cloud's points: the \a quantile (in (0, 1]) of the
 * distances from each point to its \a k -th nearest other point, over the finite
 * points (at most \a max_samples of them, evenly spread in (x, y, z) order, so that
 * the cost is bounded on large clouds and the value does not depend on the input
 * order). Points at the same position are skipped. 0
 * when there are fewer than k + 1 distinct finite points.
 *
 * With k = 1 and the median it is the typical sampling distance. A larger k follows
 * sampling that is denser along one direction than across it (the scan lines of a
 * laser or a stereo camera), a higher quantile the sparser parts of a cloud. */
template <typename PointT>
double
pointSpacing (const pcl::PointCloud<PointT>& cloud,
              double quantile = 0.5,
              std::size_t k = 1,
              std::size_t max_samples = 2000)
{
  typename pcl::PointCloud<PointT>::Ptr finite (new pcl::PointCloud<PointT>);
  for (const PointT& point : cloud)
    if (pcl::isXYZFinite (point))
      finite->push_back (point);
  // The sample is taken in (x, y, z) order, so that the spacing does not depend on
  // the input order.
  std::sort (finite->begin(), finite->end(), [] (const PointT& a, const PointT& b) {
    return std::tie (a.x, a.y, a.z) < std::tie (b.x, b.y, b.z);
  });
  if (finite->size() < 2 || k == 0)
    return 0.0;
  pcl::search::KdTree<PointT> tree;
  tree.setInputCloud (finite);
  const std::size_t stride = std::max<std::size_t> (1, finite->size() / max_samples);
  std::vector<double> spacings;
  pcl::Indices neighbors;
  std::vector<float> squared_distances;
  for (std::size_t i = 0; i < finite->size(); i += stride) {
    // Enough neighbours to step over a few duplicates of the point.
    const auto wanted = static_cast<int> (std::min (k + 8, finite->size()));
    tree.nearestKSearch ((*finite)[i], wanted, neighbors, squared_distances);
    const auto first = std::find_if (squared_distances.begin(),
                                     squared_distances.end(),
                                     [] (float d) { return d > 0.0f; });
    if (static_cast<std::size_t> (squared_distances.end() - first) >= k)
      spacings.push_back (std::sqrt (static_cast<double> (*(first + (k - 1)))));
  }
  if (spacings.empty())
    return 0.0;
  const auto rank = static_cast<std::size_t> (std::max (
      std::ceil (quantile * static_cast<double> (spacings.size())) - 1.0, 0.0));
  std::nth_element (spacings.begin(),
                    spacings.begin() + std::min (rank, spacings.size() - 1),
                    spacings.end());
  return spacings[std::min (rank, spacings.size() - 1)];
}

/** \brief How many nearest neighbours measure a surface's spacing. */
constexpr std::size_t SURFACE_SPACING_NEIGHBORS = 6;

/** \brief The sampling spacing of a surface: the square root of the area per point,
 * estimated from the median distance d_k to the k-th nearest point (k =
 * SURFACE_SPACING_NEIGHBORS) as d_k sqrt(pi / k), since a disk of radius d_k holds
 * about k points. Unlike the nearest-neighbour distance it does not depend on how
 * regular the sampling is (a jittered grid and a random sample of the same density
 * give the same value), nor on scan lines that are denser along than across. 0 when
 * the cloud has fewer than k + 1 distinct finite points. At most \a max_samples
 * points are measured (see pointSpacing()). */
template <typename PointT>
double
surfaceSpacing (const pcl::PointCloud<PointT>& cloud, std::size_t max_samples = 2000)
{
  return pointSpacing (cloud, 0.5, SURFACE_SPACING_NEIGHBORS, max_samples) *
         std::sqrt (M_PI / static_cast<double> (SURFACE_SPACING_NEIGHBORS));
}

} // namespace tda
} // namespace pcl
