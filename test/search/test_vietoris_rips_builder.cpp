#include <pcl/common/point_tests.h>
#include <pcl/io/pcd_io.h>
#include <pcl/search/kdtree.h>
#include <pcl/search/organized.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "builder_progress_check.h"
#include "complex_difference.h"
#include "test_data.h"

#include <cmath>
#include <random>
#include <tuple>

using namespace pcl::tda;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

namespace {

/** An edge or triangle by input point indices (sorted) and its value. */
using EdgeRecord = std::tuple<int, int, double>;
using TriangleRecord = std::tuple<int, int, int, double>;

double
exactDistance (const pcl::PointXYZ& p, const pcl::PointXYZ& q)
{
  const double dx = double (p.x) - q.x, dy = double (p.y) - q.y,
               dz = double (p.z) - q.z;
  return std::sqrt (dx * dx + dy * dy + dz * dz);
}

/** The O(n^2) edges and O(n^3) triangles of VR_r over the finite points. */
void
bruteForce (const Cloud& cloud,
            double radius,
            std::vector<EdgeRecord>& edges,
            std::vector<TriangleRecord>& triangles)
{
  const int n = static_cast<int> (cloud.size());
  std::vector<std::vector<double>> length (n, std::vector<double> (n, INFINITY));
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (pcl::isXYZFinite (cloud[i]) && pcl::isXYZFinite (cloud[j])) {
        const double d = exactDistance (cloud[i], cloud[j]);
        if (d <= radius) {
          length[i][j] = length[j][i] = d;
          edges.emplace_back (i, j, d);
        }
      }
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (length[i][j] <= radius)
        for (int k = j + 1; k < n; ++k)
          if (length[i][k] <= radius && length[j][k] <= radius)
            triangles.emplace_back (
                i, j, k, std::max ({length[i][j], length[i][k], length[j][k]}));
  std::sort (edges.begin(), edges.end());
  std::sort (triangles.begin(), triangles.end());
}

/** The complex's simplices by input point indices. */
void
records (const FilteredComplex& complex,
         std::vector<EdgeRecord>& edges,
         std::vector<TriangleRecord>& triangles)
{
  const auto& input = complex.pointIndices();
  for (const auto& edge : complex.edges())
    edges.emplace_back (std::min (input[edge.source], input[edge.target]),
                        std::max (input[edge.source], input[edge.target]),
                        edge.value);
  for (SimplexIndex t = 0; t < complex.numTriangles(); ++t) {
    std::array<int, 3> v;
    const auto vertices = complex.triangleVertices (t);
    for (int k = 0; k < 3; ++k)
      v[k] = input[vertices[k]];
    std::sort (v.begin(), v.end());
    triangles.emplace_back (v[0], v[1], v[2], complex.triangles()[t].value);
  }
  std::sort (edges.begin(), edges.end());
  std::sort (triangles.begin(), triangles.end());
}

void
expectEqualsBruteForce (const Cloud::ConstPtr& cloud,
                        double radius,
                        unsigned int threads)
{
  VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (radius);
  builder.setNumberOfThreads (threads);
  FilteredComplex complex;
  ASSERT_TRUE (builder.compute (complex));
  std::vector<EdgeRecord> edges, expected_edges;
  std::vector<TriangleRecord> triangles, expected_triangles;
  records (complex, edges, triangles);
  bruteForce (*cloud, radius, expected_edges, expected_triangles);
  ASSERT_EQ (edges.size(), expected_edges.size());
  EXPECT_EQ (edges, expected_edges);
  ASSERT_EQ (triangles.size(), expected_triangles.size());
  EXPECT_EQ (triangles, expected_triangles);
}

Cloud::Ptr
randomCloud (std::mt19937& random, std::size_t n, bool with_defects)
{
  Cloud::Ptr cloud (new Cloud);
  std::uniform_real_distribution<float> coordinate (-1.0f, 1.0f);
  for (std::size_t i = 0; i < n; ++i)
    cloud->push_back ({coordinate (random), coordinate (random), coordinate (random)});
  if (with_defects) {
    (*cloud)[1] = (*cloud)[0];      // a duplicate point
    (*cloud)[2].x = std::nanf (""); // a NaN point
    (*cloud)[3].z = INFINITY;       // an infinite point
    (*cloud)[5] = (*cloud)[4];
    (*cloud)[5].x = std::nextafter ((*cloud)[4].x, 2.0f); // one ulp away
  }
  return cloud;
}

} // namespace

