#include <pcl/tda/common/spanning_forest.h>
#include <pcl/tda/common/union_find.h>
#include <pcl/tda/search/nearest_neighbors.h>
#include <pcl/tda/segmentation/color_regions.h>
#include <pcl/tda/segmentation/stable_step.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

namespace pcl {
namespace tda {
namespace {

/** Regions numbered again by decreasing size, equal sizes by smallest vertex; the
 * lifetimes follow. \a smallest: the smallest vertex of each region. */
void
renumberBySize (const std::vector<std::uint32_t>& smallest, ColorRegions& regions)
{
  const std::size_t num_regions = regions.lifetimes.size();
  std::vector<std::size_t> sizes (num_regions, 0);
  for (const std::uint32_t region : regions.region_of)
    if (region != NO_REGION)
      ++sizes[region];
  std::vector<std::uint32_t> order (num_regions);
  std::iota (order.begin(), order.end(), 0u);
  std::sort (order.begin(), order.end(), [&] (std::uint32_t a, std::uint32_t b) {
    return std::make_tuple (sizes[b], smallest[a]) <
           std::make_tuple (sizes[a], smallest[b]);
  });
  std::vector<std::uint32_t> new_id (num_regions);
  std::vector<RegionLifetime> lifetimes (num_regions);
  for (std::uint32_t k = 0; k < num_regions; ++k) {
    new_id[order[k]] = k;
    lifetimes[k] = regions.lifetimes[order[k]];
  }
  for (std::uint32_t& region : regions.region_of)
    if (region != NO_REGION)
      region = new_id[region];
  regions.lifetimes = std::move (lifetimes);
}

/** The components of the forest edges of value <= threshold: a union-find over the
 * vertices. */
UnionFind
componentsAtThreshold (std::size_t num_vertices,
                       const std::vector<FilteredEdge>& forest,
                       double threshold)
{
  UnionFind components (num_vertices);
  for (const FilteredEdge& edge : forest) {
    if (edge.value > threshold)
      break;
    components.linkRoots (components.find (edge.source), components.find (edge.target));
  }
  return components;
}

} // namespace

std::vector<FilteredEdge>
homogeneityForest (std::size_t num_vertices, const std::vector<FilteredEdge>& edges)
{
  std::vector<FilteredEdge> finite;
  finite.reserve (edges.size());
  std::copy_if (edges.begin(),
                edges.end(),
                std::back_inserter (finite),
                [] (const auto& edge) { return std::isfinite (edge.value); });
  return minimumSpanningForest (num_vertices, finite);
}

ColorRegions
regionsAtThreshold (std::size_t num_vertices,
                    const std::vector<FilteredEdge>& forest,
                    double threshold,
                    std::size_t min_size)
{
  constexpr double never = std::numeric_limits<double>::infinity();
  min_size = std::max<std::size_t> (min_size, 1);
  ColorRegions regions;
  UnionFind components (num_vertices);
  // Per root: birth (infinite until the component has min_size points), smallest
  // vertex, and the region of the threshold it carries (NO_REGION before it).
  std::vector<double> birth (num_vertices, min_size == 1 ? 0.0 : never);
  std::vector<std::uint32_t> smallest (num_vertices);
  std::iota (smallest.begin(), smallest.end(), 0u);
  std::vector<std::uint32_t> region_of_root (num_vertices, NO_REGION);

  const auto join = [&] (const FilteredEdge& edge) {
    const std::uint32_t a = components.find (edge.source);
    const std::uint32_t b = components.find (edge.target);
    const auto older = [&] (std::uint32_t x, std::uint32_t y) {
      return std::tie (birth[x], smallest[x]) < std::tie (birth[y], smallest[y]);
    };
    const std::uint32_t elder = older (a, b) ? a : b;
    const std::uint32_t younger = elder == a ? b : a;
    if (std::isfinite (birth[younger])) { // two regions meet: the younger ends
      regions.bars.push_back ({0, birth[younger], edge.value});
      if (region_of_root[younger] != NO_REGION)
        regions.lifetimes[region_of_root[younger]].death = edge.value;
    }
    const double elder_birth = birth[elder];
    const std::uint32_t elder_region = region_of_root[elder];
    const std::uint32_t first = std::min (smallest[a], smallest[b]);
    const std::uint32_t root = components.linkRoots (a, b);
    birth[root] = std::isfinite (elder_birth)             ? elder_birth
                  : components.setSize (root) >= min_size ? edge.value
                                                          : never;
    region_of_root[root] = elder_region;
    smallest[root] = first;
  };

  std::size_t e = 0;
  for (; e < forest.size() && forest[e].value <= threshold; ++e)
    join (forest[e]);
  regions.region_of.assign (num_vertices, NO_REGION);
  std::vector<std::uint32_t> smallest_of_region;
  for (std::uint32_t v = 0; v < num_vertices; ++v) {
    const std::uint32_t root = components.find (v);
    if (!std::isfinite (birth[root]))
      continue;
    if (region_of_root[root] == NO_REGION) {
      region_of_root[root] = static_cast<std::uint32_t> (regions.lifetimes.size());
      regions.lifetimes.push_back ({birth[root], never});
      smallest_of_region.push_back (smallest[root]);
    }
    regions.region_of[v] = region_of_root[root];
  }
  for (; e < forest.size(); ++e)
    join (forest[e]);
  for (std::uint32_t v = 0; v < num_vertices; ++v)
    if (components.find (v) == v && std::isfinite (birth[v]))
      regions.bars.push_back ({0, birth[v], never});
  renumberBySize (smallest_of_region, regions);
  return regions;
}

std::vector<std::uint32_t>
mergeSmallRegions (const std::vector<FilteredEdge>& graph,
                   const std::vector<FilteredEdge>& forest,
                   const std::vector<LabColor>& colors,
                   double threshold,
                   std::size_t min_size,
                   double max_difference,
                   ColorRegions& regions)
{
  const std::size_t num_vertices = colors.size();
  const auto num_regions = static_cast<std::uint32_t> (regions.lifetimes.size());
  // Groups: the regions, then one per small component of the threshold.
  UnionFind components = componentsAtThreshold (num_vertices, forest, threshold);
  std::vector<std::uint32_t> group_of (num_vertices);
  std::vector<std::uint32_t> group_of_root (num_vertices, NO_REGION);
  std::uint32_t num_groups = num_regions;
  for (std::uint32_t v = 0; v < num_vertices; ++v) {
    if (regions.region_of[v] != NO_REGION) {
      group_of[v] = regions.region_of[v];
      continue;
    }
    std::uint32_t& group = group_of_root[components.find (v)];
    if (group == NO_REGION)
      group = num_groups++;
    group_of[v] = group;
  }
  if (num_groups == num_regions)
    return {};

  struct Group {
    std::size_t size = 0;
    double l = 0.0, a = 0.0, b = 0.0; // sums of the CIELAB colours
    std::uint32_t smallest = NO_REGION;
    std::vector<std::uint32_t> neighbors;
    LabColor
    mean () const
    {
      const double n = static_cast<double> (size);
      return {static_cast<float> (l / n),
              static_cast<float> (a / n),
              static_cast<float> (b / n)};
    }
  };
  std::vector<Group> groups (num_groups);
  for (std::uint32_t v = 0; v < num_vertices; ++v) {
    Group& group = groups[group_of[v]];
    ++group.size;
    group.l += colors[v].l;
    group.a += colors[v].a;
    group.b += colors[v].b;
    group.smallest = std::min (group.smallest, v);
  }
  for (const FilteredEdge& edge : graph) {
    const std::uint32_t a = group_of[edge.source], b = group_of[edge.target];
    if (a == b)
      continue;
    if (a >= num_regions)
      groups[a].neighbors.push_back (b);
    if (b >= num_regions)
      groups[b].neighbors.push_back (a);
  }

  // Smallest first; a group that has grown to min_size by then stays.
  std::vector<std::uint32_t> order (num_groups - num_regions);
  std::iota (order.begin(), order.end(), num_regions);
  std::sort (order.begin(), order.end(), [&] (std::uint32_t x, std::uint32_t y) {
    return std::tie (groups[x].size, groups[x].smallest) <
           std::tie (groups[y].size, groups[y].smallest);
  });
  UnionFind merged (num_groups);
  std::vector<std::uint32_t> host (num_groups);
  std::iota (host.begin(), host.end(), 0u); // the group a union-find root stands for
  const auto current = [&] (std::uint32_t group) { return host[merged.find (group)]; };
  for (const std::uint32_t small : order) {
    Group& group = groups[small];
    if (current (small) != small || group.size >= min_size)
      continue;
    const LabColor mean = group.mean();
    std::uint32_t best = NO_REGION;
    float best_difference = 0.0f;
    for (const std::uint32_t neighbor : group.neighbors) {
      const std::uint32_t candidate = current (neighbor);
      if (candidate == small)
        continue;
      const float difference = deltaE76 (mean, groups[candidate].mean());
      const auto key = [&] (std::uint32_t g, float d) {
        return std::make_tuple (d, ~groups[g].size, groups[g].smallest);
      };
      if (best == NO_REGION ||
          key (candidate, difference) < key (best, best_difference)) {
        best = candidate;
        best_difference = difference;
      }
    }
    if (best == NO_REGION || !(best_difference <= max_difference))
      continue;
    Group& target = groups[best];
    target.size += group.size;
    target.l += group.l;
    target.a += group.a;
    target.b += group.b;
    target.smallest = std::min (target.smallest, group.smallest);
    target.neighbors.insert (
        target.neighbors.end(), group.neighbors.begin(), group.neighbors.end());
    group.neighbors = {};
    const std::uint32_t root =
        merged.linkRoots (merged.find (small), merged.find (best));
    host[root] = best;
  }

  // Groups that end with min_size points are the regions; the merged small ones,
  // which became regions only by merging, have no bar: birth = death = threshold.
  std::vector<std::uint32_t> region_of_group (num_groups, NO_REGION);
  std::vector<std::uint32_t> smallest;
  ColorRegions result;
  result.bars = std::move (regions.bars);
  for (std::uint32_t g = 0; g < num_groups; ++g) {
    if (current (g) != g || groups[g].size < min_size)
      continue;
    region_of_group[g] = static_cast<std::uint32_t> (result.lifetimes.size());
    result.lifetimes.push_back (g < num_regions ? regions.lifetimes[g]
                                                : RegionLifetime{threshold, threshold});
    smallest.push_back (groups[g].smallest);
  }
  result.region_of.resize (num_vertices);
  std::vector<std::uint32_t> isolated;
  for (std::uint32_t v = 0; v < num_vertices; ++v) {
    const std::uint32_t group = current (group_of[v]);
    result.region_of[v] = region_of_group[group];
    if (result.region_of[v] == NO_REGION && groups[group].neighbors.empty())
      isolated.push_back (v);
  }
  renumberBySize (smallest, result);
  regions = std::move (result);
  return isolated;
}

void
attachIsolatedPoints (const std::vector<Point3d>& points,
                      const std::vector<LabColor>& colors,
                      const std::vector<std::uint32_t>& isolated,
                      std::size_t k,
                      unsigned int threads,
                      ColorRegions& regions)
{
  if (isolated.empty())
    return;
  std::vector<std::uint32_t> labelled;
  for (std::uint32_t v = 0; v < points.size(); ++v)
    if (regions.region_of[v] != NO_REGION)
      labelled.push_back (v);
  if (labelled.empty())
    return;
  const std::size_t num_neighbors = std::min (k, labelled.size());
  std::vector<std::uint32_t> neighbors;
  std::vector<float> squared_distances;
  NearestNeighbors (floatCoordinates (points, labelled))
      .search (floatCoordinates (points, isolated),
               num_neighbors,
               threads,
               neighbors,
               squared_distances);
  for (std::size_t i = 0; i < isolated.size(); ++i) {
    const std::uint32_t v = isolated[i];
    const auto row = neighbors.begin() + i * num_neighbors;
    // The most similar colour; of equal ones, the nearest (the search's order).
    std::uint32_t best = labelled[*row];
    for (auto neighbor = row; neighbor != row + num_neighbors; ++neighbor) {
      const std::uint32_t w = labelled[*neighbor];
      if (deltaE76 (colors[v], colors[w]) < deltaE76 (colors[v], colors[best]))
        best = w;
    }
    regions.region_of[v] = regions.region_of[best];
  }
}

std::vector<FilteredEdge>
regionColorForest (const std::vector<FilteredEdge>& graph,
                   const std::vector<LabColor>& colors,
                   const ColorRegions& regions)
{
  const std::size_t num_regions = regions.lifetimes.size();
  std::vector<std::array<double, 3>> sums (num_regions, {0.0, 0.0, 0.0});
  std::vector<std::size_t> sizes (num_regions, 0);
  for (std::size_t v = 0; v < colors.size(); ++v) {
    const std::uint32_t region = regions.region_of[v];
    if (region == NO_REGION)
      continue;
    sums[region][0] += colors[v].l;
    sums[region][1] += colors[v].a;
    sums[region][2] += colors[v].b;
    ++sizes[region];
  }
  std::vector<LabColor> means (num_regions);
  for (std::size_t r = 0; r < num_regions; ++r) {
    const double n = static_cast<double> (sizes[r]);
    means[r] = {static_cast<float> (sums[r][0] / n),
                static_cast<float> (sums[r][1] / n),
                static_cast<float> (sums[r][2] / n)};
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const FilteredEdge& edge : graph) {
    const std::uint32_t a = regions.region_of[edge.source];
    const std::uint32_t b = regions.region_of[edge.target];
    if (a != b && a != NO_REGION && b != NO_REGION && std::isfinite (edge.value))
      pairs.emplace_back (std::min (a, b), std::max (a, b));
  }
  std::sort (pairs.begin(), pairs.end());
  pairs.erase (std::unique (pairs.begin(), pairs.end()), pairs.end());
  std::vector<FilteredEdge> edges;
  edges.reserve (pairs.size());
  for (const auto& [a, b] : pairs)
    edges.push_back ({a, b, deltaE76 (means[a], means[b])});
  return minimumSpanningForest (num_regions, edges);
}

ColorRegions
mergeSimilarRegions (const ColorRegions& patches,
                     const std::vector<FilteredEdge>& forest,
                     double threshold)
{
  const std::size_t num_patches = patches.lifetimes.size();
  // Patches are numbered by decreasing size: the smaller id is the elder.
  const ColorRegions merged = regionsAtThreshold (num_patches, forest, threshold, 1);
  ColorRegions regions;
  regions.lifetimes = merged.lifetimes;
  for (RegionLifetime& lifetime : regions.lifetimes)
    lifetime.birth = 0.0;
  for (const FilteredEdge& edge : forest) {
    if (edge.value > threshold)
      break;
    RegionLifetime& lifetime = regions.lifetimes[merged.region_of[edge.source]];
    lifetime.birth = std::max (lifetime.birth, edge.value);
  }
  regions.region_of.resize (patches.region_of.size());
  std::vector<std::uint32_t> smallest (regions.lifetimes.size(), NO_REGION);
  for (std::uint32_t v = 0; v < patches.region_of.size(); ++v) {
    const std::uint32_t patch = patches.region_of[v];
    const std::uint32_t region =
        patch == NO_REGION ? NO_REGION : merged.region_of[patch];
    regions.region_of[v] = region;
    if (region != NO_REGION)
      smallest[region] = std::min (smallest[region], v);
  }
  regions.bars = merged.bars;
  renumberBySize (smallest, regions);
  return regions;
}

ColorThresholdChoice
chooseColorThreshold (const PersistenceDiagram& bars,
                      double floor,
                      double max_threshold,
                      double gap_ratio,
                      double fallback)
{
  ColorThresholdChoice choice;
  choice.threshold = std::min (fallback, max_threshold);
  if (!(floor > 0.0 && floor < max_threshold))
    return choice;
  // The region count changes at the births (+1) and deaths (-1) of the bars.
  std::vector<std::pair<double, int>> events;
  for (const PersistenceInterval& bar : bars) {
    events.emplace_back (bar.birth, +1);
    if (!bar.isEssential())
      events.emplace_back (bar.death, -1);
  }
  StableStep chosen;
  if (!chooseStableStep (events, floor, max_threshold, gap_ratio, chosen))
    return choice;
  choice.low = chosen.low;
  choice.high = chosen.high;
  choice.num_regions = chosen.count;
  choice.clear = chosen.clear;
  if (chosen.high >= gap_ratio * chosen.low) // stable enough to be taken
    choice.threshold = std::sqrt (choice.low * choice.high);
  return choice;
}

} // namespace tda
} // namespace pcl
