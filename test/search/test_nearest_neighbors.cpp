/** NearestNeighbors: the same neighbours and squared distances as pcl::KdTreeFLANN
 * searching one query at a time, and as a brute-force search, on random clouds with
 * duplicate points; the same result for 1 and 2 threads; k above the set's size; no
 * queries. */
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/tda/search/nearest_neighbors.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace {

using pcl::tda::NearestNeighbors;

/** \a count random points in a cube of side 1, with about a tenth repeated. */
std::vector<float>
randomPoints (std::size_t count, std::mt19937& random)
{
  std::uniform_real_distribution<float> coordinate (0.0f, 1.0f);
  std::vector<float> xyz;
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0 && random() % 10 == 0) { // a duplicate of an earlier point
      const std::size_t earlier = random() % i;
      xyz.insert (xyz.end(), &xyz[3 * earlier], &xyz[3 * earlier] + 3);
      continue;
    }
    for (int axis = 0; axis < 3; ++axis)
      xyz.push_back (coordinate (random));
  }
  return xyz;
}

/** The squared distance as FLANN's L2_Simple sums it, in float. */
float
squaredDistance (const float* a, const float* b)
{
  float sum = 0.0f;
  for (int axis = 0; axis < 3; ++axis)
    sum += (a[axis] - b[axis]) * (a[axis] - b[axis]);
  return sum;
}

TEST (NearestNeighbors, SameAsKdTreeFLANNAndBruteForce)
{
  std::mt19937 random (7);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t size = 1 + random() % 600;
    const std::vector<float> xyz = randomPoints (size, random);
    const std::vector<float> queries = randomPoints (1 + random() % 50, random);
    const std::size_t k = 1 + random() % 20;
    std::vector<std::uint32_t> neighbors;
    std::vector<float> squared_distances;
    NearestNeighbors (xyz).search (queries, k, 2, neighbors, squared_distances);

    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
    for (std::size_t i = 0; i < size; ++i)
      cloud->push_back (pcl::PointXYZ (xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]));
    pcl::KdTreeFLANN<pcl::PointXYZ> tree;
    tree.setInputCloud (cloud);
    const std::size_t found = std::min (k, size);
    ASSERT_EQ (neighbors.size(), queries.size() / 3 * found);
    for (std::size_t q = 0; q < queries.size() / 3; ++q) {
      const float* query = &queries[3 * q];
      pcl::Indices pcl_neighbors;
      std::vector<float> pcl_distances;
      tree.nearestKSearch (pcl::PointXYZ (query[0], query[1], query[2]),
                           static_cast<int> (k),
                           pcl_neighbors,
                           pcl_distances);
      std::vector<float> brute_force;
      for (std::size_t i = 0; i < size; ++i)
        brute_force.push_back (squaredDistance (query, &xyz[3 * i]));
      std::sort (brute_force.begin(), brute_force.end());
      for (std::size_t j = 0; j < found; ++j) {
        const std::size_t at = q * found + j;
        EXPECT_EQ (neighbors[at], static_cast<std::uint32_t> (pcl_neighbors[j]))
            << "trial " << trial << " query " << q << " rank " << j;
        EXPECT_EQ (squared_distances[at], pcl_distances[j]);
        EXPECT_EQ (squared_distances[at], brute_force[j]);
        EXPECT_EQ (squared_distances[at],
                   squaredDistance (query, &xyz[3 * neighbors[at]]));
      }
    }
  }
}

TEST (NearestNeighbors, SameForAnyThreadCount)
{
  std::mt19937 random (11);
  const std::vector<float> xyz = randomPoints (3000, random);
  const NearestNeighbors tree (xyz);
  std::vector<std::uint32_t> one, two;
  std::vector<float> one_distances, two_distances;
  tree.search (xyz, 9, 1, one, one_distances);
  tree.search (xyz, 9, 2, two, two_distances);
  EXPECT_EQ (one, two);
  EXPECT_EQ (one_distances, two_distances);
  // Each point of the set is its own nearest, at distance 0.
  for (std::size_t q = 0; q < 3000; ++q)
    EXPECT_EQ (one_distances[9 * q], 0.0f);
}

TEST (NearestNeighbors, SmallSetsAndNoQueries)
{
  const NearestNeighbors tree ({0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f});
  EXPECT_EQ (tree.size(), 2u);
  std::vector<std::uint32_t> neighbors;
  std::vector<float> squared_distances;
  tree.search ({0.75f, 0.0f, 0.0f}, 5, 0, neighbors, squared_distances);
  EXPECT_EQ (neighbors, (std::vector<std::uint32_t>{1, 0}));
  EXPECT_EQ (squared_distances, (std::vector<float>{0.0625f, 0.5625f}));
  tree.search ({}, 5, 0, neighbors, squared_distances);
  EXPECT_TRUE (neighbors.empty());
  EXPECT_TRUE (squared_distances.empty());
  const NearestNeighbors empty ({});
  EXPECT_EQ (empty.size(), 0u);
  empty.search ({0.0f, 0.0f, 0.0f}, 3, 0, neighbors, squared_distances);
  EXPECT_TRUE (neighbors.empty());
}

TEST (NearestNeighbors, FloatCoordinates)
{
  const std::vector<pcl::tda::Point3d> points = {{1.0, 2.0, 3.0}, {0.1, 0.2, 0.3}};
  EXPECT_EQ (pcl::tda::floatCoordinates (points),
             (std::vector<float>{1.0f, 2.0f, 3.0f, 0.1f, 0.2f, 0.3f}));
  EXPECT_EQ (
      pcl::tda::floatCoordinates (points, {1, 1, 0}),
      (std::vector<float>{0.1f, 0.2f, 0.3f, 0.1f, 0.2f, 0.3f, 1.0f, 2.0f, 3.0f}));
}

} // namespace
