// PersistentRegionGrowingRGB on clouds whose regions are known by construction:
// coloured quadrants of a plane, a fold whose two faces only the normals separate,
// shuffled inputs and thread counts, the thesis' filtration by distance, and its
// refusals of bad input.

#include <pcl/tda/common/cielab.h>
#include <pcl/tda/segmentation/homogeneity_graph.h>
#include <pcl/tda/segmentation/persistent_region_growing_rgb.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <vector>

using namespace pcl::tda;
using Cloud = pcl::PointCloud<pcl::PointXYZRGB>;
using Normals = pcl::PointCloud<pcl::Normal>;
using RegionGrowing = PersistentRegionGrowingRGB<pcl::PointXYZRGB, pcl::Normal>;

namespace {

constexpr float SPACING = 0.005f;

/** The four colours of the quadrants: the first two 13.8 Delta E apart, the others
 * 76 to 119. */
const std::uint8_t QUADRANT_COLORS[4][3] = {
    {200, 60, 50}, {200, 90, 60}, {60, 90, 200}, {70, 160, 80}};
/** The same with the first two 25.3 Delta E apart. */
const std::uint8_t DISTINCT_COLORS[4][3] = {
    {200, 60, 50}, {200, 110, 60}, {60, 90, 200}, {70, 160, 80}};

/** A 40 x 40 grid of spacing 5 mm in the plane z = 0, jittered, each quadrant in its
 * colour with Gaussian noise of \a noise levels; \a truth gets the quadrant of each
 * point. Normals (0, 0, +-1) at random signs. */
void
quadrantCloud (Cloud& cloud,
               Normals& normals,
               std::vector<int>& truth,
               float noise,
               std::uint32_t seed,
               const std::uint8_t (*colors)[3] = QUADRANT_COLORS)
{
  std::mt19937 random (seed);
  std::normal_distribution<float> color_noise (0.0f, noise);
  std::uniform_real_distribution<float> jitter (-0.2f * SPACING, 0.2f * SPACING);
  std::bernoulli_distribution flip (0.5);
  cloud.clear();
  normals.clear();
  truth.clear();
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const int quadrant = (i >= 20) + 2 * (j >= 20);
      pcl::PointXYZRGB point;
      point.x = i * SPACING + jitter (random);
      point.y = j * SPACING + jitter (random);
      point.z = 0.0f;
      const auto channel = [&] (std::uint8_t value) {
        return static_cast<std::uint8_t> (
            std::clamp (std::lround (value + color_noise (random)), 0L, 255L));
      };
      point.r = channel (colors[quadrant][0]);
      point.g = channel (colors[quadrant][1]);
      point.b = channel (colors[quadrant][2]);
      cloud.push_back (point);
      pcl::Normal normal (0.0f, 0.0f, flip (random) ? 1.0f : -1.0f);
      normals.push_back (normal);
      truth.push_back (quadrant);
    }
}

/** The regions as a set of sets of input indices. */
std::set<std::vector<pcl::index_t>>
asSets (const std::vector<pcl::PointIndices>& regions)
{
  std::set<std::vector<pcl::index_t>> sets;
  for (const auto& region : regions)
    sets.insert (region.indices);
  return sets;
}

std::vector<pcl::PointIndices>
grow (RegionGrowing& growing, const Cloud::ConstPtr& cloud)
{
  growing.setInputCloud (cloud);
  std::vector<pcl::PointIndices> regions;
  growing.extract (regions);
  return regions;
}

/** The radius graph of \a points (neighborGraph()). */
std::vector<FilteredEdge>
radiusGraph (const std::vector<Point3d>& points, double radius)
{
  std::vector<FilteredEdge> graph;
  ComplexSize size;
  EXPECT_TRUE (neighborGraph (
      points, radius, 1, MemoryBudget{std::size_t (1) << 30, 24, 0}, graph, size));
  return graph;
}

/** Expects every edge of \a graph once, ends in increasing order, and the edges
 * added after the first \a radius_edges (those of the radius graph) longer than
 * \a radius. */
