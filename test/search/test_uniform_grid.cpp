#include <pcl/tda/common/spanning_forest.h>
#include <pcl/tda/search/radius_edges.h>
#include <pcl/tda/search/uniform_grid.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace pcl::tda;

namespace {

/** Random points with duplicates and lattice points whose distances hit the radius
 * exactly (spacing r / 2 on a grid), to exercise the test near the radius. */
std::vector<Point3d>
randomPoints (std::mt19937& random, std::size_t n, double radius)
{
  std::uniform_real_distribution<double> coordinate (-1.0, 1.0);
  std::uniform_int_distribution<int> lattice (-6, 6);
  std::vector<Point3d> points;
  while (points.size() < n) {
    const int kind = static_cast<int> (points.size() % 4);
    if (kind == 0 && !points.empty())
      points.push_back (points[random() % points.size()]); // a duplicate
    else if (kind == 1)
      points.push_back ({lattice (random) * radius / 2,
                         lattice (random) * radius / 2,
                         lattice (random) * radius / 2});
    else
      points.push_back (
          {coordinate (random), coordinate (random), coordinate (random)});
  }
  return points;
}

std::vector<FilteredEdge>
bruteForceEdges (const std::vector<Point3d>& points, double radius, bool odd_sum_only)
{
  std::vector<FilteredEdge> edges;
  for (SimplexIndex a = 0; a < points.size(); ++a)
    for (SimplexIndex b = a + 1; b < points.size(); ++b)
      if (withinRadius (points[a], points[b], radius) &&
          (!odd_sum_only || (a + b) % 2 == 1))
        edges.push_back ({a, b, distance (points[a], points[b])});
  std::sort (edges.begin(), edges.end(), edgeFiltrationLess);
  return edges;
}

void
expectSameEdges (const std::vector<FilteredEdge>& actual,
                 const std::vector<FilteredEdge>& expected,
                 const std::string& what)
{
  ASSERT_EQ (actual.size(), expected.size()) << what;
  for (std::size_t e = 0; e < actual.size(); ++e) {
    ASSERT_EQ (actual[e].source, expected[e].source) << what << " edge " << e;
    ASSERT_EQ (actual[e].target, expected[e].target) << what << " edge " << e;
    ASSERT_EQ (actual[e].value, expected[e].value) << what << " edge " << e;
  }
}

struct OddSum {
  bool
  operator() (SimplexIndex a, SimplexIndex b) const
  {
    return (a + b) % 2 == 1;
  }
};

} // namespace

// Every pair within the radius, once, with the one distance test, on 1 and 2
// threads; the candidate count bounds the edge count.
TEST (UniformGrid, RadiusEdgesEqualBruteForce)
{
  std::mt19937 random (11);
  for (unsigned int k = 0; k < 60; ++k) {
    const double radius = 0.05 + 0.01 * (k % 20);
    const std::vector<Point3d> points = randomPoints (random, 50 + 10 * k, radius);
    const UniformGrid grid (points, radius);
    for (const unsigned int threads : {1u, 2u}) {
      const auto offsets =
          countRadiusEdges (grid, points, radius, AcceptAllPairs{}, threads);
      EXPECT_GE (grid.numCandidatePairs(), offsets.back());
      std::vector<FilteredEdge> edges =
          listRadiusEdges (grid, points, radius, AcceptAllPairs{}, offsets, threads);
      sortEdges (edges, threads);
      expectSameEdges (edges,
                       bruteForceEdges (points, radius, false),
                       "case " + std::to_string (k) + " threads " +
                           std::to_string (threads));
      const auto odd = countRadiusEdges (grid, points, radius, OddSum{}, threads);
      std::vector<FilteredEdge> odd_edges =
          listRadiusEdges (grid, points, radius, OddSum{}, odd, threads);
      sortEdges (odd_edges, threads);
      expectSameEdges (odd_edges,
                       bruteForceEdges (points, radius, true),
                       "odd case " + std::to_string (k));
    }
  }
}

// The cells and candidate pairs are those of the half stencil: every pair of
// points in neighbouring cells is a candidate exactly once.
TEST (UniformGrid, CandidatePairsCoverNeighbouringCellsOnce)
{
  std::mt19937 random (3);
  const double cell = 0.2;
  const std::vector<Point3d> points = randomPoints (random, 400, cell);
  const UniformGrid grid (points, cell);
  std::vector<std::uint64_t> seen;
  std::size_t points_in_cells = 0;
  for (std::size_t c = 0; c < grid.numCells(); ++c) {
    points_in_cells += grid.cellSize (c);
    grid.forEachCandidatePair (c, [&] (std::uint32_t a, std::uint32_t b) {
      ASSERT_NE (a, b);
      seen.push_back ((std::uint64_t{std::min (a, b)} << 32) | std::max (a, b));
    });
  }
  EXPECT_EQ (points_in_cells, points.size());
  std::sort (seen.begin(), seen.end());
  EXPECT_EQ (std::adjacent_find (seen.begin(), seen.end()), seen.end());
  EXPECT_EQ (seen.size(), grid.numCandidatePairs());
  // Every pair within the cell size is a candidate.
  for (const auto& edge : bruteForceEdges (points, cell, false))
    EXPECT_TRUE (std::binary_search (
        seen.begin(), seen.end(), (std::uint64_t{edge.source} << 32) | edge.target));
}

// The spanning forest of the radius graph with a pair test is the minimum spanning
// forest of the brute-force graph with that test.
TEST (UniformGrid, RadiusGraphSpanningForestWithPairTest)
{
  std::mt19937 random (5);
  for (unsigned int k = 0; k < 30; ++k) {
    const double radius = 0.1 + 0.02 * (k % 10);
    const std::vector<Point3d> points = randomPoints (random, 100 + 20 * k, radius);
    std::vector<FilteredEdge> edges = bruteForceEdges (points, radius, true);
    const std::size_t expected_edges = edges.size();
    const auto expected = minimumSpanningForest (points.size(), edges);
    std::size_t num_graph_edges = 0;
    const auto forest =
        radiusGraphSpanningForest (points, radius, OddSum{}, 2, num_graph_edges);
    EXPECT_EQ (num_graph_edges, expected_edges);
    expectSameEdges (forest, expected, "case " + std::to_string (k));
  }
}

TEST (UniformGrid, RefusesBadCellSizes)
{
  const std::vector<Point3d> points{{0, 0, 0}, {1, 1, 1}};
  for (const double bad : {0.0,
                           -1.0,
                           std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity(),
                           1e-20})
    EXPECT_THROW (UniformGrid (points, bad), pcl::BadArgumentException) << bad;
  EXPECT_EQ (UniformGrid ({}, 1.0).numCells(), 0u);
}
