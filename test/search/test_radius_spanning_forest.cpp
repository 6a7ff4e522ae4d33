#include <pcl/tda/common/spanning_forest.h>
#include <pcl/tda/search/radius_spanning_forest.h>

#include <gtest/gtest.h>

#include "search/grid_test_utils.h"

#include <cmath>

using namespace pcl::tda;
using namespace pcl::tda::test;

namespace {

/** Dense blobs far apart compared with their spacing, with duplicates and lattice
 * points whose distances tie: at a radius that spans several blobs the grid has far
 * more candidate pairs than the sparse threshold, so the forest takes several scales.
 */
std::vector<Point3d>
blobs (std::mt19937& random, std::size_t num_blobs, std::size_t per_blob)
{
  std::uniform_real_distribution<double> centre (-1.0, 1.0);
  std::normal_distribution<double> spread (0.0, 0.01);
  std::uniform_int_distribution<int> lattice (-3, 3);
  std::vector<Point3d> points;
  for (std::size_t b = 0; b < num_blobs; ++b) {
    const Point3d c{centre (random), centre (random), centre (random)};
    for (std::size_t i = 0; i < per_blob; ++i) {
      if (i % 5 == 0 && i > 0)
        points.push_back (points.back()); // a duplicate
      else if (i % 5 == 1)
        points.push_back ({c[0] + 0.004 * lattice (random),
                           c[1] + 0.004 * lattice (random),
                           c[2] + 0.004 * lattice (random)});
      else
        points.push_back (
            {c[0] + spread (random), c[1] + spread (random), c[2] + spread (random)});
    }
  }
  return points;
}

template <typename Accept>
std::vector<FilteredEdge>
forestOf (const std::vector<Point3d>& points,
          double radius,
          const Accept& accept,
          unsigned int threads,
          std::size_t& most_listed,
          std::size_t memory_limit = std::size_t{1} << 30)
{
  std::vector<FilteredEdge> forest;
  const MemoryBudget budget{memory_limit, 24, 0};
  most_listed =
      radiusGraphSpanningForest (points, radius, accept, threads, budget, forest);
  return forest;
}

} // namespace

// The spanning forest of the radius graph with a pair test is the minimum spanning
// forest of the brute-force graph with that test, for 1 and 2 threads.
TEST (RadiusSpanningForest, IsTheForestOfTheBruteForceGraphWithAPairTest)
{
  std::mt19937 random (5);
  for (unsigned int k = 0; k < 30; ++k) {
    const double radius = 0.1 + 0.02 * (k % 10);
    const std::vector<Point3d> points = randomPoints (random, 100 + 20 * k, radius);
    std::vector<FilteredEdge> edges = bruteForceEdges (points, radius, true);
    const auto expected = minimumSpanningForest (points.size(), edges);
    for (const unsigned int threads : {1u, 2u}) {
      std::size_t most_listed = 0;
      const auto forest = forestOf (points, radius, OddSum{}, threads, most_listed);
      expectSameEdges (forest, expected, "case " + std::to_string (k));
    }
  }
}

// At a radius far above the spacing the forest is found over several scales, from
// fewer listed edges than the graph has, and is still that of the whole graph,
// edge for edge (ties and duplicates included), with or without a pair test.
TEST (RadiusSpanningForest, SeveralScalesGiveTheForestOfTheWholeGraph)
{
  std::mt19937 random (11);
  for (unsigned int k = 0; k < 20; ++k) {
    const std::vector<Point3d> points = blobs (random, 2 + k % 4, 400 + 30 * k);
    const double radius = 0.3 + 0.1 * (k % 8);
    ASSERT_GT (spanningForestScales (points, radius, 0).size(), 2u) << "case " << k;
    for (const bool odd_sum : {false, true}) {
      std::vector<FilteredEdge> edges = bruteForceEdges (points, radius, odd_sum);
      const double graph_edges = static_cast<double> (edges.size());
      const auto expected = minimumSpanningForest (points.size(), edges);
      for (const unsigned int threads : {1u, 2u}) {
        std::size_t most_listed = 0;
        const auto forest =
            odd_sum ? forestOf (points, radius, OddSum{}, threads, most_listed)
                    : forestOf (points, radius, AcceptAllPairs{}, threads, most_listed);
        const std::string what = "case " + std::to_string (k) +
                                 (odd_sum ? ", odd sums" : "") + ", " +
                                 std::to_string (threads) + " threads";
        expectSameEdges (forest, expected, what);
        EXPECT_LT (static_cast<double> (most_listed), graph_edges) << what;
      }
    }
  }
}

