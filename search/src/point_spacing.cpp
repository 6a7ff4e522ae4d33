#include <pcl/tda/search/nearest_neighbors.h>
#include <pcl/tda/search/point_spacing.h>

namespace pcl {
namespace tda {

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
  const std::size_t num_samples = samples.size() / 3;
  // Enough neighbours to step over a few duplicates of the point.
  const std::size_t wanted = std::min (k + 8, num_points);
  std::vector<std::uint32_t> neighbors;
  std::vector<float> squared_distances;
  NearestNeighbors (std::move (xyz))
      .search (std::move (samples), wanted, threads, neighbors, squared_distances);
  std::vector<double> spacings;
  for (std::size_t q = 0; q < num_samples; ++q) {
    const auto row = squared_distances.begin() + q * wanted;
    const auto first =
        std::find_if (row, row + wanted, [] (float d) { return d > 0.0f; });
    if (static_cast<std::size_t> (row + wanted - first) >= k)
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

} // namespace tda
} // namespace pcl
