// computeCliqueH1Persistence() against the standard reduction of the same complex
// with its triangles listed.

#include <pcl/io/pcd_io.h>
#include <pcl/tda/common/coboundary_reduction.h>
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/persistence_engines.h>
#include <pcl/tda/search/clique_persistence.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "test_data.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

using namespace pcl::tda;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

namespace {

FilteredComplex
buildComplex (const Cloud::ConstPtr& cloud, double radius, int max_dimension)
{
  VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (radius);
  builder.setMaxDimension (max_dimension);
  FilteredComplex complex;
  EXPECT_TRUE (builder.compute (complex));
  return complex;
}

/** The clique engine on the skeleton equals \a engine on the listed complex:
 * the same intervals in the same order, and the same number of triangles, with 1,
 * 2 and 3 threads. Returns the number of intervals. */
std::size_t
expectSameAsListed (const Cloud::ConstPtr& cloud,
                    double radius,
                    PersistenceEngine engine,
                    const std::string& what)
{
  const FilteredComplex listed = buildComplex (cloud, radius, 2);
  const PersistenceResult result = computePersistence (listed, engine);
  PersistenceDiagram expected;
  for (const PersistenceInterval& interval : result.diagram (listed))
    if (interval.dimension == 1)
      expected.push_back (interval);

  // The pairing edge by edge: the value of the killing triangle, infinity for an
  // essential class, the edge's own value for a negative edge.
  std::vector<double> expected_death (listed.numEdges());
  for (std::size_t e = 0; e < expected_death.size(); ++e) {
    const SimplexIndex killer = result.edge_killer[e];
    expected_death[e] = !result.edge_positive[e] ? listed.edges()[e].value
                        : killer == INVALID_SIMPLEX
                            ? std::numeric_limits<double>::infinity()
                            : listed.triangles()[killer].value;
  }

  const FilteredComplex skeleton = buildComplex (cloud, radius, 1);
  EXPECT_EQ (skeleton.numTriangles(), 0u);
  EXPECT_EQ (skeleton.numEdges(), listed.numEdges()) << what;
  const PersistenceResult h0 = computeH0Persistence (skeleton);
  for (const unsigned int threads : {1u, 2u, 3u}) {
    const CliqueH1Persistence clique =
        computeCliqueH1Persistence (skeleton, h0, threads);
    EXPECT_EQ (clique.num_triangles, listed.numTriangles()) << what;
    EXPECT_EQ (clique.edge_death, expected_death) << what;
    EXPECT_EQ (clique.diagram.size(), expected.size()) << what;
    for (std::size_t k = 0; k < std::min (expected.size(), clique.diagram.size());
         ++k) {
      EXPECT_EQ (clique.diagram[k].dimension, 1) << what;
      EXPECT_EQ (clique.diagram[k].birth, expected[k].birth) << what << " " << k;
      EXPECT_EQ (clique.diagram[k].death, expected[k].death) << what << " " << k;
    }
  }
  return expected.size();
}

/** \a n random points in a cube; with \a on_grid, on an integer grid of spacing
 * 0.1, so that many edges have equal lengths and ties decide the order. */
Cloud::Ptr
randomCloud (std::mt19937& random, std::size_t n, bool on_grid)
{
  Cloud::Ptr cloud (new Cloud);
  std::uniform_real_distribution<float> coordinate (-1.0f, 1.0f);
  std::uniform_int_distribution<int> cell (-6, 6);
  for (std::size_t i = 0; i < n; ++i)
    if (on_grid)
      cloud->push_back (
          {0.1f * cell (random), 0.1f * cell (random), 0.1f * cell (random)});
    else
      cloud->push_back (
          {coordinate (random), coordinate (random), coordinate (random)});
  return cloud;
}

} // namespace

TEST (CliqueH1Persistence, EqualsTheStandardReductionOnRandomClouds)
{
  std::mt19937 random (17);
  std::size_t intervals = 0;
  for (unsigned int k = 0; k < 40; ++k) {
    const bool on_grid = k % 2 == 1;
    const std::size_t n = 20 + random() % 180;
    const double radius = std::uniform_real_distribution<double> (0.15, 0.6) (random);
    intervals += expectSameAsListed (randomCloud (random, n, on_grid),
                                     radius,
                                     PersistenceEngine::STANDARD,
                                     "case " + std::to_string (k));
  }
  EXPECT_GT (intervals, 200u); // the cases are not trivial
}

TEST (CliqueH1Persistence, EqualsTheStandardReductionAcrossManyBatches)
{
  // Thousands of columns to reduce, in many batches (BATCH_COLUMNS) whose columns
  // meet the pivots of earlier columns of the same batch.
  std::mt19937 random (23);
  std::size_t intervals = 0;
  for (unsigned int k = 0; k < 4; ++k) {
    const bool on_grid = k % 2 == 1;
    const double radius = on_grid ? 0.25 : 0.3;
    intervals += expectSameAsListed (randomCloud (random, 2500, on_grid),
                                     radius,
                                     PersistenceEngine::STANDARD,
                                     "large case " + std::to_string (k));
  }
  EXPECT_GT (intervals, 4 * pcl::tda::BATCH_COLUMNS);
}

TEST (CliqueH1Persistence, CircleHasOneLongInterval)
{
  // A regular 12-gon of radius 1: the cycle is born at the side 2 sin(pi/12) and
  // dies when the first triangle holding the centre appears, at the chord over 4
  // sides, 2 sin(pi/3) (an equilateral triangle of every 4th vertex).
  Cloud::Ptr circle (new Cloud);
  for (int i = 0; i < 12; ++i) {
    const double angle = 2.0 * M_PI * i / 12.0;
    circle->push_back ({static_cast<float> (std::cos (angle)),
                        static_cast<float> (std::sin (angle)),
                        0});
  }
  const FilteredComplex skeleton = buildComplex (circle, 2.5, 1);
  const CliqueH1Persistence clique =
      computeCliqueH1Persistence (skeleton, computeH0Persistence (skeleton));
  ASSERT_EQ (clique.diagram.size(), 1u);
  EXPECT_NEAR (clique.diagram[0].birth, 2.0 * std::sin (M_PI / 12.0), 1e-6);
  EXPECT_NEAR (clique.diagram[0].death, 2.0 * std::sin (M_PI / 3.0), 1e-6);
  EXPECT_EQ (clique.num_triangles, 220u); // all 12 choose 3 within 2.5
}

TEST (CliqueH1Persistence, EqualsTheCohomologyEngineOnScans)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  Cloud::Ptr bunny (new Cloud);
  ASSERT_EQ (pcl::io::loadPCDFile (test::dataFile ("bunny.pcd"), *bunny), 0);
  for (const double radius : {0.01, 0.02, 0.04})
    EXPECT_GT (expectSameAsListed (bunny,
                                   radius,
                                   PersistenceEngine::COHOMOLOGY,
                                   "bunny r " + std::to_string (radius)),
               10u);
  PCL_TDA_REQUIRE_DATA ("milk.pcd");
  Cloud::Ptr milk (new Cloud);
  ASSERT_EQ (pcl::io::loadPCDFile (test::dataFile ("milk.pcd"), *milk), 0);
  EXPECT_GT (expectSameAsListed (milk, 0.006, PersistenceEngine::COHOMOLOGY, "milk"),
             100u);
}