// A scale whose edges are over the budget, or whose pairs across are too many to look
// at, is searched by Borůvka's rounds instead: the same forest, edge for edge, with
// ties, duplicates and a pair test, for 1 and 2 threads, holding one edge per point.
TEST (RadiusSpanningForest, OverTheBudgetBoruvkaGivesTheSameForest)
{
  std::mt19937 random (23);
  for (unsigned int k = 0; k < 12; ++k) {
    const std::vector<Point3d> points = blobs (random, 2 + k % 5, 300 + 40 * k);
    const double radius = 0.2 + 0.15 * (k % 6);
    for (const bool odd_sum : {false, true}) {
      std::vector<FilteredEdge> edges = bruteForceEdges (points, radius, odd_sum);
      const auto expected = minimumSpanningForest (points.size(), edges);
      for (const unsigned int threads : {1u, 2u})
        for (const std::size_t memory_limit : {std::size_t{0}, std::size_t{50000}}) {
          std::size_t most_listed = 0;
          const auto forest =
              odd_sum
                  ? forestOf (
                        points, radius, OddSum{}, threads, most_listed, memory_limit)
                  : forestOf (points,
                              radius,
                              AcceptAllPairs{},
                              threads,
                              most_listed,
                              memory_limit);
          const std::string what = "case " + std::to_string (k) +
                                   (odd_sum ? ", odd sums" : "") + ", " +
                                   std::to_string (threads) + " threads, limit " +
                                   std::to_string (memory_limit);
          expectSameEdges (forest, expected, what);
          EXPECT_LE (most_listed * 24, std::max (memory_limit, points.size() * 24))
              << what;
        }
    }
  }
}

// Two sheets 0.4 apart, at a radius that holds both: the pairs across are 4e8, too
// many to look at; Borůvka's searches join the sheets with the one shortest pair
// across, the one a brute-force search finds.
TEST (RadiusSpanningForest, LargeComponentsWithinTheRadiusJoinedByTheirShortestPair)
{
  std::mt19937 random (37);
  std::uniform_real_distribution<double> coordinate (0.0, 1.0);
  std::vector<Point3d> points;
  for (int i = 0; i < 40000; ++i)
    points.push_back ({coordinate (random), coordinate (random), i % 2 ? 0.0 : 0.4});
  std::size_t most_listed = 0;
  const auto forest = forestOf (points, 1.0, AcceptAllPairs{}, 0, most_listed);
  ASSERT_EQ (forest.size(), points.size() - 1);
  FilteredEdge across = NO_EDGE;
  for (std::uint32_t a = 0; a < points.size(); a += 2)
    for (std::uint32_t b = 1; b < points.size(); b += 2)
      if (std::abs (points[a][0] - points[b][0]) < 0.01 &&
          std::abs (points[a][1] - points[b][1]) < 0.01) {
        const FilteredEdge edge{
            std::min (a, b), std::max (a, b), distance (points[a], points[b])};
        across = std::min (across, edge, edgeFiltrationLess);
      }
  EXPECT_EQ (forest.back().source, across.source);
  EXPECT_EQ (forest.back().target, across.target);
  EXPECT_EQ (forest.back().value, across.value);
  EXPECT_LE (static_cast<double> (most_listed),
             SPANNING_FOREST_VISITS_PER_POINT * static_cast<double> (points.size()));
}

// Thousands of copies of a few points, among other points: the copies are joined
// first (20,000 copies of one point would be 2e8 pairs), as Kruskal joins them, and
// the forest is that of the whole graph, with or without a pair test.
TEST (RadiusSpanningForest, CopiesOfAPointAreJoinedFirst)
{
  std::mt19937 random (31);
  std::uniform_real_distribution<double> coordinate (0.0, 1.0);
  std::vector<Point3d> points;
  for (int i = 0; i < 600; ++i)
    points.push_back ({coordinate (random), coordinate (random), coordinate (random)});
  for (int i = 0; i < 4500; ++i) // copies of three of them, interleaved
    points.insert (points.begin() + random() % points.size(), points[i % 3]);
  for (const bool odd_sum : {false, true}) {
    std::vector<FilteredEdge> edges = bruteForceEdges (points, 0.2, odd_sum);
    const auto expected = minimumSpanningForest (points.size(), edges);
    std::size_t most_listed = 0;
    const auto forest = odd_sum
                            ? forestOf (points, 0.2, OddSum{}, 2, most_listed)
                            : forestOf (points, 0.2, AcceptAllPairs{}, 2, most_listed);
    expectSameEdges (forest, expected, odd_sum ? "odd sums" : "all pairs");
  }

  const std::vector<Point3d> copies (20000, Point3d{0.5, 0.5, 0.5});
  std::size_t most_listed = 0;
  const auto forest = forestOf (copies, 0.01, AcceptAllPairs{}, 0, most_listed);
  ASSERT_EQ (forest.size(), copies.size() - 1);
  for (SimplexIndex e = 0; e < forest.size(); ++e) {
    EXPECT_EQ (forest[e].source, 0u);
    EXPECT_EQ (forest[e].target, e + 1);
  }
  EXPECT_EQ (most_listed, 0u);
}
