#include <pcl/tda/search/canonical_order.h>

#include "stable_radix_sort.h"

#include <algorithm>

namespace pcl {
namespace tda {

void
sortCanonically (std::vector<CanonicalPoint>& points, unsigned int threads)
{
  // Each pass keeps the order of equal keys: first by index (where the points are
  // not in that order already), then by (y, z), then by x.
  const auto by_index = [] (const CanonicalPoint& a, const CanonicalPoint& b) {
    return a.index < b.index;
  };
  std::vector<CanonicalPoint> scratch;
  if (!std::is_sorted (points.begin(), points.end(), by_index))
    stableRadixSort (
        points,
        [] (const CanonicalPoint& point) {
          return static_cast<std::uint64_t> (point.index);
        },
        threads,
        scratch);
  stableRadixSort (
      points,
      [] (const CanonicalPoint& point) {
        return (std::uint64_t{orderedBits (point.y)} << 32) | orderedBits (point.z);
      },
      threads,
      scratch);
  stableRadixSort (
      points,
      [] (const CanonicalPoint& point) { return std::uint64_t{orderedBits (point.x)}; },
      threads,
      scratch);
}

} // namespace tda
} // namespace pcl
