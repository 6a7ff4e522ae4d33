// Tests of the seeded random numbers and the surface samplers shared by the
// generators: portable values, bounds, exact counts and area-uniform sampling.

#include <pcl/tda/generators/random_sampling.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

using pcl::tda::PortableRandom;
using pcl::tda::SurfaceSample;

TEST (PortableRandom, UniformIsTheHigh53BitsOfMersenneTwister)
{
  // The C++ standard fixes the 10000th output of a default-seeded mt19937_64.
  PortableRandom random (5489);
  for (int i = 0; i < 9999; ++i)
    random.uniform();
  EXPECT_EQ ((9981545732273789042ull >> 11) * 0x1.0p-53, random.uniform());

  std::mt19937_64 engine (42);
  PortableRandom same (42);
  for (int i = 0; i < 1000; ++i)
    ASSERT_EQ (static_cast<double> (engine() >> 11) / 9007199254740992.0,
               same.uniform());
}

TEST (PortableRandom, RangesAndIndices)
{
  PortableRandom random (7);
  std::set<std::size_t> seen;
  for (int i = 0; i < 10000; ++i) {
    const double x = random.uniform (-2.0, 3.0);
    ASSERT_GE (x, -2.0);
    ASSERT_LT (x, 3.0);
    const std::size_t k = random.index (5);
    ASSERT_LT (k, 5u);
    seen.insert (k);
    ASSERT_EQ (0u, random.index (1));
  }
  EXPECT_EQ (5u, seen.size());
}

TEST (PortableRandom, NormalHasMeanZeroAndUnitVariance)
{
  PortableRandom random (3);
  const int n = 200000;
  double sum = 0.0, squares = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = random.normal();
    sum += x;
    squares += x * x;
  }
  EXPECT_NEAR (0.0, sum / n, 0.01);
  EXPECT_NEAR (1.0, squares / n, 0.01);
}

TEST (PortableRandom, TruncatedNormalsStayWithinBoundsAndDrawNothingForZeroSigma)
{
  PortableRandom random (11);
  double largest = 0.0, largest3 = 0.0;
  for (int i = 0; i < 100000; ++i) {
    largest = std::max (largest, std::abs (random.truncatedNormal (0.5, 3.0)));
    largest3 = std::max (largest3, random.truncatedNormal3 (0.5).norm());
  }
  EXPECT_LE (largest, 1.5);
  EXPECT_GT (largest, 1.4); // the tails are really drawn
  EXPECT_LE (largest3, pcl::tda::NOISE_TRUNCATION * 0.5);
  EXPECT_GT (largest3, 1.8);

  PortableRandom a (5), b (5);
  EXPECT_EQ (0.0, a.truncatedNormal (0.0, 3.0));
  EXPECT_TRUE (a.truncatedNormal3 (0.0).isZero (0.0));
  EXPECT_EQ (b.uniform(), a.uniform());
}

TEST (Apportion, LargestRemainderWithTiesToTheLowerIndex)
{
  using Counts = std::vector<std::size_t>;
  EXPECT_EQ ((Counts{4, 3, 3}), pcl::tda::apportion ({1.0, 1.0, 1.0}, 10));
  EXPECT_EQ ((Counts{3, 2, 2}), pcl::tda::apportion ({0.5, 0.25, 0.25}, 7));
  EXPECT_EQ ((Counts{1, 0}), pcl::tda::apportion ({1.0, 1.0}, 1));
  EXPECT_EQ ((Counts{0, 0, 0}), pcl::tda::apportion ({1.0, 2.0, 3.0}, 0));
  EXPECT_EQ ((Counts{17, 33, 50}), pcl::tda::apportion ({1.0, 2.0, 3.0}, 100));
}

TEST (CellCount, CeilingOfTheRatioAndAtLeastOne)
{
  EXPECT_EQ (4u, pcl::tda::cellCount (1.0, 0.25));
  EXPECT_EQ (5u, pcl::tda::cellCount (1.01, 0.25));
  EXPECT_EQ (1u, pcl::tda::cellCount (0.0, 0.1));
  EXPECT_EQ (1u, pcl::tda::cellCount (0.01, 0.1));
}

