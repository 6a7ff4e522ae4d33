#include <pcl/tda/apps/feature_scaling.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace pcl {
namespace tda {

std::vector<float>
FeatureScaling::apply (const std::vector<float>& row) const
{
  if (row.size() != offset.size())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "A row of " << row.size() << " values for a scaling of "
                                     << offset.size());
  std::vector<float> scaled (row.size());
  for (std::size_t d = 0; d < row.size(); ++d)
    scaled[d] = static_cast<float> ((row[d] - offset[d]) * factor[d]);
  return scaled;
}

FeatureScaling
fitFeatureScaling (const std::vector<std::vector<float>>& rows,
                   const std::vector<std::size_t>& training,
                   const std::vector<std::size_t>& parts,
                   FeatureScalingMode mode)
{
  if (training.empty())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "A scaling needs at least one training row.");
  const std::size_t size = rows[training.front()].size();
  for (const std::size_t i : training)
    if (rows[i].size() != size)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Rows of " << rows[i].size() << " and " << size
                                      << " values.");
  std::vector<std::size_t> part_sizes = parts;
  if (part_sizes.empty())
    part_sizes.push_back (size);
  if (std::accumulate (part_sizes.begin(), part_sizes.end(), std::size_t{0}) != size ||
      std::count (part_sizes.begin(), part_sizes.end(), 0) > 0)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "The parts do not add up to the " << size << " values.");

  FeatureScaling scaling;
  scaling.offset.assign (size, 0.0);
  scaling.factor.assign (size, 0.0);
  const auto n = static_cast<double> (training.size());
  for (std::size_t d = 0; d < size; ++d) {
    double spread = 0.0;
    if (mode == FeatureScalingMode::Z_SCORE) {
      double sum = 0.0;
      for (const std::size_t i : training)
        sum += rows[i][d];
      const double mean = sum / n;
      double squares = 0.0;
      for (const std::size_t i : training)
        squares += (rows[i][d] - mean) * (rows[i][d] - mean);
      scaling.offset[d] = mean;
      spread = std::sqrt (squares / n);
    }
    else {
      double low = std::numeric_limits<double>::max(), high = -low;
      for (const std::size_t i : training) {
        low = std::min<double> (low, rows[i][d]);
        high = std::max<double> (high, rows[i][d]);
      }
      scaling.offset[d] = low;
      spread = high - low;
    }
    scaling.factor[d] = spread > 0.0 ? 1.0 / spread : 0.0;
  }

  const auto parts_count = static_cast<double> (part_sizes.size());
  std::size_t first = 0;
  for (const std::size_t part : part_sizes) {
    const double weight = std::sqrt (static_cast<double> (size) /
                                     (parts_count * static_cast<double> (part)));
    for (std::size_t d = first; d < first + part; ++d)
      scaling.factor[d] *= weight;
    first += part;
  }
  return scaling;
}

} // namespace tda
} // namespace pcl
