#include <pcl/tda/search/radius_edges.h>
#include <pcl/tda/search/uniform_grid.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include "search/grid_test_utils.h"
#include <omp.h>

#include <algorithm>
#include <random>

using namespace pcl::tda;
using namespace pcl::tda::test;

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
      const auto counts =
          countRadiusEdges (grid, points, radius, AcceptAllPairs{}, threads);
      EXPECT_GE (grid.numCandidatePairs(), counts.offsets.back());
      std::vector<FilteredEdge> edges = listRadiusEdges (
          grid, points, radius, AcceptAllPairs{}, counts.offsets, threads);
      sortEdges (edges, threads);
      expectSameEdges (edges,
                       bruteForceEdges (points, radius, false),
                       "case " + std::to_string (k) + " threads " +
                           std::to_string (threads));
      const auto odd = countRadiusEdges (grid, points, radius, OddSum{}, threads);
      std::vector<FilteredEdge> odd_edges =
          listRadiusEdges (grid, points, radius, OddSum{}, odd.offsets, threads);
      sortEdges (odd_edges, threads);
      expectSameEdges (odd_edges,
                       bruteForceEdges (points, radius, true),
                       "odd case " + std::to_string (k));
    }
  }
}

namespace {

/** The cells and candidate pairs of a grid over \a points with cells of \a cell,
 * built on \a threads threads, are those of the half stencil: every pair of points in
 * neighbouring cells is a candidate exactly once. Returns the grid's cell count. */
std::size_t
expectHalfStencil (const std::vector<Point3d>& points,
                   double cell,
                   unsigned int threads)
{
  const UniformGrid grid (points, cell, threads);
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
        seen.begin(), seen.end(), (std::uint64_t{edge.source} << 32) | edge.target))
        << edge.source << " " << edge.target << ", threads " << threads;
  return grid.numCells();
}

} // namespace

TEST (UniformGrid, CandidatePairsCoverNeighbouringCellsOnce)
{
  std::mt19937 random (3);
  const double cell = 0.2;
  expectHalfStencil (randomPoints (random, 400, cell), cell, 1);
}

// The grid finds the neighbour cells of blocks of 4,096 cells at a time, each block
// from its own start: several blocks, on 1 and 2 threads.
TEST (UniformGrid, CandidatePairsCoverNeighbouringCellsOnceOverManyCells)
{
  std::mt19937 random (5);
  const double cell = 0.02;
  const std::vector<Point3d> points = randomPoints (random, 20000, cell);
  for (const unsigned int threads : {1u, 2u})
    EXPECT_GT (expectHalfStencil (points, cell, threads), 2u * 4096u);
}

TEST (UniformGrid, RefusesBadCellSizes)
{
  const std::vector<Point3d> points{{0, 0, 0}, {1, 1, 1}};
  for (const double bad : {0.0,
                           -1.0,
                           std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()})
    EXPECT_THROW (UniformGrid (points, bad), pcl::BadArgumentException) << bad;
  EXPECT_EQ (UniformGrid ({}, 1.0).numCells(), 0u);
}

// Far outliers and tiny cells do not make a cloud unusable: clamped cell
// coordinates keep every pair within the radius a candidate, and the other points'
// edges are those of a brute-force search.
TEST (UniformGrid, AnyExtentWithOutliers)
{
  std::mt19937 random (37);
  for (const double radius : {0.05, 1e-12}) {
    std::vector<Point3d> points = randomPoints (random, 300, radius);
    points.push_back ({1e30, 0.0, 0.0});
    points.push_back ({1e30, 0.0, 0.0}); // a duplicate far outlier: an edge of length 0
    points.push_back ({-1e300, 1e300, 5.0});
    const UniformGrid grid (points, radius);
    const auto counts = countRadiusEdges (grid, points, radius, AcceptAllPairs{}, 0);
    std::vector<FilteredEdge> edges =
        listRadiusEdges (grid, points, radius, AcceptAllPairs{}, counts.offsets, 0);
    sortEdges (edges, 0);
    expectSameEdges (edges,
                     bruteForceEdges (points, radius, false),
                     "radius " + std::to_string (radius));
  }
}

// A one-off run gets one thread per POINTS_PER_THREAD points, at least one and at
// most OpenMP's default; a thread count that is set is taken as it is.
TEST (UniformGrid, ThreadsForPoints)
{
  const auto most = static_cast<unsigned int> (omp_get_max_threads());
  EXPECT_EQ (threadsForPoints (0, 0), 1u);
  EXPECT_EQ (threadsForPoints (0, POINTS_PER_THREAD - 1), 1u);
  EXPECT_EQ (threadsForPoints (0, 2 * POINTS_PER_THREAD), std::min (2u, most));
  EXPECT_EQ (threadsForPoints (0, 1000 * POINTS_PER_THREAD), most);
  EXPECT_EQ (threadsForPoints (3, 10), 3u);
  EXPECT_EQ (resolveThreads (0), static_cast<int> (most));
}