TEST (VietorisRipsBuilder, EqualsBruteForceOnRandomClouds)
{
  std::mt19937 random (7);
  for (int k = 0; k < 60; ++k) {
    const std::size_t n = 20 + random() % 200;
    const double radius = std::uniform_real_distribution<double> (0.05, 0.6) (random);
    const Cloud::Ptr cloud = randomCloud (random, n, k % 2 == 0);
    SCOPED_TRACE ("case " + std::to_string (k));
    expectEqualsBruteForce (cloud, radius, 1 + k % 2);
  }
}

TEST (VietorisRipsBuilder, EqualsBruteForceOnRealScans)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  Cloud::Ptr bunny (new Cloud);
  ASSERT_EQ (pcl::io::loadPCDFile (test::dataFile ("bunny.pcd"), *bunny), 0);
  for (const double radius : {0.005, 0.01, 0.02})
    expectEqualsBruteForce (bunny, radius, 2);

  PCL_TDA_REQUIRE_DATA ("milk.pcd");
  Cloud::Ptr milk (new Cloud);
  ASSERT_EQ (pcl::io::loadPCDFile (test::dataFile ("milk.pcd"), *milk), 0);
  Cloud::Ptr subsample (new Cloud);
  for (std::size_t i = 0; i < milk->size(); i += 20)
    subsample->push_back ((*milk)[i]);
  expectEqualsBruteForce (subsample, 0.01, 2);
}

TEST (VietorisRipsBuilder, SameComplexForShuffledInputThreadsAndSearchMethods)
{
  std::mt19937 random (11);
  for (int k = 0; k < 10; ++k) {
    const Cloud::Ptr cloud = randomCloud (random, 3000, true);
    Cloud::Ptr shuffled (new Cloud (*cloud));
    std::shuffle (shuffled->begin(), shuffled->end(), random);

    VietorisRipsBuilder<pcl::PointXYZ> builder;
    builder.setRadius (0.12);
    FilteredComplex reference, other;
    builder.setInputCloud (cloud);
    builder.setNumberOfThreads (1);
    ASSERT_TRUE (builder.compute (reference));
    EXPECT_GT (reference.numTriangles(), 1000u);

    builder.setNumberOfThreads (2);
    ASSERT_TRUE (builder.compute (other));
    EXPECT_EQ (test::complexDifference (reference, other), "");

    builder.setInputCloud (shuffled);
    ASSERT_TRUE (builder.compute (other));
    EXPECT_EQ (test::complexDifference (reference, other, false), "");
    for (std::size_t v = 0; v < other.numVertices(); ++v) {
      const auto& p = (*shuffled)[other.pointIndices()[v]];
      const auto& q = (*cloud)[reference.pointIndices()[v]];
      ASSERT_TRUE (p.x == q.x && p.y == q.y && p.z == q.z);
    }

    builder.setInputCloud (cloud);
    builder.setSearchMethod (pcl::search::KdTree<pcl::PointXYZ>::Ptr (
        new pcl::search::KdTree<pcl::PointXYZ>));
    ASSERT_TRUE (builder.compute (other));
    EXPECT_EQ (test::complexDifference (reference, other), "");
  }
}

// A thread count past MAX_THREADS (-1 given as an unsigned count: OpenMP asked for
// terabytes and ended the process) is taken as MAX_THREADS, the same complex.
TEST (VietorisRipsBuilder, ThreadCountCappedAtTheMost)
{
  std::mt19937 random (5);
  const Cloud::Ptr cloud = randomCloud (random, 500, true);
  VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (0.3);
  FilteredComplex reference, other;
  builder.setNumberOfThreads (1);
  ASSERT_TRUE (builder.compute (reference));
  builder.setNumberOfThreads (static_cast<unsigned int> (-1));
  EXPECT_EQ (builder.getNumberOfThreads(), pcl::tda::MAX_THREADS);
  ASSERT_TRUE (builder.compute (other));
  EXPECT_EQ (test::complexDifference (reference, other), "");
  EXPECT_EQ (pcl::tda::resolveThreads (static_cast<unsigned int> (-1)),
             static_cast<int> (pcl::tda::MAX_THREADS));
}