void
expectEdgesOnceAddedBeyond (const std::vector<FilteredEdge>& graph,
                            std::size_t radius_edges,
                            double radius)
{
  std::set<std::pair<SimplexIndex, SimplexIndex>> pairs;
  for (std::size_t e = 0; e < graph.size(); ++e) {
    EXPECT_TRUE (pairs.insert ({graph[e].source, graph[e].target}).second);
    EXPECT_LT (graph[e].source, graph[e].target);
    if (e >= radius_edges) {
      EXPECT_GT (graph[e].value, radius);
    }
  }
}

} // namespace

/** The share of the points whose region is that of the truth, with each region
 * matched to the quadrant it overlaps most. */
double
agreement (const std::vector<pcl::PointIndices>& regions, const std::vector<int>& truth)
{
  std::size_t agreeing = 0;
  for (const auto& region : regions) {
    std::map<int, std::size_t> overlap;
    for (const auto index : region.indices)
      ++overlap[truth[index]];
    std::size_t best = 0;
    for (const auto& [quadrant, count] : overlap)
      best = std::max (best, count);
    agreeing += best;
  }
  return static_cast<double> (agreeing) / static_cast<double> (truth.size());
}

// The four quadrants exactly, noise-free and with colour noise, with and without the
// second filtration, and with the automatic threshold; raw colours (the median
// filter may move a point at a corner where three colours meet).
TEST (PersistentRegionGrowingRGB, FindsTheColouredQuadrants)
{
  for (const float noise : {0.0f, 3.0f}) {
    Cloud::Ptr cloud (new Cloud);
    Normals::Ptr normals (new Normals);
    std::vector<int> truth;
    quadrantCloud (*cloud, *normals, truth, noise, 5);
    std::set<std::vector<pcl::index_t>> expected;
    for (int q = 0; q < 4; ++q) {
      std::vector<pcl::index_t> members;
      for (std::size_t i = 0; i < truth.size(); ++i)
        if (truth[i] == q)
          members.push_back (static_cast<pcl::index_t> (i));
      expected.insert (members);
    }
    for (const int mode : {0, 1, 2}) {
      RegionGrowing growing;
      growing.setMaxDistance (1.5 * SPACING);
      growing.setInputNormals (normals);
      growing.setMinClusterSize (20);
      growing.setColorSmoothing (false);
      growing.setRegionColorThreshold (mode == 0 ? 0.0 : 8.0);
      growing.setAutoColorThreshold (mode == 2);
      if (mode == 2)
        growing.setRegionColorThreshold (40.0);
      const auto regions = grow (growing, cloud);
      EXPECT_EQ (asSets (regions), expected) << "noise " << noise << " mode " << mode;
      ASSERT_EQ (growing.getRegionLifetimes().size(), regions.size());
      EXPECT_EQ (growing.getNumSkippedPoints(), 0u);
      if (mode == 2) {
        EXPECT_GT (growing.getChosenRegionColorThreshold(), 2.3);
        EXPECT_LT (growing.getChosenRegionColorThreshold(), 10.0);
      }
    }
  }
}

// With the median filter and strong colour noise (RGB sigma 8, about 6 Delta E per
// point): four regions 25 Delta E or more apart, at most a few points astray.
TEST (PersistentRegionGrowingRGB, FiltersStrongColourNoise)
{
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    Cloud::Ptr cloud (new Cloud);
    Normals::Ptr normals (new Normals);
    std::vector<int> truth;
    quadrantCloud (*cloud, *normals, truth, 8.0f, seed, DISTINCT_COLORS);
    RegionGrowing growing;
    growing.setMaxDistance (2.0 * SPACING);
    growing.setInputNormals (normals);
    growing.setMinClusterSize (20);
    growing.setAutoColorThreshold (true);
    growing.setRegionColorThreshold (40.0);
    const auto regions = grow (growing, cloud);
    EXPECT_EQ (regions.size(), 4u) << "seed " << seed;
    EXPECT_GT (agreement (regions, truth), 0.99) << "seed " << seed;
  }
}

