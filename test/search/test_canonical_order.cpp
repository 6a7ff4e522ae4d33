// canonicalOrder() and sortCanonically() against std::sort with (x, y, z, index).

#include <pcl/tda/search/canonical_order.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>

using namespace pcl::tda;

namespace {

/** \a n points of a handful of tied coordinates (0 and -0 among them), negative,
 * tiny and huge ones, or spread; indices below \a indices, repeated where \a n is
 * larger, in random order. */
std::vector<CanonicalPoint>
randomPoints (std::mt19937& random, std::size_t n, pcl::index_t indices)
{
  std::uniform_real_distribution<float> spread (-1.0f, 1.0f);
  std::uniform_int_distribution<pcl::index_t> index (0, indices - 1);
  const std::vector<float> tied{0.0f, -0.0f, 0.5f, 1e-38f, -2.5f, 3e38f};
  const auto coordinate = [&] {
    return random() % 2 == 0 ? tied[random() % tied.size()] : spread (random);
  };
  std::vector<CanonicalPoint> points;
  for (std::size_t i = 0; i < n; ++i)
    points.push_back ({coordinate(), coordinate(), coordinate(), index (random)});
  return points;
}

/** The canonical order by comparisons (float comparison: 0 and -0 are equal). */
bool
canonicalLess (const CanonicalPoint& a, const CanonicalPoint& b)
{
  return std::tie (a.x, a.y, a.z, a.index) < std::tie (b.x, b.y, b.z, b.index);
}

/** Equal where the comparison cannot tell them apart (0 and -0 alike). */
bool
samePoints (const std::vector<CanonicalPoint>& a, const std::vector<CanonicalPoint>& b)
{
  return std::equal (
      a.begin(), a.end(), b.begin(), b.end(), [] (const auto& p, const auto& q) {
        return !canonicalLess (p, q) && !canonicalLess (q, p);
      });
}

} // namespace

// Sizes around the chunks of the parallel passes, 1 to 3 threads, ties in every
// coordinate, signed zeros, indices in and out of order: the order of std::sort.
TEST (CanonicalOrder, SameOrderAsStdSort)
{
  std::mt19937 random (53);
  for (const std::size_t n :
       {0ul, 1ul, 2ul, 17ul, 1000ul, 65535ul, 65536ul, 131073ul, 300000ul}) {
    for (const bool indices_in_order : {true, false}) {
      std::vector<CanonicalPoint> points =
          randomPoints (random, n, n < 100 ? 5 : static_cast<pcl::index_t> (n));
      if (indices_in_order)
        std::sort (points.begin(), points.end(), [] (const auto& a, const auto& b) {
          return a.index < b.index;
        });
      std::vector<CanonicalPoint> expected = points;
      std::sort (expected.begin(), expected.end(), canonicalLess);
      for (const unsigned int threads : {1u, 2u, 3u}) {
        std::vector<CanonicalPoint> sorted = points;
        sortCanonically (sorted, threads);
        EXPECT_TRUE (samePoints (sorted, expected))
            << n << " points, indices in order " << indices_in_order << ", " << threads
            << " threads";
      }
    }
  }
}

// The finite points only, counted as skipped otherwise; the same order for a
// shuffled cloud, index for point.
TEST (CanonicalOrder, SkipsNonFinitePointsAndIgnoresInputOrder)
{
  std::mt19937 random (59);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const auto& point : randomPoints (random, 5000, 1))
    cloud.push_back ({point.x, point.y, point.z});
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  cloud[10].x = nan;
  cloud[20].y = inf;
  cloud[30].z = -inf;
  pcl::Indices all (cloud.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    all[i] = static_cast<pcl::index_t> (i);
  std::size_t skipped = 0;
  const pcl::Indices order = canonicalOrder (cloud, all, skipped);
  EXPECT_EQ (skipped, 3u);
  ASSERT_EQ (order.size(), cloud.size() - 3);

  std::vector<pcl::index_t> permutation = all;
  std::shuffle (permutation.begin(), permutation.end(), random);
  pcl::PointCloud<pcl::PointXYZ> shuffled;
  for (const auto index : permutation)
    shuffled.push_back (cloud[index]);
  const pcl::Indices shuffled_order = canonicalOrder (shuffled, all, skipped);
  EXPECT_EQ (skipped, 3u);
  ASSERT_EQ (shuffled_order.size(), order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const auto& p = cloud[order[i]];
    const auto& q = shuffled[shuffled_order[i]];
    ASSERT_TRUE (p.x == q.x && p.y == q.y && p.z == q.z) << "position " << i;
  }
}
