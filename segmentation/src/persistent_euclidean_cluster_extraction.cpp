#include <pcl/impl/instantiate.hpp>
#include <pcl/tda/common/union_find.h>
#include <pcl/tda/segmentation/persistent_euclidean_cluster_extraction.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <tuple>
#include <utility>

namespace pcl {
namespace tda {

namespace {

/** Kruskal with filtering (Osipov, Sanders, Singler 2009) on edges[begin, end):
 * split at the median value, take the forest of the lighter half, drop the heavier
 * edges that no longer join two components, recurse on the rest. Appends the
 * forest's edges to \a forest, in increasing value. */
void
filterKruskal (std::vector<FilteredEdge>& edges,
               std::size_t begin,
               std::size_t end,
               UnionFind& components,
               std::vector<FilteredEdge>& forest)
{
  const auto lighter = [] (const FilteredEdge& a, const FilteredEdge& b) {
    return a.value < b.value;
  };
  constexpr std::size_t SMALL = 2048;
  if (end - begin <= SMALL) {
    std::sort (edges.begin() + begin, edges.begin() + end, lighter);
    for (std::size_t e = begin; e < end; ++e) {
      const SimplexIndex a = components.find (edges[e].source);
      const SimplexIndex b = components.find (edges[e].target);
      if (a != b) {
        components.linkRoots (a, b);
        forest.push_back (edges[e]);
      }
    }
    return;
  }
  const std::size_t middle = begin + (end - begin) / 2;
  std::nth_element (
      edges.begin() + begin, edges.begin() + middle, edges.begin() + end, lighter);
  filterKruskal (edges, begin, middle, components, forest);
  const auto joined = [&components] (const FilteredEdge& edge) {
    return components.find (edge.source) == components.find (edge.target);
  };
  const auto rest =
      std::remove_if (edges.begin() + middle, edges.begin() + end, joined);
  filterKruskal (edges, middle, rest - edges.begin(), components, forest);
}

} // namespace

std::vector<FilteredEdge>
radiusGraphSpanningForest (const std::vector<Point3d>& points,
                           double radius,
                           const EdgeTest& accept,
                           unsigned int threads,
                           std::size_t& num_graph_edges)
{
  num_graph_edges = 0;
  if (!(radius > 0.0) || !std::isfinite (radius))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "the radius must be positive and finite, not " << radius);
  const std::size_t n = points.size();
  if (n == 0)
    return {};

  // Cells of size radius, keyed by 21 bits per axis (offset by one so that the
  // neighbouring cells have keys too); points sorted by cell.
  Point3d low = points[0], high = points[0];
  for (const Point3d& point : points)
    for (int axis = 0; axis < 3; ++axis) {
      low[axis] = std::min (low[axis], point[axis]);
      high[axis] = std::max (high[axis], point[axis]);
    }
  constexpr double MAX_CELLS = double (1 << 20);
  for (int axis = 0; axis < 3; ++axis)
    if ((high[axis] - low[axis]) / radius >= MAX_CELLS)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "the radius " << radius
                                         << " is too small for a cloud extent "
                                         << "of " << high[axis] - low[axis]
                                         << " (more than 2^20 cells)");
  const auto cellKey = [&] (const Point3d& point) {
    std::uint64_t key = 0;
    for (int axis = 0; axis < 3; ++axis)
      key = (key << 21) |
            (static_cast<std::uint64_t> ((point[axis] - low[axis]) / radius) + 1);
    return key;
  };
  std::vector<std::pair<std::uint64_t, SimplexIndex>> keyed (n);
  for (SimplexIndex v = 0; v < n; ++v)
    keyed[v] = {cellKey (points[v]), v};
  std::sort (keyed.begin(), keyed.end());
  std::vector<std::uint64_t> cell_keys;
  std::vector<std::uint32_t> cell_begin;
  std::vector<Point3d> sorted (n);
  for (std::size_t k = 0; k < n; ++k) {
    if (k == 0 || keyed[k].first != keyed[k - 1].first) {
      cell_keys.push_back (keyed[k].first);
      cell_begin.push_back (static_cast<std::uint32_t> (k));
    }
    sorted[k] = points[keyed[k].second];
  }
  cell_begin.push_back (static_cast<std::uint32_t> (n));

