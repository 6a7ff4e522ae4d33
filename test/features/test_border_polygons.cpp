/** borderPolygons() on a square grid with a round hole: the outer border and the
 * rim give one polygon each, and both hold the hole, whose rim minimalCycles()
 * then finds; also from a star polygon that cuts through the hole. */
#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/features/border_polygons.h>
#include <pcl/tda/features/star_polygon.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using pcl::tda::FilteredEdge;
using pcl::tda::Point3d;
using pcl::tda::SimplexIndex;

constexpr double HOLE_RADIUS = 4.0;
constexpr double RADIUS = 1.6; // the automatic radius for a grid of spacing 1

/** A 40 x 40 grid of spacing 1, centred on the origin, without the points within
 * HOLE_RADIUS of it, and its edges up to RADIUS in filtration order. */
struct Grid {
  std::vector<Point3d> positions;
  pcl::tda::EdgeAdjacency adjacency;
  std::vector<FilteredEdge> edges;
};

Grid
gridWithHole ()
{
  Grid grid;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const Point3d p{i - 19.5, j - 19.5, 0.0};
      if (std::hypot (p[0], p[1]) > HOLE_RADIUS)
        grid.positions.push_back (p);
    }
  for (SimplexIndex a = 0; a < grid.positions.size(); ++a)
    for (SimplexIndex b = a + 1; b < grid.positions.size(); ++b) {
      const double d = pcl::tda::distance (grid.positions[a], grid.positions[b]);
      if (d <= RADIUS)
        grid.edges.push_back ({a, b, d});
    }
  std::sort (grid.edges.begin(), grid.edges.end(), pcl::tda::edgeFiltrationLess);
  grid.adjacency = pcl::tda::buildEdgeAdjacency (grid.positions.size(), grid.edges);
  return grid;
}

double
distanceFromCentre (const Point3d& p)
{
  return std::hypot (p[0], p[1]);
}

TEST (BorderPolygons, OuterBorderAndHoleRimEachGiveAPolygonAroundThem)
{
  const Grid grid = gridWithHole();
  for (const unsigned int threads : {1u, 2u}) {
    const std::vector<pcl::tda::InitialCycle> polygons = pcl::tda::borderPolygons (
        grid.positions, grid.adjacency, RADIUS, RADIUS, threads);
    ASSERT_EQ (polygons.size(), 2u);
    int around_hole = 0;
    for (const pcl::tda::InitialCycle& polygon : polygons) {
      EXPECT_EQ (polygon.class_edge, pcl::tda::INVALID_SIMPLEX);
      double nearest = 1e9, farthest = 0.0;
      for (const SimplexIndex v : polygon.vertices) {
        nearest = std::min (nearest, distanceFromCentre (grid.positions[v]));
        farthest = std::max (farthest, distanceFromCentre (grid.positions[v]));
      }
      if (farthest < 10.0) {
        // Within two edges outside the rim, all the way round.
        ++around_hole;
        EXPECT_GT (nearest, HOLE_RADIUS + 0.5);
        EXPECT_LE (farthest, HOLE_RADIUS + 1.0 + 2.0 * RADIUS);
        EXPECT_GE (polygon.vertices.size(), 8u);
      }
      else {
        EXPECT_GT (nearest, 18.0); // the outer border
      }
    }
    EXPECT_EQ (around_hole, 1);

    const std::vector<pcl::tda::MinimalCycle> rims = pcl::tda::minimalCycles (
        pcl::tda::FilteredComplex (grid.positions.size(), grid.edges, {}),
        polygons,
        grid.positions,
        grid.adjacency,
        RADIUS,
        threads);
    // Both polygons hold the hole (the outer border's holds the whole grid): each
    // gives the rim around it, which holeRims() keeps once.
    ASSERT_EQ (rims.size(), 2u);
    for (const pcl::tda::MinimalCycle& rim : rims) {
      EXPECT_NEAR (rim.clearance, HOLE_RADIUS + 0.5, 0.6);
      EXPECT_GE (rim.vertices.size(), 16u);
      for (const SimplexIndex v : rim.vertices)
        EXPECT_LT (distanceFromCentre (grid.positions[v]), HOLE_RADIUS + 1.0);
    }
  }
}

TEST (BorderPolygons, APolygonThatCutsThroughTheHoleStillGivesItsRim)
{
  // A star polygon around a point of the hole's edge holds half of the hole: no
  // cycle inside it goes around the hole. The search grows a star polygon around
  // the widest point of that half, and finds the whole rim.
  const Grid grid = gridWithHole();
  const Eigen::Vector3d edge_point (HOLE_RADIUS, 0.0, 0.0);
  std::vector<SimplexIndex> near_edge;
  for (SimplexIndex v = 0; v < grid.positions.size(); ++v)
    if (pcl::tda::distance (grid.positions[v], {HOLE_RADIUS, 0.0, 0.0}) <= HOLE_RADIUS)
      near_edge.push_back (v);
  std::vector<std::uint8_t> seen (grid.positions.size(), 0);
  const std::vector<SimplexIndex> star = pcl::tda::starPolygonAround (
      edge_point, HOLE_RADIUS, near_edge, grid.positions, grid.adjacency, RADIUS, seen);
  ASSERT_GE (star.size(), 8u);
  for (const SimplexIndex v : star)
    EXPECT_LE (pcl::tda::distance (grid.positions[v], {HOLE_RADIUS, 0.0, 0.0}),
               HOLE_RADIUS);
  EXPECT_TRUE (
      std::all_of (seen.begin(), seen.end(), [] (std::uint8_t s) { return s == 0; }));

  for (const unsigned int threads : {1u, 2u}) {
    const std::vector<pcl::tda::MinimalCycle> rims = pcl::tda::minimalCycles (
        pcl::tda::FilteredComplex (grid.positions.size(), grid.edges, {}),
        {{star, pcl::tda::INVALID_SIMPLEX}},
        grid.positions,
        grid.adjacency,
        RADIUS,
        threads);
    ASSERT_EQ (rims.size(), 1u);
    EXPECT_NEAR (rims[0].clearance, HOLE_RADIUS + 0.5, 0.6);
    EXPECT_GE (rims[0].vertices.size(), 16u);
    double largest_angle_step = 0.0;
    for (std::size_t i = 0; i < rims[0].vertices.size(); ++i) {
      const Point3d& a = grid.positions[rims[0].vertices[i]];
      const Point3d& b =
          grid.positions[rims[0].vertices[(i + 1) % rims[0].vertices.size()]];
      EXPECT_LT (distanceFromCentre (a), HOLE_RADIUS + 1.0);
      const double step = std::abs (std::remainder (
          std::atan2 (b[1], b[0]) - std::atan2 (a[1], a[0]), 2.0 * M_PI));
      largest_angle_step = std::max (largest_angle_step, step);
    }
    EXPECT_LT (largest_angle_step, M_PI / 4.0); // all the way round, step by step
  }
}

TEST (BorderPolygons, ShortBordersAreSkipped)
{
  // A hole needs a rim of 2 pi min_clearance / radius border vertices: with a
  // min_clearance far larger than this hole, only the long outer border is left.
  const Grid grid = gridWithHole();
  const auto polygons =
      pcl::tda::borderPolygons (grid.positions, grid.adjacency, RADIUS, 10.0);
  ASSERT_EQ (polygons.size(), 1u);
  for (const SimplexIndex v : polygons[0].vertices)
    EXPECT_GT (distanceFromCentre (grid.positions[v]), 18.0);
}

} // namespace
