// The two filtrations of colour region growing against brute force: flood fills of
// random graphs for the patches and their bars, the merging of small patches on
// hand-made graphs, and the components of the region adjacency graph.

#include <pcl/tda/segmentation/color_regions.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <vector>

using namespace pcl::tda;

namespace {

constexpr double INF = std::numeric_limits<double>::infinity();

/** A partition as a set of sorted vertex sets, NO_REGION vertices left out. */
std::set<std::vector<std::uint32_t>>
partition (const std::vector<std::uint32_t>& region_of)
{
  std::map<std::uint32_t, std::vector<std::uint32_t>> members;
  for (std::uint32_t v = 0; v < region_of.size(); ++v)
    if (region_of[v] != NO_REGION)
      members[region_of[v]].push_back (v);
  std::set<std::vector<std::uint32_t>> sets;
  for (auto& [region, vertices] : members)
    sets.insert (vertices);
  return sets;
}

/** Components of the edges accepted by \a keep, by repeated flood fills. */
template <typename Keep>
std::vector<std::uint32_t>
floodFill (std::size_t n, const std::vector<FilteredEdge>& edges, const Keep& keep)
{
  std::vector<std::vector<std::uint32_t>> adjacent (n);
  for (const FilteredEdge& edge : edges)
    if (keep (edge)) {
      adjacent[edge.source].push_back (edge.target);
      adjacent[edge.target].push_back (edge.source);
    }
  std::vector<std::uint32_t> component (n, NO_REGION);
  std::uint32_t next = 0;
  for (std::uint32_t start = 0; start < n; ++start) {
    if (component[start] != NO_REGION)
      continue;
    std::vector<std::uint32_t> stack{start};
    component[start] = next;
    while (!stack.empty()) {
      const std::uint32_t v = stack.back();
      stack.pop_back();
      for (const std::uint32_t w : adjacent[v])
        if (component[w] == NO_REGION) {
          component[w] = next;
          stack.push_back (w);
        }
    }
    ++next;
  }
  return component;
}

/** The flood-fill components of at least \a min_size vertices; others NO_REGION. */
std::vector<std::uint32_t>
bigComponents (std::vector<std::uint32_t> component, std::size_t min_size)
{
  std::map<std::uint32_t, std::size_t> sizes;
  for (const std::uint32_t c : component)
    ++sizes[c];
  for (std::uint32_t& c : component)
    if (sizes[c] < min_size)
      c = NO_REGION;
  return component;
}

/** A random graph: \a n vertices, about \a degree edges each, values drawn from a
 * few levels (many ties) and some infinite. */
std::vector<FilteredEdge>
randomGraph (std::size_t n, double degree, std::mt19937& random)
{
  std::uniform_int_distribution<std::uint32_t> vertex (
      0, static_cast<std::uint32_t> (n - 1));
  std::uniform_int_distribution<int> level (0, 12);
  std::vector<FilteredEdge> edges;
  const auto num_edges =
      static_cast<std::size_t> (degree * static_cast<double> (n) / 2);
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  while (edges.size() < num_edges) {
    std::uint32_t a = vertex (random), b = vertex (random);
    if (a == b || !seen.insert ({std::min (a, b), std::max (a, b)}).second)
      continue;
    const int l = level (random);
    edges.push_back ({std::min (a, b), std::max (a, b), l == 12 ? INF : 0.5 * l});
  }
  return edges;
}

} // namespace

// The patches of every threshold and minimum size are the flood-fill components of
// the edges within the threshold, on random graphs with many ties.
TEST (ColorRegions, PatchesAreFloodFillComponents)
{
  std::mt19937 random (7);
  for (int trial = 0; trial < 60; ++trial) {
    const std::size_t n = 20 + 7 * trial;
    const std::vector<FilteredEdge> graph = randomGraph (n, 1.0 + 0.05 * trial, random);
    const std::vector<FilteredEdge> forest = homogeneityForest (n, graph);
    for (const double threshold : {0.0, 1.0, 2.5, 4.0, 6.0})
      for (const std::size_t min_size : {1, 2, 5}) {
        const ColorRegions regions =
            regionsAtThreshold (n, forest, threshold, min_size);
        const auto expected = bigComponents (
            floodFill (
                n, graph, [&] (const FilteredEdge& e) { return e.value <= threshold; }),
            min_size);
        ASSERT_EQ (partition (regions.region_of), partition (expected))
            << "trial " << trial << " threshold " << threshold << " min " << min_size;
        ASSERT_EQ (regions.lifetimes.size(), partition (expected).size());
        // Numbered by decreasing size.
        std::vector<std::size_t> sizes (regions.lifetimes.size(), 0);
        for (const std::uint32_t r : regions.region_of)
          if (r != NO_REGION)
            ++sizes[r];
        ASSERT_TRUE (std::is_sorted (sizes.rbegin(), sizes.rend()));
      }
  }
}

