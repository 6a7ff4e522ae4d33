#include <pcl/tda/common/coordinate_scale.h>
#include <pcl/tda/search/nearest_neighbors.h>
#include <pcl/tda/search/point_spacing.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace pcl {
namespace tda {

namespace {

/** The power of two by which distances are measured (powerOfTwoScale() of the
 * largest coordinate magnitude of \a points and \a queries). */
double
coordinateScale (const std::vector<float>& points, const std::vector<float>& queries)
{
  float largest = 0.0f;
  for (const std::vector<float>* values : {&points, &queries})
    for (const float value : *values)
      largest = std::max (largest, std::abs (value));
  return powerOfTwoScale (largest);
}

/** Per query of \a queries, its distance to the \a k -th nearest point of \a points
 * at a positive distance (so that duplicates of the query do not count), or 0 where
 * fewer than k such points exist among the nearest k + 8. */
std::vector<double>
kthNeighborDistances (std::vector<float> points,
                      std::vector<float> queries,
                      std::size_t k,
                      unsigned int threads)
{
  const double scale = coordinateScale (points, queries);
  for (std::vector<float>* values : {&points, &queries})
    for (float& value : *values)
      value = static_cast<float> (value / scale);
  const NearestNeighbors tree (std::move (points));
  const std::size_t num_queries = queries.size() / 3;
  const std::size_t wanted = std::min (k + 8, tree.size());
  std::vector<std::uint32_t> neighbors;
  std::vector<float> squared_distances;
  tree.search (std::move (queries), wanted, threads, neighbors, squared_distances);
  std::vector<double> distances (num_queries, 0.0);
  for (std::size_t q = 0; q < num_queries; ++q) {
    const auto row = squared_distances.begin() + q * wanted;
    const auto first =
        std::find_if (row, row + wanted, [] (float d) { return d > 0.0f; });
    if (static_cast<std::size_t> (row + wanted - first) >= k)
      distances[q] = scale * std::sqrt (static_cast<double> (*(first + (k - 1))));
  }
  return distances;
}

} // namespace

double
sortedPointSpacing (std::vector<float> xyz,
                    double quantile,
                    std::size_t k,
                    std::size_t max_samples,
                    unsigned int threads)
{
  const std::size_t num_points = xyz.size() / 3;
  if (num_points < 2 || k == 0)
    return 0.0;
  const std::size_t stride = std::max<std::size_t> (1, num_points / max_samples);
  std::vector<float> samples;
  for (std::size_t i = 0; i < num_points; i += stride)
    samples.insert (samples.end(), &xyz[3 * i], &xyz[3 * i] + 3);
  std::vector<double> spacings =
      kthNeighborDistances (std::move (xyz), std::move (samples), k, threads);
  spacings.erase (std::remove (spacings.begin(), spacings.end(), 0.0), spacings.end());
  if (spacings.empty())
    return 0.0;
  const auto rank = static_cast<std::size_t> (std::max (
      std::ceil (quantile * static_cast<double> (spacings.size())) - 1.0, 0.0));
  std::nth_element (spacings.begin(),
                    spacings.begin() + std::min (rank, spacings.size() - 1),
                    spacings.end());
  return spacings[std::min (rank, spacings.size() - 1)];
}

std::vector<double>
localSurfaceSpacings (const std::vector<Point3d>& points,
                      const std::vector<std::uint32_t>& queries,
                      unsigned int threads)
{
  if (points.size() < 2)
    return std::vector<double> (queries.size(), 0.0);
  std::vector<double> spacings =
      kthNeighborDistances (floatCoordinates (points),
                            floatCoordinates (points, queries),
                            SURFACE_SPACING_NEIGHBORS,
                            threads);
  const double per_distance =
      std::sqrt (M_PI / static_cast<double> (SURFACE_SPACING_NEIGHBORS));
  for (double& spacing : spacings)
    spacing *= per_distance;
  return spacings;
}

} // namespace tda
} // namespace pcl