// Same regions, in the same order, for shuffled inputs and 1 or 2 threads.
TEST (PersistentRegionGrowingRGB, IndependentOfInputOrderAndThreads)
{
  Cloud::Ptr cloud (new Cloud);
  Normals::Ptr normals (new Normals);
  std::vector<int> truth;
  quadrantCloud (*cloud, *normals, truth, 8.0f, 9);
  RegionGrowing reference;
  reference.setMaxDistance (2.0 * SPACING);
  reference.setInputNormals (normals);
  reference.setMinClusterSize (10);
  reference.setAutoColorThreshold (true);
  reference.setRegionColorThreshold (40.0);
  reference.setNumberOfThreads (1);
  const auto expected = grow (reference, cloud);
  ASSERT_GE (expected.size(), 4u);

  std::mt19937 random (1);
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<std::size_t> order (cloud->size());
    std::iota (order.begin(), order.end(), 0);
    std::shuffle (order.begin(), order.end(), random);
    Cloud::Ptr shuffled (new Cloud);
    Normals::Ptr shuffled_normals (new Normals);
    for (const std::size_t i : order) {
      shuffled->push_back ((*cloud)[i]);
      shuffled_normals->push_back ((*normals)[i]);
    }
    RegionGrowing growing;
    growing.setMaxDistance (2.0 * SPACING);
    growing.setInputNormals (shuffled_normals);
    growing.setMinClusterSize (10);
    growing.setAutoColorThreshold (true);
    growing.setRegionColorThreshold (40.0);
    growing.setNumberOfThreads (1 + trial % 2);
    const auto regions = grow (growing, shuffled);
    ASSERT_EQ (regions.size(), expected.size());
    for (std::size_t k = 0; k < regions.size(); ++k) {
      std::vector<pcl::index_t> mapped;
      for (const auto index : regions[k].indices)
        mapped.push_back (static_cast<pcl::index_t> (order[index]));
      std::sort (mapped.begin(), mapped.end());
      EXPECT_EQ (mapped, expected[k].indices) << "trial " << trial << " region " << k;
    }
    EXPECT_EQ (growing.getChosenRegionColorThreshold(),
               reference.getChosenRegionColorThreshold());
  }
}

// A fold of one colour: two perpendicular faces. With normals, two regions (the
// angle test cuts the fold); without, one.
TEST (PersistentRegionGrowingRGB, NormalsSeparateTheFacesOfAFold)
{
  Cloud::Ptr cloud (new Cloud);
  Normals::Ptr normals (new Normals);
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) {
      pcl::PointXYZRGB point;
      point.r = 120, point.g = 120, point.b = 60;
      point.x = i * SPACING, point.y = j * SPACING, point.z = 0.0f; // floor
      cloud->push_back (point);
      normals->push_back (pcl::Normal (0.0f, 0.0f, 1.0f));
      point.x = -SPACING, point.y = j * SPACING, point.z = (i + 1) * SPACING; // wall
      cloud->push_back (point);
      normals->push_back (pcl::Normal (1.0f, 0.0f, 0.0f));
    }
  RegionGrowing growing;
  growing.setMaxDistance (1.5 * SPACING);
  growing.setInputNormals (normals);
  growing.setNormalAngleThreshold (30.0);
  EXPECT_EQ (grow (growing, cloud).size(), 2u);
  RegionGrowing colour_only;
  colour_only.setMaxDistance (1.5 * SPACING);
  EXPECT_EQ (grow (colour_only, cloud).size(), 1u);
}

// The thesis' filtration by distance gives the same regions; its diagram has one
// essential bar per component of the similar pairs.
TEST (PersistentRegionGrowingRGB, DistanceFiltrationGivesTheSameRegions)
{
  Cloud::Ptr cloud (new Cloud);
  Normals::Ptr normals (new Normals);
  std::vector<int> truth;
  quadrantCloud (*cloud, *normals, truth, 0.0f, 3);
  RegionGrowing by_color, by_distance;
  for (RegionGrowing* growing : {&by_color, &by_distance}) {
    growing->setMaxDistance (1.5 * SPACING);
    growing->setRegionColorThreshold (0.0);
  }
  by_distance.setFiltration (RegionGrowing::Filtration::DISTANCE);
  by_distance.setFiltrationSteps (10);
  const auto expected = grow (by_color, cloud);
  EXPECT_EQ (asSets (grow (by_distance, cloud)), asSets (expected));
  std::size_t essential = 0;
  for (const auto& interval : by_distance.getPersistenceDiagram()) {
    essential += interval.isEssential();
    if (!interval.isEssential()) {
      // Stepped: deaths are multiples of max distance / 10.
      const double steps = interval.death / (0.15 * SPACING);
      EXPECT_NEAR (steps, std::round (steps), 1e-6);
    }
  }
  EXPECT_EQ (essential, 4u);
}

