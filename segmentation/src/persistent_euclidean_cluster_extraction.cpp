#include <pcl/impl/instantiate.hpp>
#include <pcl/tda/common/point_types.h>
#include <pcl/tda/common/union_find.h>
#include <pcl/tda/segmentation/persistent_euclidean_cluster_extraction.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace pcl {
namespace tda {

double
chooseClusterDistance (const FilteredComplex& complex,
                       const PersistenceResult& h0,
                       double max_distance,
                       std::size_t min_cluster_size,
                       double gap_ratio)
{
  // Bars of the significant components: a component is born (as a would-be
  // cluster) when it first has significant_size points, and dies when it merges
  // with an older one (the elder rule on these births).
  struct Bar {
    double birth;
    double death;
  };
  const std::size_t significant_size = std::max<std::size_t> (min_cluster_size, 2);
  const std::size_t num_vertices = complex.numVertices();
  constexpr double NOT_SIGNIFICANT = -1.0;
  UnionFind components (num_vertices);
  std::vector<double> significant_birth (num_vertices, NOT_SIGNIFICANT);
  std::vector<Bar> bars;
  std::vector<std::pair<double, int>> events; // (scale, +1 birth or -1 death)
  double smallest_death = std::numeric_limits<double>::infinity();
  // The negative edges in filtration order: replaying them gives the components.
  for (const SimplexIndex e : h0.negativeEdges()) {
    const FilteredEdge& edge = complex.edges()[e];
    const SimplexIndex a = components.find (edge.source);
    const SimplexIndex b = components.find (edge.target);
    const double birth_a = significant_birth[a], birth_b = significant_birth[b];
    const SimplexIndex root = components.linkRoots (a, b);
    if (edge.value > 0.0)
      smallest_death = std::min (smallest_death, edge.value);
    if (birth_a >= 0.0 && birth_b >= 0.0) {
      bars.push_back ({std::max (birth_a, birth_b), edge.value});
      events.emplace_back (edge.value, -1);
      significant_birth[root] = std::min (birth_a, birth_b);
    }
    else if (birth_a >= 0.0 || birth_b >= 0.0)
      significant_birth[root] = std::max (birth_a, birth_b);
    else if (components.setSize (root) >= significant_size) {
      significant_birth[root] = edge.value;
      events.emplace_back (edge.value, +1);
    }
  }
  std::size_t eldest = bars.size();
  for (SimplexIndex v = 0; v < num_vertices; ++v)
    if (components.find (v) == v && significant_birth[v] >= 0.0) {
      if (eldest == bars.size() || significant_birth[v] < bars[eldest].birth)
        eldest = bars.size();
      bars.push_back ({significant_birth[v], max_distance});
    }
  if (eldest == bars.size() || !std::isfinite (smallest_death))
    return max_distance; // no component of significant size, or no positive scale

  // Dense bars are born within gap_ratio of the eldest's birth, i.e. at the
  // sampling scale; sparse ones later (e.g. remnants of a removed plane).
  const double densest_birth = std::max (bars[eldest].birth, smallest_death);
  const auto dense = [&] (const Bar& bar) {
    return bar.birth <= gap_ratio * densest_birth;
  };
  const auto lifetime = [&] (const Bar& bar) {
    return std::log (bar.death / std::max (bar.birth, smallest_death));
  };
  // The clusters: the eldest bar, plus the dense bars above the largest gap in the
  // log-lifetimes of the others (a virtual bar of lifetime 0 below them), among
  // those that live at least gap_ratio times their birth.
  std::vector<std::size_t> others;
  for (std::size_t k = 0; k < bars.size(); ++k)
    if (k != eldest && dense (bars[k]))
      others.push_back (k);
  std::stable_sort (others.begin(), others.end(), [&] (std::size_t a, std::size_t b) {
    return lifetime (bars[a]) > lifetime (bars[b]);
  });
  std::size_t num_longer = 0;
  double largest_gap = -1.0;
  for (std::size_t k = 0;
       k < others.size() && lifetime (bars[others[k]]) >= std::log (gap_ratio);
       ++k) {
    const double next = k + 1 < others.size() ? lifetime (bars[others[k + 1]]) : 0.0;
    if (lifetime (bars[others[k]]) - next > largest_gap) {
      largest_gap = lifetime (bars[others[k]]) - next;
      num_longer = k + 1;
    }
  }
  const std::size_t num_clusters = num_longer + 1;

  // The window of scales where these clusters all exist and no sparse component
  // has merged yet.
  double window_low = densest_birth, window_high = max_distance;
  for (std::size_t k = 0; k < num_longer; ++k) {
    window_low = std::max (window_low, bars[others[k]].birth);
    window_high = std::min (window_high, bars[others[k]].death);
  }
  for (const Bar& bar : bars)
    if (!dense (bar))
      window_high = std::min (window_high, bar.death);
  if (!(window_high > window_low)) {
    window_low = smallest_death;
    window_high = max_distance;
  }

  // The distance: the geometric middle of the longest (relative) interval of the
  // window over which exactly k significant components exist (or, without one, the
  // count nearest k).
  std::stable_sort (events.begin(), events.end(), [] (const auto& a, const auto& b) {
    return a.first < b.first;
  });
  std::size_t count = 0;
  double best_length = -1.0, chosen = max_distance;
  std::size_t best_miss = std::numeric_limits<std::size_t>::max();
  for (std::size_t e = 0; e < events.size(); ++e) {
    count += events[e].second; // -1 wraps to a decrement
    const double low = std::max (events[e].first, window_low);
    const double high = std::min (
        e + 1 < events.size() ? events[e + 1].first : max_distance, window_high);
    if (!(high > low))
      continue;
    const std::size_t miss =
        count > num_clusters ? count - num_clusters : num_clusters - count;
    const double length = std::log (high / low);
    if (miss < best_miss || (miss == best_miss && length > best_length)) {
      best_miss = miss;
      best_length = length;
      chosen = std::sqrt (low * high);
    }
  }
  return std::min (chosen, max_distance);
}

} // namespace tda
} // namespace pcl

#ifndef PCL_NO_PRECOMPILE
#include <pcl/tda/segmentation/impl/persistent_euclidean_cluster_extraction.hpp>

PCL_INSTANTIATE (PersistentEuclideanClusterExtraction, PCL_TDA_XYZ_POINT_TYPES)
#endif // PCL_NO_PRECOMPILE