// The bars alive at any threshold are as many as the components of at least the
// minimum size there; each region's lifetime contains the threshold.
TEST (ColorRegions, BarsCountTheRegionsOfEveryThreshold)
{
  std::mt19937 random (11);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 30 + 5 * trial;
    const std::vector<FilteredEdge> graph = randomGraph (n, 1.5, random);
    const std::vector<FilteredEdge> forest = homogeneityForest (n, graph);
    const std::size_t min_size = 1 + trial % 4;
    const ColorRegions any = regionsAtThreshold (n, forest, 0.0, min_size);
    for (double t = 0.0; t <= 6.0; t += 0.25) {
      std::size_t alive = 0;
      for (const PersistenceInterval& bar : any.bars)
        alive += bar.birth <= t && t < bar.death;
      const ColorRegions at_t = regionsAtThreshold (n, forest, t, min_size);
      ASSERT_EQ (alive, at_t.lifetimes.size()) << "trial " << trial << " t " << t;
      ASSERT_EQ (at_t.bars.size(), any.bars.size());
      for (const RegionLifetime& lifetime : at_t.lifetimes) {
        ASSERT_LE (lifetime.birth, t);
        ASSERT_GT (lifetime.death, t);
      }
    }
  }
}

// A path 0-1-2-3-4 | 5 | 6-7-8-9-10 of red, then a lone orange-ish vertex, then
// blue: the small patch {5} joins the region of the closer mean colour, whichever
// side it is on; an isolated small patch stays out.
TEST (ColorRegions, SmallPatchesJoinTheMostSimilarNeighbour)
{
  const LabColor red{50.0f, 60.0f, 40.0f}, blue{40.0f, 10.0f, -50.0f};
  for (const bool near_red : {true, false}) {
    std::vector<LabColor> colors (12, red);
    for (std::size_t v = 6; v <= 10; ++v)
      colors[v] = blue;
    colors[5] =
        near_red ? LabColor{50.0f, 50.0f, 35.0f} : LabColor{42.0f, 15.0f, -40.0f};
    colors[11] = red; // isolated
    std::vector<FilteredEdge> graph;
    for (std::uint32_t v = 0; v + 1 <= 9; ++v)
      graph.push_back (
          {v, v + 1, static_cast<double> (deltaE76 (colors[v], colors[v + 1]))});
    graph.push_back ({9, 10, 0.0});
    const std::vector<FilteredEdge> forest = homogeneityForest (12, graph);
    ColorRegions regions = regionsAtThreshold (12, forest, 3.0, 3);
    ASSERT_EQ (regions.lifetimes.size(), 2u);
    EXPECT_EQ (regions.region_of[5], NO_REGION);
    mergeSmallRegions (graph, forest, colors, 3.0, 3, INF, regions);
    ASSERT_EQ (regions.lifetimes.size(), 2u);
    EXPECT_EQ (regions.region_of[5], regions.region_of[near_red ? 4 : 6]);
    EXPECT_EQ (regions.region_of[11], NO_REGION);
  }
}

