/** pointSpacing(): known values on regular samplings, non-finite points and
 * duplicates skipped, the same value for any input order, also when only a
 * sample of the points is measured, and in any unit (no float overflow).
 * localSurfaceSpacings(): the closed form on a grid sampled at two densities. */
#include <pcl/tda/search/point_spacing.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/** A square grid of \a side x \a side points, \a step apart, in the plane z = 0. */
Cloud
grid (int side, float step)
{
  Cloud cloud;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      cloud.push_back (pcl::PointXYZ (i * step, j * step, 0.0f));
  return cloud;
}

TEST (PointSpacing, RegularGridValues)
{
  const Cloud cloud = grid (30, 0.01f);
  // Interior points: 4 neighbours at 1 step, 4 at sqrt(2), 4 at 2.
  EXPECT_NEAR (pcl::tda::pointSpacing (cloud), 0.01, 1e-6);
  EXPECT_NEAR (pcl::tda::pointSpacing (cloud, 0.5, 6), std::sqrt (2.0) * 0.01, 1e-6);
  EXPECT_NEAR (pcl::tda::pointSpacing (cloud, 0.5, 10), 0.02, 1e-6);
}

TEST (PointSpacing, SkipsNonFiniteAndDuplicatePoints)
{
  Cloud cloud = grid (20, 0.02f);
  const Cloud copy = cloud;
  for (const auto& point : copy)
    cloud.push_back (point); // every point twice
  cloud.push_back (pcl::PointXYZ (std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f));
  EXPECT_NEAR (pcl::tda::pointSpacing (cloud), 0.02, 1e-6);
  EXPECT_EQ (pcl::tda::pointSpacing (Cloud()), 0.0);
  Cloud single;
  single.push_back (pcl::PointXYZ (1.0f, 2.0f, 3.0f));
  single.push_back (pcl::PointXYZ (1.0f, 2.0f, 3.0f));
  EXPECT_EQ (pcl::tda::pointSpacing (single), 0.0);
}

TEST (PointSpacing, IndependentOfInputOrder)
{
  // More points than the sample, so that which points are measured matters.
  std::mt19937 rng (4);
  std::uniform_real_distribution<float> coordinate (0.0f, 1.0f);
  Cloud cloud;
  for (int i = 0; i < 20000; ++i)
    cloud.push_back (
        pcl::PointXYZ (coordinate (rng), coordinate (rng), 0.1f * coordinate (rng)));
  for (const std::size_t k : {1u, 6u})
    for (const double quantile : {0.5, 0.9}) {
      const double expected = pcl::tda::pointSpacing (cloud, quantile, k);
      ASSERT_GT (expected, 0.0);
      for (const unsigned seed : {1u, 2u, 3u}) {
        Cloud shuffled = cloud;
        std::mt19937 shuffler (seed);
        std::shuffle (shuffled.begin(), shuffled.end(), shuffler);
        EXPECT_EQ (pcl::tda::pointSpacing (shuffled, quantile, k), expected)
            << "k " << k << " quantile " << quantile << " seed " << seed;
      }
    }
}

TEST (PointSpacing, ScalesWithTheCloudAtAnyUnit)
{
  // A cloud in units where its squared distances overflow (1e25: 1e50 > FLT_MAX) or
  // underflow (1e-25: 1e-50 < FLT_MIN) in float has the spacing times the unit.
  const float step = 0.01f;
  const Cloud cloud = grid (30, step);
  const double spacing = pcl::tda::pointSpacing (cloud);
  const double surface = pcl::tda::surfaceSpacing (cloud);
  std::vector<pcl::tda::Point3d> points;
  for (const auto& point : cloud)
    points.push_back ({point.x, point.y, point.z});
  const std::uint32_t inside = 15 * 30 + 15;
  const double local = pcl::tda::localSurfaceSpacings (points, {inside})[0];
  for (const float unit : {1e25f, 1e-25f, 1e35f, 1e-35f}) {
    Cloud scaled = cloud;
    std::vector<pcl::tda::Point3d> scaled_points = points;
    for (auto& point : scaled)
      point.getVector3fMap() *= unit;
    for (auto& point : scaled_points)
      for (double& coordinate : point)
        coordinate *= unit;
    EXPECT_NEAR (pcl::tda::pointSpacing (scaled) / unit, spacing, 1e-6 * spacing)
        << unit;
    EXPECT_NEAR (pcl::tda::surfaceSpacing (scaled) / unit, surface, 1e-6 * surface)
        << unit;
    EXPECT_NEAR (pcl::tda::localSurfaceSpacings (scaled_points, {inside})[0] / unit,
                 local,
                 1e-6 * local)
        << unit;
  }
}

TEST (LocalSurfaceSpacings, FollowTheDensityAroundEachPoint)
{
  // Closed form: inside a square grid of step a, the 6th nearest point is at
  // sqrt(2) a, so the local spacing is sqrt(2) a sqrt(pi / 6), as surfaceSpacing()
  // gives for the grid as a whole. Two grids side by side, of steps 1 cm and 2 cm.
  const float fine = 0.01f, coarse = 0.02f;
  std::vector<pcl::tda::Point3d> points;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
      points.push_back ({i * fine, j * fine, 0.0});
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      points.push_back ({1.0 + i * coarse, j * coarse, 0.0});
  points.push_back (points.front()); // a duplicate does not count as a neighbour
  const std::uint32_t fine_inside = 20 * 40 + 20, coarse_inside = 1600 + 10 * 20 + 10;
  const std::vector<double> spacings =
      pcl::tda::localSurfaceSpacings (points, {fine_inside, coarse_inside, 0});
  ASSERT_EQ (spacings.size(), 3u);
  const double per_step = std::sqrt (2.0) * std::sqrt (M_PI / 6.0);
  EXPECT_NEAR (spacings[0], per_step * fine, 1e-6);
  EXPECT_NEAR (spacings[1], per_step * coarse, 1e-6);
  // A corner point's 6th nearest point (its duplicate skipped) is at sqrt(5) steps.
  EXPECT_NEAR (spacings[2], std::sqrt (5.0) * fine * std::sqrt (M_PI / 6.0), 1e-6);
  Cloud fine_grid = grid (40, fine);
  EXPECT_NEAR (pcl::tda::surfaceSpacing (fine_grid), spacings[0], 1e-6);
  EXPECT_EQ (pcl::tda::localSurfaceSpacings ({points.front()}, {0}),
             std::vector<double> (1, 0.0));
}

} // namespace