// Small regions labelled as noise instead of merged.
TEST (PersistentRegionGrowingRGB, SmallRegionsAsNoise)
{
  Cloud::Ptr cloud (new Cloud);
  Normals::Ptr normals (new Normals);
  std::vector<int> truth;
  quadrantCloud (*cloud, *normals, truth, 0.0f, 3);
  const pcl::PointXYZRGB quadrant_color = (*cloud)[0];
  const auto lab = [] (const pcl::PointXYZRGB& p) {
    return pcl::tda::rgbToLab (p.r, p.g, p.b);
  };
  RegionGrowing growing;
  growing.setMaxDistance (1.5 * SPACING);
  growing.setMinClusterSize (5);
  growing.setColorSmoothing (false);
  const auto covered = [&] {
    std::size_t count = 0;
    for (const auto& region : grow (growing, cloud))
      count += region.indices.size();
    return count;
  };
  // A speck a little off the quadrant's colour joins it.
  (*cloud)[0].r = static_cast<std::uint8_t> (quadrant_color.r / 2 + 64);
  const float off = pcl::tda::deltaE76 (lab ((*cloud)[0]), lab (quadrant_color));
  ASSERT_GT (off, 3.0 * growing.getColorThreshold());
  ASSERT_LT (off, growing.getMaxMergeColorDifference());
  EXPECT_EQ (covered(), cloud->size());
  // A cyan speck, of another colour than every quadrant, is left out, unless the
  // limit is lifted.
  (*cloud)[0].r = 0, (*cloud)[0].g = 255, (*cloud)[0].b = 255;
  EXPECT_EQ (covered(), cloud->size() - 1);
  growing.setMaxMergeColorDifference (INFINITY);
  EXPECT_EQ (covered(), cloud->size());
  growing.setMergeSmallRegions (false);
  EXPECT_EQ (covered(), cloud->size() - 1);
}

// Bad input: clear errors, no regions.
TEST (PersistentRegionGrowingRGB, RefusesBadInput)
{
  Cloud::Ptr cloud (new Cloud);
  Normals::Ptr normals (new Normals);
  std::vector<int> truth;
  quadrantCloud (*cloud, *normals, truth, 0.0f, 3);
  const auto refused = [&cloud] (const std::function<void (RegionGrowing&)>& set) {
    RegionGrowing growing;
    growing.setMaxDistance (1.5 * SPACING);
    set (growing);
    return grow (growing, cloud).empty() && !growing.getColoredCloud();
  };
  EXPECT_FALSE (refused ([] (RegionGrowing&) {}));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) { g.setMaxDistance (0.0); }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) { g.setMaxDistance (NAN); }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) { g.setColorThreshold (0.0); }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) { g.setColorThreshold (-1.0); }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) { g.setRegionColorThreshold (-1.0); }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) { g.setMaxMergeColorDifference (0.0); }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) { g.setMaxMergeColorDifference (NAN); }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) { g.setImageNeighborRatio (-0.1); }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) { g.setImageNeighborRatio (INFINITY); }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) {
    g.setAutoColorThreshold (true);
    g.setRegionColorThreshold (0.0);
  }));
  EXPECT_TRUE (refused ([&normals] (RegionGrowing& g) {
    g.setInputNormals (normals);
    g.setNormalAngleThreshold (0.0);
  }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) {
    g.setMinClusterSize (10);
    g.setMaxClusterSize (5);
  }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) { g.setMemoryLimit (1000); }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) {
    g.setFiltration (static_cast<RegionGrowing::Filtration> (7)); // was DISTANCE
  }));
  // Indices past the cloud (a crash) or repeated.
  EXPECT_TRUE (refused ([] (RegionGrowing& g) {
    g.setIndices (pcl::IndicesPtr (new pcl::Indices{0, 1, 50000000}));
  }));
  EXPECT_TRUE (refused ([] (RegionGrowing& g) {
    g.setIndices (pcl::IndicesPtr (new pcl::Indices{0, 1, 1}));
  }));
  Normals::Ptr short_normals (new Normals (*normals));
  short_normals->resize (10);
  EXPECT_TRUE (refused (
      [&short_normals] (RegionGrowing& g) { g.setInputNormals (short_normals); }));
  // NaN positions and normals: those points are left out, and counted.
  Normals::Ptr nan_normals (new Normals (*normals));
  (*nan_normals)[3].normal_x = NAN;
  (*cloud)[7].x = NAN;
  RegionGrowing growing;
  growing.setMaxDistance (1.5 * SPACING);
  growing.setInputNormals (nan_normals);
  std::size_t covered = 0;
  for (const auto& region : grow (growing, cloud))
    covered += region.indices.size();
  EXPECT_EQ (growing.getNumSkippedPoints(), 2u);
  EXPECT_EQ (covered, cloud->size() - 2);
  // An empty cloud.
  RegionGrowing empty;
  empty.setMaxDistance (1.0);
  EXPECT_TRUE (grow (empty, Cloud::Ptr (new Cloud)).empty());
}

