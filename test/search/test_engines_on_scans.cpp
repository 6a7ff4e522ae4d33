// Every persistence engine, and PHAT, on Vietoris-Rips complexes of real scans.

#include <pcl/io/pcd_io.h>
#include <pcl/tda/common/persistence_engines.h>
#include <pcl/tda/common/phat_io.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "../common/test_utils.h"
#include "test_data.h"
#include <phat/algorithms/twist_reduction.h>
#include <phat/compute_persistence_pairs.h>
#include <phat/representations/default_representations.h>

#include <cstdio>

using namespace pcl::tda;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

namespace {

FilteredComplex
scanComplex (const std::string& name, double radius, std::size_t stride = 1)
{
  Cloud cloud, kept;
  EXPECT_EQ (pcl::io::loadPCDFile (test::dataFile (name), cloud), 0);
  for (std::size_t i = 0; i < cloud.size(); i += stride)
    kept.push_back (cloud[i]);
  VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (kept.makeShared());
  builder.setRadius (radius);
  FilteredComplex complex;
  EXPECT_TRUE (builder.compute (complex));
  return complex;
}

/** PHAT's twist reduction of the matrix we write for \a complex. */
std::vector<std::pair<std::int64_t, std::int64_t>>
phatPairs (const FilteredComplex& complex)
{
  const std::string path = testing::TempDir() + "engines_on_scans.bin";
  savePHATBoundaryMatrix (path, complex, PHATFormat::BINARY);
  phat::boundary_matrix<phat::vector_vector> matrix;
  EXPECT_TRUE (matrix.load_binary (path));
  std::remove (path.c_str());
  phat::persistence_pairs pairs;
  phat::compute_persistence_pairs<phat::twist_reduction> (pairs, matrix);
  pairs.sort();
  std::vector<std::pair<std::int64_t, std::int64_t>> result;
  for (phat::index p = 0; p < pairs.get_num_pairs(); ++p)
    result.push_back (pairs.get_pair (p));
  return result;
}

void
expectAllEnginesAgree (const FilteredComplex& complex, const std::string& what)
{
  ASSERT_GT (complex.numTriangles(), 0u) << what;
  const PersistenceResult oracle =
      computePersistence (complex, PersistenceEngine::STANDARD);
  const auto expected = test::globalPairs (complex, oracle);
  EXPECT_EQ (phatPairs (complex), expected) << what;
  for (const PersistenceEngineEntry& entry : persistenceEngines()) {
    const PersistenceResult result = computePersistence (complex, entry.engine);
    EXPECT_EQ (test::globalPairs (complex, result), expected)
        << what << " " << entry.name;
    EXPECT_EQ (result.edge_killer, oracle.edge_killer) << what << " " << entry.name;
    EXPECT_EQ (result.triangle_positive, oracle.triangle_positive)
        << what << " " << entry.name;
  }
}

} // namespace

TEST (EnginesOnScans, Bunny)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  for (const double radius : {0.01, 0.02, 0.03})
    expectAllEnginesAgree (scanComplex ("bunny.pcd", radius),
                           "bunny radius " + std::to_string (radius));
}

TEST (EnginesOnScans, MilkAndCarSubsamples)
{
  PCL_TDA_REQUIRE_DATA ("milk.pcd");
  expectAllEnginesAgree (scanComplex ("milk.pcd", 0.006, 4), "milk");
  PCL_TDA_REQUIRE_DATA ("car6.pcd");
  expectAllEnginesAgree (scanComplex ("car6.pcd", 0.08, 3), "car6");
}

TEST (EnginesOnScans, NoisySlice)
{
  PCL_TDA_REQUIRE_DATA ("noisy_slice_displaced.pcd");
  expectAllEnginesAgree (scanComplex ("noisy_slice_displaced.pcd", 0.005),
                         "noisy slice");
}