// A path 0-1-2-3-4 | 5 | 6-7-8-9-10 of red, a green speck, then blue, and two
// isolated points beside vertex 0, one red and one green: within the limit of 30
// Delta E, the speck is left out (no region); with no limit it joins its most
// similar neighbour. The isolated points are returned for attachIsolatedPoints(),
// the speck is not, and they join the most similar of their nearest region points.
TEST (ColorRegions, SpecksOfAnotherColourAreLeftOut)
{
  const LabColor red{50.0f, 60.0f, 40.0f}, blue{40.0f, 10.0f, -50.0f},
      green{60.0f, -60.0f, 50.0f};
  std::vector<LabColor> colors (13, red);
  for (std::size_t v = 6; v <= 10; ++v)
    colors[v] = blue;
  colors[5] = colors[12] = green;
  std::vector<Point3d> points (13);
  for (std::size_t v = 0; v <= 10; ++v)
    points[v] = {static_cast<double> (v), 0.0, 0.0};
  points[11] = {0.0, 5.0, 0.0};
  points[12] = {10.0, -5.0, 0.0};
  std::vector<FilteredEdge> graph;
  for (std::uint32_t v = 0; v < 10; ++v)
    graph.push_back (
        {v, v + 1, static_cast<double> (deltaE76 (colors[v], colors[v + 1]))});
  const std::vector<FilteredEdge> forest = homogeneityForest (13, graph);
  for (const double limit : {30.0, INF}) {
    ColorRegions regions = regionsAtThreshold (13, forest, 3.0, 3);
    const std::vector<std::uint32_t> isolated =
        mergeSmallRegions (graph, forest, colors, 3.0, 3, limit, regions);
    EXPECT_EQ (isolated, (std::vector<std::uint32_t>{11, 12}));
    attachIsolatedPoints (points, colors, isolated, 8, 1, regions);
    ASSERT_EQ (regions.lifetimes.size(), 2u);
    EXPECT_EQ (regions.region_of[11], regions.region_of[0]);
    EXPECT_NE (regions.region_of[12], NO_REGION);
    if (limit == INF)
      EXPECT_EQ (regions.region_of[5], regions.region_of[4]); // red is nearer green
    else
      EXPECT_EQ (regions.region_of[5], NO_REGION);
  }
}

// Small patches that only touch each other gather into one; when together they
// reach the minimum size, they are a region (with birth = death = the threshold).
TEST (ColorRegions, SmallPatchesTogetherMakeARegion)
{
  std::vector<LabColor> colors (6);
  for (std::size_t v = 0; v < 6; ++v)
    colors[v] = {static_cast<float> (20 * v), 0.0f, 0.0f};
  std::vector<FilteredEdge> graph;
  for (std::uint32_t v = 0; v + 1 < 6; ++v)
    graph.push_back ({v, v + 1, 20.0});
  const std::vector<FilteredEdge> forest = homogeneityForest (6, graph);
  ColorRegions regions = regionsAtThreshold (6, forest, 5.0, 4);
  EXPECT_TRUE (regions.lifetimes.empty());
  mergeSmallRegions (graph, forest, colors, 5.0, 4, INF, regions);
  ASSERT_EQ (regions.lifetimes.size(), 1u);
  for (const std::uint32_t r : regions.region_of)
    EXPECT_EQ (r, 0u);
  EXPECT_EQ (regions.lifetimes[0].birth, 5.0);
  EXPECT_EQ (regions.lifetimes[0].death, 5.0);
}

// The second filtration: regions are the flood-fill components of the adjacent
// patches whose mean colours are within the threshold, on random patchings.
TEST (ColorRegions, RegionsAreComponentsOfSimilarAdjacentPatches)
{
  std::mt19937 random (3);
  std::uniform_real_distribution<float> channel (-40.0f, 40.0f);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 40 + 10 * trial;
    const std::vector<FilteredEdge> graph = randomGraph (n, 2.0, random);
    const std::vector<FilteredEdge> forest = homogeneityForest (n, graph);
    ColorRegions patches = regionsAtThreshold (n, forest, 2.0, 2);
    std::vector<LabColor> colors (n);
    for (auto& color : colors)
      color = {50.0f + channel (random), channel (random), channel (random)};
    const std::vector<FilteredEdge> patch_forest =
        regionColorForest (graph, colors, patches);
    // Brute force: mean colours, adjacency over finite edges, flood fill.
    const std::size_t k = patches.lifetimes.size();
    std::vector<std::array<double, 4>> sums (k, {0.0, 0.0, 0.0, 0.0});
    for (std::size_t v = 0; v < n; ++v)
      if (patches.region_of[v] != NO_REGION) {
        auto& s = sums[patches.region_of[v]];
        s[0] += colors[v].l, s[1] += colors[v].a, s[2] += colors[v].b, s[3] += 1.0;
      }
    const auto mean = [&] (std::uint32_t p) {
      return LabColor{static_cast<float> (sums[p][0] / sums[p][3]),
                      static_cast<float> (sums[p][1] / sums[p][3]),
                      static_cast<float> (sums[p][2] / sums[p][3])};
    };
    std::vector<FilteredEdge> patch_graph;
    for (const FilteredEdge& edge : graph) {
      const std::uint32_t a = patches.region_of[edge.source],
                          b = patches.region_of[edge.target];
      if (a != b && a != NO_REGION && b != NO_REGION && std::isfinite (edge.value))
        patch_graph.push_back (
            {a, b, static_cast<double> (deltaE76 (mean (a), mean (b)))});
    }
    for (const double threshold : {5.0, 15.0, 30.0, 60.0}) {
      const ColorRegions regions =
          mergeSimilarRegions (patches, patch_forest, threshold);
      const auto patch_component = floodFill (
          k, patch_graph, [&] (const FilteredEdge& e) { return e.value <= threshold; });
      std::vector<std::uint32_t> expected (n, NO_REGION);
      for (std::size_t v = 0; v < n; ++v)
        if (patches.region_of[v] != NO_REGION)
          expected[v] = patch_component[patches.region_of[v]];
      ASSERT_EQ (partition (regions.region_of), partition (expected))
          << "trial " << trial << " threshold " << threshold;
      for (const RegionLifetime& lifetime : regions.lifetimes) {
        ASSERT_LE (lifetime.birth, threshold);
        ASSERT_GT (lifetime.death, threshold);
      }
    }
  }
}