// getColoredCloud(): one colour per region, white elsewhere, input positions.
TEST (PersistentRegionGrowingRGB, ColoredCloud)
{
  Cloud::Ptr cloud (new Cloud);
  Normals::Ptr normals (new Normals);
  std::vector<int> truth;
  quadrantCloud (*cloud, *normals, truth, 0.0f, 3);
  RegionGrowing growing;
  growing.setMaxDistance (1.5 * SPACING);
  const auto regions = grow (growing, cloud);
  const auto colored = growing.getColoredCloud();
  ASSERT_TRUE (colored);
  ASSERT_EQ (colored->size(), cloud->size());
  std::set<std::uint32_t> colors;
  for (const auto& region : regions) {
    const auto& first = (*colored)[region.indices.front()];
    colors.insert (first.rgba);
    for (const auto index : region.indices) {
      EXPECT_EQ ((*colored)[index].rgba, first.rgba);
      EXPECT_EQ ((*colored)[index].x, (*cloud)[index].x);
    }
  }
  EXPECT_EQ (colors.size(), regions.size());
  // A smaller input set for the next frame: the picture stays that of the regions
  // found, on their cloud (it indexed the new input with them and crashed).
  Cloud::Ptr next (new Cloud);
  next->resize (10);
  growing.setInputCloud (next);
  const auto again = growing.getColoredCloud();
  ASSERT_TRUE (again);
  ASSERT_EQ (again->size(), cloud->size());
  for (std::size_t i = 0; i < cloud->size(); ++i)
    EXPECT_EQ ((*again)[i].rgba, (*colored)[i].rgba);
}

// Rows of points 1 mm apart along, 1 cm across, as on the far side of a depth frame:
// the radius graph of 3 mm cuts them into strips, the nearest-neighbour fallback
// joins them, adding only edges longer than the radius, each once.
TEST (PersistentRegionGrowingRGB, MinNeighborsJoinSparseRows)
{
  Cloud::Ptr cloud (new Cloud);
  for (int row = 0; row < 4; ++row)
    for (int i = 0; i < 60; ++i) {
      pcl::PointXYZRGB point;
      point.x = 0.001f * i;
      point.y = 0.01f * row;
      point.z = 0.0f;
      point.r = 90, point.g = 140, point.b = 60;
      cloud->push_back (point);
    }
  RegionGrowing growing;
  growing.setMaxDistance (0.003);
  growing.setMinClusterSize (10);
  EXPECT_EQ (grow (growing, cloud).size(), 4u);
  growing.setMinNeighbors (5);
  EXPECT_EQ (grow (growing, cloud).size(), 1u);

  std::vector<Point3d> points;
  for (const auto& p : *cloud)
    points.push_back ({p.x, p.y, p.z});
  std::vector<FilteredEdge> graph = radiusGraph (points, 0.003);
  const std::size_t radius_edges = graph.size();
  addNearestNeighbors (points, 0.003, 5, 0, graph);
  ASSERT_GT (graph.size(), radius_edges);
  expectEdgesOnceAddedBeyond (graph, radius_edges, 0.003);
}

