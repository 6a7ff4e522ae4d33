#include <pcl/tda/search/complex_size.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "search/grid_test_utils.h"

#include <cmath>

using namespace pcl::tda;
using namespace pcl::tda::test;

namespace {

/** Brute-force number of triangles of the clique complex of \a edges. */
double
bruteForceTriangles (std::size_t num_vertices, const std::vector<FilteredEdge>& edges)
{
  std::vector<std::vector<bool>> adjacent (num_vertices,
                                           std::vector<bool> (num_vertices, false));
  for (const auto& edge : edges)
    adjacent[edge.source][edge.target] = adjacent[edge.target][edge.source] = true;
  double triangles = 0.0;
  for (const auto& edge : edges)
    for (std::size_t w = edge.target + 1; w < num_vertices; ++w)
      triangles += adjacent[edge.source][w] && adjacent[edge.target][w];
  return triangles;
}

/** Points on a wavy surface patch, n of them, as a scan would give. */
std::vector<Point3d>
surfacePoints (std::mt19937& random, std::size_t n)
{
  std::uniform_real_distribution<double> coordinate (0.0, 1.0);
  std::vector<Point3d> points (n);
  for (auto& point : points) {
    const double x = coordinate (random), y = coordinate (random);
    point = {x, y, 0.05 * std::sin (10.0 * x) * std::cos (7.0 * y)};
  }
  return points;
}

} // namespace

// With a sample that covers everything, the estimate is the exact count; the count
// pass's triangle bound is at least the number of triangles.
TEST (ComplexSize, ExactOnSmallInputsAndBoundsHold)
{
  std::mt19937 random (13);
  for (unsigned int k = 0; k < 30; ++k) {
    const double radius = 0.1 + 0.02 * (k % 10);
    const std::vector<Point3d> points = randomPoints (random, 60 + 10 * k, radius);
    const UniformGrid grid (points, radius);
    const auto edges = bruteForceEdges (points, radius, false);
    const double triangles = bruteForceTriangles (points.size(), edges);
    const ComplexSize size = estimateComplexSize (
        grid, points, radius, AcceptAllPairs{}, 0, 1 << 20, 1 << 20, 1 << 20);
    EXPECT_TRUE (size.exact) << "case " << k;
    EXPECT_EQ (size.edges, static_cast<double> (edges.size())) << "case " << k;
    EXPECT_EQ (size.triangles, triangles) << "case " << k;
    const RadiusEdgeCounts counts =
        countRadiusEdges (grid, points, radius, AcceptAllPairs{}, 0);
    EXPECT_GE (static_cast<double> (counts.triangle_bound), triangles) << "case " << k;
  }
}

// A sample of a few hundred points estimates a 40k-point surface's complex within
// 15%, the same for any thread count.
TEST (ComplexSize, SampledEstimateIsCloseAndDeterministic)
{
  std::mt19937 random (17);
  const std::vector<Point3d> points = surfacePoints (random, 40000);
  const double radius = 0.02;
  VietorisRipsBuilder<pcl::PointXYZ> builder;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& point : points)
    cloud->push_back (pcl::PointXYZ (static_cast<float> (point[0]),
                                     static_cast<float> (point[1]),
                                     static_cast<float> (point[2])));
  std::vector<Point3d> float_points;
  for (const auto& point : *cloud)
    float_points.push_back ({point.x, point.y, point.z});
  builder.setInputCloud (cloud);
  builder.setRadius (radius);
  FilteredComplex complex;
  ASSERT_TRUE (builder.compute (complex));

  const UniformGrid grid (float_points, radius);
  const ComplexSize one = estimateComplexSize (
      grid, float_points, radius, AcceptAllPairs{}, 1, 500, 64, 64);
  const ComplexSize two = estimateComplexSize (
      grid, float_points, radius, AcceptAllPairs{}, 2, 500, 64, 64);
  EXPECT_FALSE (one.exact);
  EXPECT_EQ (one.edges, two.edges);
  EXPECT_EQ (one.triangles, two.triangles);
  EXPECT_NEAR (one.edges / complex.numEdges(), 1.0, 0.15);
  EXPECT_NEAR (one.triangles / complex.numTriangles(), 1.0, 0.15);
}

// Far over the budget: refused without the count pass, on the estimate; under it:
// the exact count.
TEST (ComplexSize, BudgetRefusesFarOverAndCountsOtherwise)
{
  std::mt19937 random (19);
  const std::vector<Point3d> points = surfacePoints (random, 20000);
  const double radius = 0.05;
  const UniformGrid grid (points, radius);
  const RadiusEdgeCounts exact =
      countRadiusEdges (grid, points, radius, AcceptAllPairs{}, 0);
  const double edges = static_cast<double> (exact.offsets.back());

  RadiusEdgeCounts counts;
  ComplexSize size;
  const MemoryBudget tight{static_cast<std::size_t> (edges * 24 / 10), 24, 0};
  EXPECT_FALSE (countRadiusEdgesWithinBudget (
      grid, points, radius, AcceptAllPairs{}, 0, tight, counts, size));
  EXPECT_FALSE (size.exact);
  EXPECT_TRUE (counts.offsets.empty()); // refused before counting
  EXPECT_NEAR (size.edges / edges, 1.0, 0.15);

  const MemoryBudget ample{static_cast<std::size_t> (edges * 24 * 1.01), 24, 0};
  EXPECT_TRUE (countRadiusEdgesWithinBudget (
      grid, points, radius, AcceptAllPairs{}, 0, ample, counts, size));
  EXPECT_EQ (counts.offsets, exact.offsets);

  // Just over: the exact count decides.
  const MemoryBudget just_under{static_cast<std::size_t> (edges * 24 * 0.99), 24, 0};
  EXPECT_FALSE (countRadiusEdgesWithinBudget (
      grid, points, radius, AcceptAllPairs{}, 0, just_under, counts, size));
  EXPECT_TRUE (size.exact);
  EXPECT_EQ (size.edges, edges);
}
