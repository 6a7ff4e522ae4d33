#include <pcl/impl/instantiate.hpp>
#include <pcl/tda/common/point_types.h>
#include <pcl/tda/common/union_find.h>
#include <pcl/tda/segmentation/persistent_euclidean_cluster_extraction.h>
#include <pcl/tda/segmentation/stable_step.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace pcl {
namespace tda {
namespace {

/** The \a q quantile (0 < q <= 1, the smallest value with at least a share q of the
 * values at or below it) of \a values, not empty; reorders them. */
double
quantile (std::vector<double>& values, double q)
{
  const auto rank = static_cast<std::size_t> (
      std::max (std::ceil (q * static_cast<double> (values.size())) - 1.0, 0.0));
  std::nth_element (values.begin(), values.begin() + rank, values.end());
  return values[rank];
}

} // namespace

ClusterDistanceChoice
chooseClusterDistance (const FilteredComplex& complex,
                       const PersistenceResult& h0,
                       double max_distance,
                       std::size_t min_cluster_size,
                       double gap_ratio,
                       double min_distance,
                       double piece_ratio)
{
  ClusterDistanceChoice choice;
  choice.distance = max_distance;

  // Replaying the negative edges (the minimum spanning forest) in filtration order
  // gives the components. A component becomes significant (a would-be cluster, +1 to
  // the count) when it first has significant_size points, and a merge of two
  // significant components subtracts 1; but when the smaller of the two has fewer
  // than piece_ratio times the points of the larger, it was a piece of the larger:
  // it is taken off the count from the scale it counted from (its +1 cancelled)
  // instead, and the scale at which it joined is kept. A merged component counts
  // from the earlier of its parts' scales.
  const std::size_t significant_size = std::max<std::size_t> (min_cluster_size, 2);
  const std::size_t num_vertices = complex.numVertices();
  UnionFind components (num_vertices);
  std::vector<bool> significant (num_vertices, false);
  std::vector<double> counted_from (num_vertices, 0.0);
  std::vector<std::pair<double, int>> events; // (scale, +1 or -1)
  std::vector<double> piece_joins;
  std::vector<double> nearest (num_vertices, std::numeric_limits<double>::infinity());
  for (const SimplexIndex e : h0.negativeEdges()) {
    const FilteredEdge& edge = complex.edges()[e];
    const SimplexIndex a = components.find (edge.source);
    const SimplexIndex b = components.find (edge.target);
    const std::size_t size_a = components.setSize (a), size_b = components.setSize (b);
    const double from_a = counted_from[a], from_b = counted_from[b];
    const bool both = significant[a] && significant[b];
    const bool either = significant[a] || significant[b];
    const SimplexIndex root = components.linkRoots (a, b);
    significant[root] = either || components.setSize (root) >= significant_size;
    if (both) {
      const bool a_smaller = size_a < size_b;
      const double smaller = static_cast<double> (a_smaller ? size_a : size_b);
      const double larger = static_cast<double> (a_smaller ? size_b : size_a);
      if (smaller < piece_ratio * larger) {
        events.emplace_back (a_smaller ? from_a : from_b, -1);
        piece_joins.push_back (edge.value);
      }
      else
        events.emplace_back (edge.value, -1);
      counted_from[root] = std::min (from_a, from_b);
    }
    else if (either)
      counted_from[root] = significant[a] ? from_a : from_b;
    else if (significant[root]) {
      events.emplace_back (edge.value, +1);
      counted_from[root] = edge.value;
    }
    if (edge.value > 0.0) {
      nearest[edge.source] = std::min (nearest[edge.source], edge.value);
      nearest[edge.target] = std::min (nearest[edge.target], edge.value);
    }
  }

  // The sampling scale: the median nearest-neighbour distance (the shortest
  // spanning forest edge of each point).
  std::vector<double> spacings;
  for (const double spacing : nearest)
    if (std::isfinite (spacing))
      spacings.push_back (spacing);
  if (spacings.empty())
    return choice; // no positive scale

  // The floor: the sampling scale or the caller's floor, whichever is larger.
  choice.sampling_scale = quantile (spacings, 0.5);
  const double floor = std::max (choice.sampling_scale, min_distance);
  if (!(floor < max_distance))
    return choice;

  // The count of significant components is a step function of the scale.
  StableStep chosen;
  if (!chooseStableStep (
          events, floor, max_distance, gap_ratio, chosen, StableStepPreference::FINEST))
    return choice; // no significant component above the floor
  choice.low = chosen.low;
  choice.high = chosen.high;
  choice.num_clusters = chosen.count;
  // The count has no piece apart: the distance is past the last piece that joins
  // its object within the step (the join's edge is then in), in the middle of the rest.
  double pieces_joined = choice.low;
  for (const double join : piece_joins)
    if (join < choice.high)
      pieces_joined = std::max (pieces_joined, join);
  choice.distance = std::sqrt (pieces_joined * choice.high);
  choice.clear = chosen.clear;
  return choice;
}

} // namespace tda
} // namespace pcl

#ifndef PCL_NO_PRECOMPILE
#include <pcl/tda/segmentation/impl/persistent_euclidean_cluster_extraction.hpp>

PCL_INSTANTIATE (PersistentEuclideanClusterExtraction, PCL_TDA_XYZ_POINT_TYPES)
#endif // PCL_NO_PRECOMPILE