// An organized frame: 8 rows of a surface 1 mm apart along and 1 cm apart across at
// a range of about 1 m (a surface seen at a grazing angle), then 4 rows of another
// surface of the same colour 20 cm behind it, with a lost pixel. The radius graph of
// 3 mm cuts the rows into 12 strips; the image neighbours within 2% of the range
// join the rows of each surface but not the two surfaces; an unorganized copy of
// the points (also one written as a column) is not affected. Edges are added once each,
// longer than the radius.
TEST (PersistentRegionGrowingRGB, ImageNeighborsJoinTheRowsOfADepthFrame)
{
  const std::size_t width = 60, height = 12;
  Cloud::Ptr frame (new Cloud (width, height));
  for (std::size_t row = 0; row < height; ++row)
    for (std::size_t column = 0; column < width; ++column) {
      pcl::PointXYZRGB& point = frame->at (column, row);
      point.x = 0.001f * column;
      point.y = -0.3f;
      point.z = row < 8 ? 1.0f + 0.01f * row : 1.3f + 0.01f * row;
      point.r = 90, point.g = 140, point.b = 60;
    }
  frame->at (30, 3).x = std::numeric_limits<float>::quiet_NaN();
  RegionGrowing growing;
  growing.setMaxDistance (0.003);
  growing.setMinClusterSize (10);
  EXPECT_EQ (grow (growing, frame).size(), 12u);
  growing.setImageNeighborRatio (0.02);
  const auto regions = grow (growing, frame);
  ASSERT_EQ (regions.size(), 2u);
  EXPECT_EQ (regions[0].indices.size(), 8 * width - 1);
  EXPECT_EQ (regions[1].indices.size(), 4 * width);
  Cloud::Ptr unorganized (new Cloud (*frame));
  unorganized->width = static_cast<std::uint32_t> (unorganized->size());
  unorganized->height = 1;
  EXPECT_EQ (grow (growing, unorganized).size(), 12u);
  // Nor a column (WIDTH 1): a list of points, here column by column, whose
  // neighbours in the list (across the rows) joined before.
  Cloud::Ptr column (new Cloud);
  for (std::size_t x = 0; x < width; ++x)
    for (std::size_t row = 0; row < height; ++row)
      column->push_back (frame->at (x, row));
  column->width = 1;
  column->height = static_cast<std::uint32_t> (column->size());
  EXPECT_EQ (grow (growing, column).size(), 12u);

  // The graph: the image neighbours, then the nearest points, each edge once.
  std::vector<Point3d> points;
  std::vector<SimplexIndex> vertex_of_pixel;
  for (const auto& p : *frame) {
    vertex_of_pixel.push_back (std::isfinite (p.x) ? points.size() : INVALID_SIMPLEX);
    if (std::isfinite (p.x))
      points.push_back ({p.x, p.y, p.z});
  }
  std::vector<FilteredEdge> graph = radiusGraph (points, 0.003);
  const std::size_t radius_edges = graph.size();
  addImageNeighbors (
      points, vertex_of_pixel, width, {0.0, 0.0, 0.0}, 0.003, 0.02, graph);
  // From every pixel to the three below it, within each surface (7 + 3 pairs of
  // rows), but at the rows' ends and around the lost pixel.
  EXPECT_EQ (graph.size() - radius_edges, 10 * (3 * width - 2) - 6);
  addNearestNeighbors (points, 0.003, 5, 0, graph);
  expectEdgesOnceAddedBeyond (graph, radius_edges, 0.003);
}