TEST (VietorisRipsBuilder, EdgesOnlyAndIndices)
{
  std::mt19937 random (3);
  const Cloud::Ptr cloud = randomCloud (random, 500, false);
  VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (0.3);
  builder.setMaxDimension (1);
  FilteredComplex complex;
  ASSERT_TRUE (builder.compute (complex));
  EXPECT_EQ (complex.numTriangles(), 0u);
  EXPECT_GT (complex.numEdges(), 0u);

  pcl::IndicesPtr indices (new pcl::Indices);
  for (int i = 0; i < 500; i += 5)
    indices->push_back (i);
  builder.setIndices (indices);
  ASSERT_TRUE (builder.compute (complex));
  EXPECT_EQ (complex.numVertices(), indices->size());
  for (const int index : complex.pointIndices())
    EXPECT_EQ (index % 5, 0);
}

TEST (VietorisRipsBuilder, EdgeOfLengthExactlyRadiusIsIn)
{
  Cloud::Ptr cloud (new Cloud);
  cloud->push_back ({0.0f, 0.0f, 0.0f});
  cloud->push_back ({0.5f, 0.0f, 0.0f});
  cloud->push_back ({1.5f, 0.0f, 0.0f});
  VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (1.0);
  FilteredComplex complex;
  ASSERT_TRUE (builder.compute (complex));
  ASSERT_EQ (complex.numEdges(), 2u);
  EXPECT_EQ (complex.edges()[1].value, 1.0);
  EXPECT_EQ (complex.numTriangles(), 0u);
}

// An OrganizedNeighbor on a cloud without rows and columns finds nothing: refused
// (every point was a component of its own); on the same points as rows and
// columns, the grid's complex.
TEST (VietorisRipsBuilder, RefusesASearchMethodThatCannotSearchTheCloud)
{
  Cloud::Ptr grid (new Cloud);
  for (int row = 0; row < 10; ++row)
    for (int column = 0; column < 10; ++column)
      grid->push_back ({0.01f * column, 0.01f * row, 1.0f});
  VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (grid);
  builder.setRadius (0.015);
  FilteredComplex reference, complex;
  ASSERT_TRUE (builder.compute (reference));
  builder.setSearchMethod (pcl::search::OrganizedNeighbor<pcl::PointXYZ>::Ptr (
      new pcl::search::OrganizedNeighbor<pcl::PointXYZ>));
  EXPECT_FALSE (builder.compute (complex));
  EXPECT_EQ (complex.numSimplices(), 0u);
  grid->width = 10;
  grid->height = 10;
  ASSERT_TRUE (builder.compute (complex));
  EXPECT_EQ (test::complexDifference (reference, complex), "");
}