// The automatic threshold: the middle of the longest step of two regions or more
// when it is clear, otherwise of the finest stable one.
TEST (ColorRegions, ChoosesTheMiddleOfTheLongestStep)
{
  // Four patches: two merge at 3 (noise), one at 40; the last never. Steps over
  // [2, 100]: 3 regions [2, 3), 2 regions [3, 40), 1 region [40, 100).
  const PersistenceDiagram bars{
      {0, 0.0, 3.0}, {0, 0.0, 40.0}, {0, 0.0, INF}, {0, 0.0, 1.0}};
  // The step taken and its middle.
  const auto expectStep = [] (const ColorThresholdChoice& choice,
                              std::size_t num_regions,
                              double low,
                              double high,
                              bool clear) {
    EXPECT_EQ (choice.num_regions, num_regions);
    EXPECT_DOUBLE_EQ (choice.low, low);
    EXPECT_DOUBLE_EQ (choice.high, high);
    EXPECT_NEAR (choice.threshold, std::sqrt (low * high), 1e-12);
    EXPECT_EQ (choice.clear, clear);
  };
  expectStep (chooseColorThreshold (bars, 2.0, 100.0, 1.5, 10.0), 2, 3.0, 40.0, true);
  // No step of two regions long enough: the one-region step.
  const PersistenceDiagram close{{0, 0.0, 2.2}, {0, 0.0, INF}};
  const ColorThresholdChoice whole =
      chooseColorThreshold (close, 2.0, 100.0, 1.5, 10.0);
  EXPECT_EQ (whole.num_regions, 1u);
  EXPECT_DOUBLE_EQ (whole.low, 2.2);
  EXPECT_NEAR (whole.threshold, std::sqrt (220.0), 1e-12);
  // The count falls gradually (steps of a factor 1.2): the fallback, not clear.
  PersistenceDiagram gradual{{0, 0.0, INF}};
  for (double death = 2.0; death < 100.0; death *= 1.2)
    gradual.push_back ({0, 0.0, death});
  const ColorThresholdChoice guess =
      chooseColorThreshold (gradual, 2.0, 100.0, 1.5, 10.0);
  EXPECT_DOUBLE_EQ (guess.threshold, 10.0);
  EXPECT_FALSE (guess.clear);
  // Regions of close colours: 4 regions on [2.5, 7), 3 on [7, 11), 2 on [11, 33),
  // the last a little longer than the first but not clearly: the finest stable
  // step, the 4 regions, not the 2 left after the close colours merged.
  const PersistenceDiagram close_colors{
      {0, 0.0, 2.5}, {0, 0.0, 7.0}, {0, 0.0, 11.0}, {0, 0.0, 33.0}, {0, 0.0, INF}};
  expectStep (
      chooseColorThreshold (close_colors, 2.0, 40.0, 1.5, 10.0), 4, 2.5, 7.0, false);
  // Two splits of similar length: not clear.
  const PersistenceDiagram twice{{0, 0.0, 4.0}, {0, 0.0, 8.0}, {0, 0.0, INF}};
  const ColorThresholdChoice unclear =
      chooseColorThreshold (twice, 2.0, 8.0, 1.5, 10.0);
  EXPECT_EQ (unclear.num_regions, 3u);
  EXPECT_FALSE (unclear.clear);
}