TEST (SampleSphere, ExactCountOnTheSphereAndAreaUniform)
{
  PortableRandom random (1);
  const std::size_t n = 4001;
  const std::vector<SurfaceSample> samples = pcl::tda::sampleSphere (2.0, n, random);
  ASSERT_EQ (n, samples.size());
  std::size_t upper = 0, cap = 0;
  for (const SurfaceSample& s : samples) {
    ASSERT_NEAR (1.0, s.normal.norm(), 1e-12);
    ASSERT_TRUE (s.point.isApprox (2.0 * s.normal, 1e-12));
    upper += s.normal.z() > 0.0;
    cap += s.normal.z() > 0.5; // a quarter of the area
  }
  EXPECT_NEAR (0.5, static_cast<double> (upper) / n, 0.005);
  EXPECT_NEAR (0.25, static_cast<double> (cap) / n, 0.01);
}

TEST (SampleTorus, ExactCountOnTheTorusAndAreaUniform)
{
  PortableRandom random (4);
  const std::size_t n = 5003;
  const double big = 0.5, small = 0.2;
  const std::vector<SurfaceSample> samples =
      pcl::tda::sampleTorus (big, small, n, random);
  ASSERT_EQ (n, samples.size());
  std::size_t outer = 0, upper = 0;
  for (const SurfaceSample& s : samples) {
    ASSERT_NEAR (1.0, s.normal.norm(), 1e-12);
    const Eigen::Vector3d axis =
        Eigen::Vector3d (s.point.x(), s.point.y(), 0.0).normalized();
    ASSERT_TRUE (s.point.isApprox (big * axis + small * s.normal, 1e-12));
    outer += s.point.head<2>().norm() > big;
    upper += s.point.z() > 0.0;
  }
  // The outer half has area 2 pi small (pi big + 2 small) of 4 pi^2 big small.
  const double outer_share = (M_PI * big + 2.0 * small) / (2.0 * M_PI * big);
  EXPECT_NEAR (outer_share, static_cast<double> (outer) / n, 0.01);
  EXPECT_NEAR (0.5, static_cast<double> (upper) / n, 0.01);
}

TEST (SampleDisc, OnePointPerCellOfEachRing)
{
  PortableRandom random (2);
  const std::vector<SurfaceSample> samples = pcl::tda::sampleDisc (0.05, 0.01, random);
  // 5 rings of width 1 cm with ceil(pi (2j + 1)) cells each: 4, 10, 16, 22, 29.
  ASSERT_EQ (81u, samples.size());
  std::vector<std::size_t> per_ring (5, 0);
  for (const SurfaceSample& s : samples) {
    ASSERT_EQ (0.0, s.point.z());
    ASSERT_EQ (Eigen::Vector3d::UnitZ(), s.normal);
    const double rho = s.point.head<2>().norm();
    ASSERT_LE (rho, 0.05 + 1e-12);
    ++per_ring[std::min<std::size_t> (4, static_cast<std::size_t> (rho / 0.01))];
  }
  EXPECT_EQ ((std::vector<std::size_t>{4, 10, 16, 22, 29}), per_ring);
}

TEST (SampleRectangle, AppendsOnePointPerGridCell)
{
  PortableRandom random (3);
  const Eigen::Vector3d origin (1.0, 2.0, 3.0), u (0.09, 0.0, 0.0), v (0.0, 0.05, 0.0);
  std::vector<SurfaceSample> samples (2);
  pcl::tda::sampleRectangle (
      origin, u, v, -Eigen::Vector3d::UnitZ(), 0.02, random, samples);
  ASSERT_EQ (2u + 5u * 3u, samples.size()); // ceil(4.5) x ceil(2.5) cells
  std::set<std::pair<int, int>> cells;
  for (std::size_t i = 2; i < samples.size(); ++i) {
    const Eigen::Vector3d d = samples[i].point - origin;
    ASSERT_NEAR (0.0, d.z(), 1e-12);
    ASSERT_EQ (-Eigen::Vector3d::UnitZ(), samples[i].normal);
    cells.insert (
        {static_cast<int> (d.x() / u.x() * 5), static_cast<int> (d.y() / v.y() * 3)});
  }
  EXPECT_EQ (15u, cells.size());
  EXPECT_EQ (0, cells.begin()->first);
  EXPECT_EQ (4, cells.rbegin()->first);
}

TEST (Samplers, SameSeedGivesTheSameSamples)
{
  PortableRandom a (9), b (9);
  const auto first = pcl::tda::sampleSphere (1.0, 500, a);
  const auto second = pcl::tda::sampleSphere (1.0, 500, b);
  for (std::size_t i = 0; i < first.size(); ++i)
    ASSERT_EQ (first[i].point, second[i].point);
}