// medianSmoothedColors() with no limit on the change: each vertex takes, channel by
// channel, the median of its own colour and its neighbours' (the upper middle value of
// an even count), computed here by sorting. Random graphs whose degrees (0-45) cover
// each way the function takes (up to 16 colours, up to 32, more); 1 and 2 threads.
TEST (PersistentRegionGrowingRGB, MedianSmoothingTakesTheMedianOfEachChannel)
{
  std::mt19937 random (23);
  std::uniform_real_distribution<float> channel (-100.0f, 100.0f);
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t num_vertices = 20 + random() % 80;
    std::vector<LabColor> colors (num_vertices);
    for (LabColor& color : colors)
      color = {channel (random), channel (random), channel (random)};
    std::vector<FilteredEdge> graph;
    for (SimplexIndex v = 0; v < num_vertices; ++v)
      for (SimplexIndex w = v + 1; w < num_vertices; ++w)
        if (random() % 100 < 3u + 2u * trial)
          graph.push_back ({v, w, 0.0});
    const NeighborLists lists = neighborLists (num_vertices, graph);
    const std::vector<LabColor> one = medianSmoothedColors (colors, lists, 1e9f, 1);
    const std::vector<LabColor> two = medianSmoothedColors (colors, lists, 1e9f, 2);
    for (SimplexIndex v = 0; v < num_vertices; ++v) {
      std::vector<SimplexIndex> members = {v};
      members.insert (members.end(),
                      lists.neighbors.begin() + lists.offsets[v],
                      lists.neighbors.begin() + lists.offsets[v + 1]);
      for (float LabColor::*part : {&LabColor::l, &LabColor::a, &LabColor::b}) {
        std::vector<float> values;
        for (const SimplexIndex member : members)
          values.push_back (colors[member].*part);
        std::sort (values.begin(), values.end());
        EXPECT_EQ (one[v].*part, values[values.size() / 2])
            << "trial " << trial << " vertex " << v << " of degree "
            << members.size() - 1;
        EXPECT_EQ (two[v].*part, one[v].*part);
      }
    }
  }
}

// A stripe two points wide across a 30 x 30 grid, its colour 11.8 Delta E from the
// rest, with noise of 2 per channel (3.2 Delta E per point on average); each point
// joined to those within 2 grid steps, so that most neighbours of a stripe point lie
// outside it. The median over the neighbours on the point's own side smooths the
// stripe almost as well as the rest: its mean error is under 2 Delta E and under 1.6
// times the rest's, for 12 seeds (with the median over every neighbour, the stripe's
// points mostly keep their raw colours: 2.2-3.4, 1.9-2.7 times the rest's).
TEST (PersistentRegionGrowingRGB, MedianSmoothingLeavesTheOtherSideOut)
{
  const LabColor outside{50.0f, 20.0f, 10.0f}, stripe{50.0f, 28.0f, 18.5f};
  constexpr int SIDE = 30;
  const auto inStripe = [] (int v) { return v % SIDE == 14 || v % SIDE == 15; };
  std::vector<FilteredEdge> graph;
  for (int v = 0; v < SIDE * SIDE; ++v)
    for (int w = v + 1; w < SIDE * SIDE; ++w) {
      const int di = v / SIDE - w / SIDE, dj = v % SIDE - w % SIDE;
      if (di * di + dj * dj <= 4)
        graph.push_back (
            {static_cast<SimplexIndex> (v), static_cast<SimplexIndex> (w), 0.0});
    }
  const NeighborLists lists = neighborLists (SIDE * SIDE, graph);
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    std::mt19937 random (seed);
    std::normal_distribution<float> noise (0.0f, 2.0f);
    std::vector<LabColor> colors;
    for (int v = 0; v < SIDE * SIDE; ++v) {
      const LabColor& truth = inStripe (v) ? stripe : outside;
      colors.push_back ({truth.l + noise (random),
                         truth.a + noise (random),
                         truth.b + noise (random)});
    }
    const std::vector<LabColor> smoothed =
        medianSmoothedColors (colors, lists, 7.5f, 1);
    double error_sum[2] = {0.0, 0.0};
    int count[2] = {0, 0};
    for (int v = 0; v < SIDE * SIDE; ++v) {
      error_sum[inStripe (v)] +=
          deltaE76 (smoothed[v], inStripe (v) ? stripe : outside);
      ++count[inStripe (v)];
    }
    const double outside_error = error_sum[0] / count[0];
    const double stripe_error = error_sum[1] / count[1];
    EXPECT_LT (stripe_error, 2.0) << "seed " << seed;
    EXPECT_LT (stripe_error, 1.6 * outside_error) << "seed " << seed;
  }
}