  // The 13 neighbouring cells after a cell in key order; each pair is found once,
  // from the cell that comes first (within a cell, from the point that comes first).
  std::vector<std::uint64_t> forward_offsets;
  for (std::int64_t dx = -1; dx <= 1; ++dx)
    for (std::int64_t dy = -1; dy <= 1; ++dy)
      for (std::int64_t dz = -1; dz <= 1; ++dz)
        if (std::make_tuple (dx, dy, dz) > std::make_tuple (0, 0, 0))
          forward_offsets.push_back ( // unsigned arithmetic wraps as intended
              (static_cast<std::uint64_t> (dx) << 42) +
              (static_cast<std::uint64_t> (dy) << 21) +
              static_cast<std::uint64_t> (dz));

  const double squared_radius = radius * radius;
  const auto num_cells = static_cast<std::int64_t> (cell_keys.size());
  const int num_threads =
      threads > 0 ? static_cast<int> (threads) : omp_get_max_threads();
  std::vector<std::vector<FilteredEdge>> thread_edges (num_threads);
#pragma omp parallel num_threads(num_threads)
  {
    std::vector<FilteredEdge>& edges = thread_edges[omp_get_thread_num()];
    const auto visit = [&] (std::uint32_t i, std::uint32_t first, std::uint32_t last) {
      for (std::uint32_t j = first; j < last; ++j) {
        const double dx = sorted[i][0] - sorted[j][0], dy = sorted[i][1] - sorted[j][1],
                     dz = sorted[i][2] - sorted[j][2];
        const double squared = dx * dx + dy * dy + dz * dz;
        if (squared > squared_radius * (1.0 + 1e-9))
          continue;
        const double length = std::sqrt (squared); // as pcl::tda::distance()
        if (length <= radius && (!accept || accept (keyed[i].second, keyed[j].second)))
          edges.push_back ({i, j, length});
      }
    };
    // Static schedule: thread t takes the t-th block of cells, so that joining the
    // threads' lists in order gives the same list for any number of threads.
#pragma omp for schedule(static)
    for (std::int64_t c = 0; c < num_cells; ++c) {
      std::uint32_t neighbours[13][2];
      std::size_t num_neighbours = 0;
      for (const std::uint64_t offset : forward_offsets) {
        const auto found = std::lower_bound (
            cell_keys.begin() + c, cell_keys.end(), cell_keys[c] + offset);
        if (found != cell_keys.end() && *found == cell_keys[c] + offset) {
          const std::size_t d = found - cell_keys.begin();
          neighbours[num_neighbours][0] = cell_begin[d];
          neighbours[num_neighbours++][1] = cell_begin[d + 1];
        }
      }
      for (std::uint32_t i = cell_begin[c]; i < cell_begin[c + 1]; ++i) {
        visit (i, i + 1, cell_begin[c + 1]);
        for (std::size_t k = 0; k < num_neighbours; ++k)
          visit (i, neighbours[k][0], neighbours[k][1]);
      }
    }
  }
  std::vector<FilteredEdge> edges = std::move (thread_edges[0]);
  for (int t = 1; t < num_threads; ++t)
    edges.insert (edges.end(), thread_edges[t].begin(), thread_edges[t].end());
  num_graph_edges = edges.size();

  UnionFind components (n);
  std::vector<FilteredEdge> forest;
  forest.reserve (n - 1);
  filterKruskal (edges, 0, edges.size(), components, forest);
  // Back to the input's vertex ids, in filtration order.
  for (FilteredEdge& edge : forest) {
    const SimplexIndex a = keyed[edge.source].second, b = keyed[edge.target].second;
    edge.source = std::min (a, b);
    edge.target = std::max (a, b);
  }
  std::sort (
      forest.begin(), forest.end(), [] (const FilteredEdge& a, const FilteredEdge& b) {
        return std::tie (a.value, a.source, a.target) <
               std::tie (b.value, b.source, b.target);
      });
  return forest;
}

