#include <pcl/tda/common/angular_gap.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pcl::tda;

// One direction leaves the whole turn, halved opposite it.
TEST (AngularGap, OneDirectionLeavesTheWholeTurn)
{
  std::vector<double> angles = {0.5};
  const AngularGap gap = widestAngularGap (angles);
  EXPECT_DOUBLE_EQ (gap.width, 2.0 * M_PI);
  EXPECT_DOUBLE_EQ (std::cos (gap.middle), std::cos (0.5 + M_PI));
  EXPECT_DOUBLE_EQ (std::sin (gap.middle), std::sin (0.5 + M_PI));
}

// A gap between two directions inside [-pi, pi], and one across pi, in any order.
TEST (AngularGap, GapInsideAndAcrossTheCut)
{
  std::vector<double> inside = {M_PI / 2, -M_PI / 2, 0.0, M_PI};
  std::vector<double> with_gap = {-0.25, 1.5, 0.25, 0.75};
  const AngularGap quarter = widestAngularGap (inside);
  EXPECT_DOUBLE_EQ (quarter.width, M_PI / 2);
  EXPECT_TRUE (std::is_sorted (inside.begin(), inside.end()));
  const AngularGap across = widestAngularGap (with_gap);
  EXPECT_DOUBLE_EQ (across.width, 2.0 * M_PI - 1.75);
  EXPECT_NEAR (std::cos (across.middle), std::cos (1.5 + across.width / 2), 1e-12);
  std::vector<double> around_pi = {-2.0, 2.0, -1.9, 1.9, 0.1};
  const AngularGap behind = widestAngularGap (around_pi);
  EXPECT_DOUBLE_EQ (behind.width, 2.0 * M_PI - 4.0);
  EXPECT_DOUBLE_EQ (behind.middle, M_PI);
  std::vector<double> closed_behind = {-2.0, 2.0, -1.9, 1.9, 0.1, -3.0, 3.0};
  const AngularGap below = widestAngularGap (closed_behind);
  EXPECT_DOUBLE_EQ (below.width, 2.0);
  EXPECT_DOUBLE_EQ (below.middle, -0.9);
}

// On random directions, the gap equals the largest difference found by testing every
// direction against every other (the gap that no other direction falls into).
TEST (AngularGap, EqualsBruteForceOnRandomDirections)
{
  std::mt19937 random (20261203u);
  std::uniform_real_distribution<double> angle (-M_PI, M_PI);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<double> angles (1 + trial % 12);
    for (double& a : angles)
      a = angle (random);
    const std::vector<double> original = angles;
    double expected = 0.0;
    for (const double from : original) {
      double nearest = 2.0 * M_PI; // counter-clockwise to the next direction
      for (const double to : original) {
        double turn = std::fmod (to - from + 2.0 * M_PI, 2.0 * M_PI);
        if (turn > 0.0)
          nearest = std::min (nearest, turn);
      }
      expected = std::max (expected, nearest);
    }
    EXPECT_NEAR (widestAngularGap (angles).width, expected, 1e-12) << "trial " << trial;
  }
}
