#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/point_cloud.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief How many points pointSpacing() and surfaceSpacing() measure at most by
 * default. */
constexpr std::size_t DEFAULT_SPACING_SAMPLES = 2000;

/** \brief The spacing of points given as x, y, z triples (\a xyz, all finite) in
 * (x, y, z) order: see pointSpacing(). */
double
sortedPointSpacing (std::vector<float> xyz,
                    double quantile,
                    std::size_t k,
                    std::size_t max_samples,
                    unsigned int threads);

/** \brief The spacing of a cloud's points: the \a quantile (in (0, 1]) of the
 * distances from each point to its \a k -th nearest other point, over the finite
 * points (at most \a max_samples of them, evenly spread in (x, y, z) order, so that
 * the cost is bounded on large clouds and the value does not depend on the input
 * order), searched with \a threads OpenMP threads (0: OpenMP's default). Points at
 * the same position are skipped. 0 when there are fewer than k + 1 distinct finite
 * points.
 *
 * With k = 1 and the median it is the typical sampling distance. A larger k follows
 * sampling that is denser along one direction than across it (the scan lines of a
 * laser or a stereo camera), a higher quantile the sparser parts of a cloud. */
template <typename PointT>
double
pointSpacing (const pcl::PointCloud<PointT>& cloud,
              double quantile = 0.5,
              std::size_t k = 1,
              std::size_t max_samples = DEFAULT_SPACING_SAMPLES,
              unsigned int threads = 0)
{
  std::vector<std::array<float, 3>> finite;
  finite.reserve (cloud.size());
  for (const PointT& point : cloud)
    if (pcl::isXYZFinite (point))
      finite.push_back ({point.x, point.y, point.z});
  std::sort (finite.begin(), finite.end());
  std::vector<float> xyz;
  xyz.reserve (3 * finite.size());
  for (const auto& point : finite)
    xyz.insert (xyz.end(), point.begin(), point.end());
  return sortedPointSpacing (std::move (xyz), quantile, k, max_samples, threads);
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
 * points are measured, with \a threads OpenMP threads (see pointSpacing()). */
template <typename PointT>
double
surfaceSpacing (const pcl::PointCloud<PointT>& cloud,
                std::size_t max_samples = DEFAULT_SPACING_SAMPLES,
                unsigned int threads = 0)
{
  return pointSpacing (cloud, 0.5, SURFACE_SPACING_NEIGHBORS, max_samples, threads) *
         std::sqrt (M_PI / static_cast<double> (SURFACE_SPACING_NEIGHBORS));
}

/** \brief The surface spacing around given points, the local counterpart of
 * surfaceSpacing(): for each of \a queries (indices into \a points), d_k sqrt(pi / k)
 * with d_k its distance to the k-th nearest point of \a points at a positive distance
 * (k = SURFACE_SPACING_NEIGHBORS); 0 where there are fewer such points. Where a
 * surface is sampled more sparsely (far from a depth camera, across the scan lines
 * of a laser) it is larger than the spacing of the whole cloud. Searched with
 * \a threads OpenMP threads (0: OpenMP's default). */
std::vector<double>
localSurfaceSpacings (const std::vector<Point3d>& points,
                      const std::vector<std::uint32_t>& queries,
                      unsigned int threads = 0);

} // namespace tda
} // namespace pcl