std::vector<pcl::Indices>
persistentComponents (const FilteredComplex& complex,
                      const PersistenceResult& h0,
                      double cut)
{
  const std::size_t num_vertices = complex.numVertices();
  UnionFind components (num_vertices);
  for (const PersistencePair& pair : h0.pairs) {
    if (pair.dimension != 0 || pair.isEssential() || pair.death > cut)
      continue;
    const FilteredEdge& edge = complex.edges()[pair.death_simplex];
    components.linkRoots (components.find (edge.source), components.find (edge.target));
  }

  // Number the components by their oldest vertex, then fill them in vertex order.
  constexpr std::uint32_t NONE = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> component_of_root (num_vertices, NONE);
  std::vector<pcl::Indices> result;
  const std::vector<int>& point_indices = complex.pointIndices();
  for (SimplexIndex v = 0; v < num_vertices; ++v) {
    const SimplexIndex root = components.find (v);
    if (component_of_root[root] == NONE) {
      component_of_root[root] = static_cast<std::uint32_t> (result.size());
      result.emplace_back();
      result.back().reserve (components.setSize (root));
    }
    result[component_of_root[root]].push_back (
        point_indices.empty() ? static_cast<pcl::index_t> (v) : point_indices[v]);
  }
  for (auto& component : result)
    std::sort (component.begin(), component.end());
  std::sort (
      result.begin(), result.end(), [] (const pcl::Indices& a, const pcl::Indices& b) {
        return a.size() != b.size() ? a.size() > b.size() : a[0] < b[0];
      });
  return result;
}

PersistenceDiagram
steppedH0Diagram (const PersistenceResult& h0, double max_distance, unsigned int steps)
{
  if (steps == 0)
    return h0.diagram (0);
  PersistenceResult stepped;
  stepped.pairs = h0.pairs;
  const double step = max_distance / steps;
  for (PersistencePair& pair : stepped.pairs) {
    if (pair.dimension != 0 || pair.isEssential())
      continue;
    const double k = std::ceil (pair.death / step);
    pair.death = k >= steps ? max_distance : k * step;
  }
  return stepped.diagram (0);
}

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
  // The finite pairs are in edge order: replaying them gives the components.
  for (const PersistencePair& pair : h0.pairs) {
    if (pair.dimension != 0 || pair.isEssential())
      continue;
    const FilteredEdge& edge = complex.edges()[pair.death_simplex];
    const SimplexIndex a = components.find (edge.source);
    const SimplexIndex b = components.find (edge.target);
    const double birth_a = significant_birth[a], birth_b = significant_birth[b];
    const SimplexIndex root = components.linkRoots (a, b);
    if (pair.death > 0.0)
      smallest_death = std::min (smallest_death, pair.death);
    if (birth_a >= 0.0 && birth_b >= 0.0) {
      bars.push_back ({std::max (birth_a, birth_b), pair.death});
      events.emplace_back (pair.death, -1);
      significant_birth[root] = std::min (birth_a, birth_b);
    }
    else if (birth_a >= 0.0 || birth_b >= 0.0)
      significant_birth[root] = std::max (birth_a, birth_b);
    else if (components.setSize (root) >= significant_size) {
      significant_birth[root] = pair.death;
      events.emplace_back (pair.death, +1);
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

PCL_INSTANTIATE (
    PersistentEuclideanClusterExtraction,
    (pcl::PointXYZ) (pcl::PointXYZI) (pcl::PointXYZRGB) (pcl::PointXYZRGBA) (
        pcl::PointNormal) (pcl::PointXYZRGBNormal) (pcl::PointXYZRGBL))
#endif // PCL_NO_PRECOMPILE