TEST (VietorisRipsBuilder, RefusesBadInput)
{
  VietorisRipsBuilder<pcl::PointXYZ> builder;
  FilteredComplex complex;
  builder.setRadius (0.1);
  EXPECT_FALSE (builder.compute (complex)); // no input

  Cloud::Ptr empty (new Cloud);
  builder.setInputCloud (empty);
  EXPECT_FALSE (builder.compute (complex));
  EXPECT_EQ (complex.numSimplices(), 0u);

  Cloud::Ptr all_nan (new Cloud);
  for (int i = 0; i < 10; ++i)
    all_nan->push_back ({NAN, NAN, NAN});
  builder.setInputCloud (all_nan);
  EXPECT_FALSE (builder.compute (complex));
  EXPECT_EQ (builder.getNumSkippedPoints(), 10u);

  std::mt19937 random (5);
  const Cloud::Ptr cloud = randomCloud (random, 200, false);
  builder.setInputCloud (cloud);
  for (const double radius : {0.0, -1.0, double (NAN), double (INFINITY)}) {
    builder.setRadius (radius);
    EXPECT_FALSE (builder.compute (complex)) << radius;
  }
  builder.setRadius (0.5);
  builder.setMaxDimension (3);
  EXPECT_FALSE (builder.compute (complex));
  builder.setMaxDimension (2);
  ASSERT_TRUE (builder.compute (complex));
  const std::size_t edges = complex.numEdges(), triangles = complex.numTriangles();

  // Over the limit: refused, whether the edges or only the triangles overflow.
  builder.setMemoryLimit (edges * builder.BYTES_PER_EDGE - 1);
  EXPECT_FALSE (builder.compute (complex));
  EXPECT_EQ (complex.numSimplices(), 0u);
  builder.setMemoryLimit (edges * builder.BYTES_PER_EDGE +
                          triangles * builder.BYTES_PER_TRIANGLE / 2);
  builder.setInputCloud (cloud);
  EXPECT_FALSE (builder.compute (complex));
  builder.setMaxDimension (1);
  EXPECT_TRUE (builder.compute (complex));
  // Edges only, with the triangles counted against the limit: the complete graph's
  // 1.3 million triangles, over twice a limit that its 19,900 edges fit.
  builder.setRadius (4.0); // the cloud's diameter is at most 2 sqrt(3)
  builder.setMemoryLimit (19900 * builder.BYTES_PER_EDGE);
  EXPECT_TRUE (builder.compute (complex));
  EXPECT_EQ (complex.numEdges(), 19900u);
  builder.setTrianglesInMemoryLimit (true);
  EXPECT_FALSE (builder.compute (complex));
  EXPECT_EQ (complex.numSimplices(), 0u);
  builder.setTrianglesInMemoryLimit (false);
  builder.setRadius (0.5);

  // Indices past the cloud (it read past its end) or repeated.
  builder.setMemoryLimit (std::size_t{1} << 30);
  for (const pcl::Indices& indices :
       {pcl::Indices{0, 1, 200}, pcl::Indices{0, 50000000}, pcl::Indices{3, 1, 3}}) {
    builder.setIndices (pcl::IndicesPtr (new pcl::Indices (indices)));
    EXPECT_FALSE (builder.compute (complex));
    EXPECT_EQ (complex.numSimplices(), 0u);
  }
}

TEST (VietorisRipsBuilder, RefusesHugeComplexBeforeAllocating)
{
  // 8,000 points within a cube and a radius covering all: 3.2e7 edges (2 GB) and
  // 8.5e10 triangles. The count pass refuses it without allocating the edges; with a
  // search object too, before its searches (it counted every triangle, for a minute).
  std::mt19937 random (9);
  const Cloud::Ptr cloud = randomCloud (random, 8000, false);
  for (const bool with_search : {false, true}) {
    SCOPED_TRACE (with_search ? "k-d tree" : "grid");
    VietorisRipsBuilder<pcl::PointXYZ> builder;
    builder.setInputCloud (cloud);
    if (with_search)
      builder.setSearchMethod (pcl::search::KdTree<pcl::PointXYZ>::Ptr (
          new pcl::search::KdTree<pcl::PointXYZ>));
    builder.setRadius (4.0);
    builder.setMemoryLimit (std::size_t (1) << 30);
    FilteredComplex complex;
    testing::internal::CaptureStderr();
    EXPECT_FALSE (builder.compute (complex));
    const std::string error = testing::internal::GetCapturedStderr();
    // Refused on a sample (the edges are all 31,996,000 pairs).
    EXPECT_NE (error.find ("would have about 3"), std::string::npos) << error;
    EXPECT_NE (error.find ("(estimated from a sample)"), std::string::npos) << error;
    EXPECT_NE (error.find ("over the memory limit of 1.0 GiB"), std::string::npos)
        << error;

    // Over the limit by triangles only, found from the count pass's bound and a
    // sample: refused before the edges are listed, naming both sizes.
    builder.setRadius (0.3);
    builder.setMemoryLimit (std::size_t (64) << 20);
    testing::internal::CaptureStderr();
    EXPECT_FALSE (builder.compute (complex));
    const std::string triangles_error = testing::internal::GetCapturedStderr();
    EXPECT_NE (triangles_error.find (" triangles"), std::string::npos)
        << triangles_error;
    EXPECT_NE (triangles_error.find ("(estimated from a sample)"), std::string::npos)
        << triangles_error;
    EXPECT_NE (triangles_error.find ("64.0 MiB"), std::string::npos) << triangles_error;
  }
}

// The build reports its progress in thousandths, never backwards, ending at 1000,
// and the complex is the same with a callback as without.
TEST (VietorisRipsBuilder, ReportsProgress)
{
  std::mt19937 random (41);
  test::expectReportsProgress<VietorisRipsBuilder<pcl::PointXYZ>> (
      randomCloud (random, 20000, false), 0.1, 5);
}
