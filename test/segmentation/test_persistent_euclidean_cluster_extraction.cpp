// PersistentEuclideanClusterExtraction against its oracles: pcl::EuclideanCluster-
// Extraction on real scans and generated scenes, the standard reduction's H0,
// ground-truth objects of generated tabletop scenes, and its refusals.

#include <pcl/common/point_tests.h>
#include <pcl/io/pcd_io.h>
#include <pcl/search/kdtree.h>
#include <pcl/tda/apps/scene_preprocessing.h>
#include <pcl/tda/common/diagram_comparison.h>
#include <pcl/tda/common/standard_reduction.h>
#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/tda/segmentation/persistent_euclidean_cluster_extraction.h>

#include <gtest/gtest.h>

#include "segmentation/cluster_oracles.h"
#include "segmentation/real_object_scenes.h"
#include "test_data.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <numeric>
#include <random>
#include <set>

using namespace pcl::tda;
using pcl::tda::test::pclEuclideanClusters;
using pcl::tda::test::sameClusters;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using LabelledCloud = pcl::PointCloud<pcl::PointXYZRGBL>;
using Extraction = PersistentEuclideanClusterExtraction<pcl::PointXYZ>;

namespace {

std::vector<pcl::PointIndices>
ourClusters (const Cloud::ConstPtr& cloud,
             double distance,
             pcl::uindex_t min_size = 1,
             pcl::uindex_t max_size = std::numeric_limits<pcl::uindex_t>::max(),
             Extraction* extraction_out = nullptr,
             bool pcl_distance_test = false)
{
  Extraction local;
  Extraction& extraction = extraction_out ? *extraction_out : local;
  extraction.setPCLDistanceTest (pcl_distance_test);
  extraction.setInputCloud (cloud);
  extraction.setMaxDistance (distance);
  extraction.setMinClusterSize (min_size);
  extraction.setMaxClusterSize (max_size);
  std::vector<pcl::PointIndices> clusters;
  extraction.extract (clusters);
  return clusters;
}

/** The finite points of a scan (PCL's class makes a singleton of every NaN). */
Cloud::Ptr
loadScan (const std::string& name)
{
  Cloud::Ptr cloud (new Cloud);
  if (pcl::io::loadPCDFile (pcl::tda::test::dataFile (name), *cloud) < 0)
    ADD_FAILURE() << "cannot read " << name;
  Cloud::Ptr finite (new Cloud);
  for (const auto& point : *cloud)
    if (pcl::isXYZFinite (point))
      finite->push_back (point);
  return finite;
}

/** The table scene as PCL's cluster extraction tutorial prepares it (1 cm voxel
 * grid, plane removed). */
Cloud::Ptr
tableSceneObjects ()
{
  ScenePreprocessing options;
  options.plane_distance = 0.02;
  options.leaf = 0.01;
  Cloud::Ptr raw (new Cloud);
  pcl::io::loadPCDFile (
      pcl::tda::test::dataFile ("table_scene_mug_stereo_textured.pcd"), *raw);
  return preprocessScene (*raw, options);
}

TabletopParameters
sceneParameters (std::uint64_t seed, float noise, float dropout)
{
  TabletopParameters parameters;
  parameters.seed = seed;
  parameters.num_objects = 3 + seed % 4;
  parameters.noise_sigma = noise;
  parameters.dropout = dropout;
  return parameters;
}

/** A generated tabletop scene with the table removed by RANSAC (labels kept). */
LabelledCloud::Ptr
sceneObjects (const TabletopParameters& parameters)
{
  const TabletopScene scene = generateTabletopScene (parameters);
  ScenePreprocessing options;
  options.plane_distance = 0.01;
  return preprocessScene (*scene.cloud, options);
}

Cloud::Ptr
xyzOf (const LabelledCloud& cloud)
{
  Cloud::Ptr xyz (new Cloud);
  pcl::copyPointCloud (cloud, *xyz);
  return xyz;
}

std::vector<std::uint32_t>
labelsOf (const LabelledCloud& cloud)
{
  std::vector<std::uint32_t> labels;
  for (const auto& point : cloud)
    labels.push_back (point.label);
  return labels;
}

/** Ours equals PCL's with PCL's distance test, and also with ours unless
 * \a rounding_band_pairs (pairs within float rounding of the distance exist). */
void
expectSameAsPCL (const Cloud::ConstPtr& cloud,
                 double distance,
                 pcl::uindex_t min_size = 1,
                 pcl::uindex_t max_size = std::numeric_limits<pcl::uindex_t>::max(),
                 bool rounding_band_pairs = false)
{
  const auto pcl_clusters =
      pclEuclideanClusters<pcl::PointXYZ> (cloud, distance, min_size, max_size);
  for (const bool pcl_test : {false, true}) {
    const auto ours =
        ourClusters (cloud, distance, min_size, max_size, nullptr, pcl_test);
    if (!pcl_test && rounding_band_pairs)
      continue;
    EXPECT_TRUE (sameClusters (ours, pcl_clusters))
        << "distance " << distance << (pcl_test ? " (PCL's test)" : "") << ": "
        << ours.size() << " clusters, PCL " << pcl_clusters.size();
    for (const auto& cluster : ours)
      EXPECT_EQ (cluster.header.frame_id, cloud->header.frame_id);
  }
}

} // namespace

TEST (PersistentEuclideanClusterExtraction, SameAsPCLOnRealScans)
{
  PCL_TDA_REQUIRE_DATA ("milk.pcd");
  PCL_TDA_REQUIRE_DATA ("car6.pcd");
  PCL_TDA_REQUIRE_DATA ("noisy_slice_displaced.pcd");
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  const Cloud::Ptr milk = loadScan ("milk.pcd");
  for (const double distance : {0.002, 0.003, 0.005})
    expectSameAsPCL (milk, distance);
  expectSameAsPCL (milk, 0.003, 10, 5000);
  const Cloud::Ptr car = loadScan ("car6.pcd");
  // car6's coordinates lie on a 0.01 grid: at 0.1, 16 pairs are at 0.1 up to float
  // rounding (0.10000000005 in double), which PCL's float test keeps.
  expectSameAsPCL (car, 0.1, 1, std::numeric_limits<pcl::uindex_t>::max(), true);
  EXPECT_GT (ourClusters (car, 0.1).size(),
             pclEuclideanClusters<pcl::PointXYZ> (car, 0.1).size());
  for (const double distance : {0.105, 0.2, 0.5})
    expectSameAsPCL (car, distance);
  expectSameAsPCL (car, 0.2, 32, 2000);
  const Cloud::Ptr slice = loadScan ("noisy_slice_displaced.pcd");
  for (const double distance : {0.002, 0.005, 0.01})
    expectSameAsPCL (slice, distance);
  const Cloud::Ptr bunny = loadScan ("bunny.pcd");
  for (const double distance : {0.005, 0.01, 0.02})
    expectSameAsPCL (bunny, distance);
}

TEST (PersistentEuclideanClusterExtraction, SameAsPCLOnTableSceneAfterPlaneRemoval)
{
  PCL_TDA_REQUIRE_DATA ("table_scene_mug_stereo_textured.pcd");
  const Cloud::Ptr objects = tableSceneObjects();
  ASSERT_GT (objects->size(), 1000u);
  // PCL's tutorial parameters, then others.
  expectSameAsPCL (objects, 0.02, 100, 25000);
  for (const double distance : {0.01, 0.015, 0.03})
    expectSameAsPCL (objects, distance);
  const auto clusters = ourClusters (objects, 0.02, 100, 25000);
  EXPECT_GE (clusters.size(), 2u); // the mug and the rest of the scene
}

TEST (PersistentEuclideanClusterExtraction, SameAsPCLOnGeneratedScenes)
{
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const Cloud::Ptr cloud =
        xyzOf (*sceneObjects (sceneParameters (seed, 0.002f, 0.1f)));
    for (const double distance : {0.01, 0.02, 0.035, 0.06})
      expectSameAsPCL (cloud, distance);
    expectSameAsPCL (cloud, 0.03, 32, 400);

    // The same with a user's search object (the graph is then built on it).
    Extraction with_tree;
    with_tree.setSearchMethod (pcl::search::KdTree<pcl::PointXYZ>::Ptr (
        new pcl::search::KdTree<pcl::PointXYZ>));
    for (const bool pcl_test : {false, true}) {
      const auto ours = ourClusters (cloud, 0.02, 1, 100000, &with_tree, pcl_test);
      EXPECT_TRUE (
          sameClusters (ours, pclEuclideanClusters<pcl::PointXYZ> (cloud, 0.02)));
      Extraction without_tree;
      ourClusters (cloud, 0.02, 1, 100000, &without_tree, pcl_test);
      EXPECT_TRUE (compareDiagrams (with_tree.getPersistenceDiagram(),
                                    without_tree.getPersistenceDiagram(),
                                    0.0)
                       .equal);
    }
  }
}

TEST (PersistentEuclideanClusterExtraction, OrganizedCloudWithNaNsAndIndices)
{
  PCL_TDA_REQUIRE_DATA ("table_scene_mug_stereo_textured.pcd");
  Cloud::Ptr raw (new Cloud);
  pcl::io::loadPCDFile (
      pcl::tda::test::dataFile ("table_scene_mug_stereo_textured.pcd"), *raw);
  ASSERT_TRUE (raw->isOrganized());
  // Every 7th row: the clusters of the finite points, in input indices.
  pcl::IndicesPtr rows (new pcl::Indices);
  Cloud::Ptr finite (new Cloud);
  pcl::Indices finite_to_input;
  for (std::size_t index = 0; index < raw->size(); ++index)
    if ((index / raw->width) % 7 == 0) {
      rows->push_back (static_cast<pcl::index_t> (index));
      if (pcl::isXYZFinite ((*raw)[index])) {
        finite->push_back ((*raw)[index]);
        finite_to_input.push_back (static_cast<pcl::index_t> (index));
      }
    }
  Extraction extraction;
  extraction.setInputCloud (raw);
  extraction.setIndices (rows);
  extraction.setMaxDistance (0.01);
  extraction.setMinClusterSize (20);
  std::vector<pcl::PointIndices> ours;
  extraction.extract (ours);
  auto expected = pclEuclideanClusters<pcl::PointXYZ> (finite, 0.01, 20);
  for (auto& cluster : expected)
    for (auto& index : cluster.indices)
      index = finite_to_input[index];
  pcl::tda::test::sortClusters (expected);
  ASSERT_FALSE (ours.empty());
  EXPECT_TRUE (sameClusters (ours, expected));
}

TEST (PersistentEuclideanClusterExtraction, BoundaryConventionEdgeOfExactlyTheDistance)
{
  // Documented difference: an edge of length exactly r is in VR_r; PCL's k-d tree
  // keeps squared distances strictly below r^2.
  Cloud::Ptr cloud (new Cloud);
  cloud->push_back ({0.0f, 0.0f, 0.0f});
  cloud->push_back ({0.5f, 0.0f, 0.0f});
  EXPECT_EQ (ourClusters (cloud, 0.5).size(), 1u);
  EXPECT_EQ (pclEuclideanClusters<pcl::PointXYZ> (cloud, 0.5).size(), 2u);
  EXPECT_EQ (ourClusters (cloud, 0.5, 1, 10, nullptr, true).size(), 2u);
  EXPECT_EQ (ourClusters (cloud, 0.4999).size(), 2u);
  EXPECT_EQ (ourClusters (cloud, 0.5001, 1, 10, nullptr, true).size(), 1u);
}

TEST (PersistentEuclideanClusterExtraction, IndependentOfInputOrderAndThreads)
{
  const Cloud::Ptr cloud = xyzOf (*sceneObjects (sceneParameters (3, 0.003f, 0.2f)));
  Extraction extraction;
  const auto reference = ourClusters (cloud, 0.02, 5, 100000, &extraction);
  const PersistenceDiagram reference_diagram = extraction.getPersistenceDiagram();
  ASSERT_GT (reference.size(), 2u);

  std::vector<int> permutation (cloud->size());
  std::iota (permutation.begin(), permutation.end(), 0);
  std::shuffle (permutation.begin(), permutation.end(), std::mt19937 (5));
  Cloud::Ptr shuffled (new Cloud);
  for (const int index : permutation)
    shuffled->push_back ((*cloud)[index]);
  auto clusters = ourClusters (shuffled, 0.02, 5, 100000, &extraction);
  for (auto& cluster : clusters)
    for (auto& index : cluster.indices)
      index = permutation[index];
  pcl::tda::test::sortClusters (clusters);
  EXPECT_TRUE (sameClusters (clusters, reference));
  EXPECT_TRUE (
      compareDiagrams (extraction.getPersistenceDiagram(), reference_diagram, 0.0)
          .equal);

  for (const unsigned int threads : {1u, 2u}) {
    extraction.setNumberOfThreads (threads);
    extraction.setInputCloud (cloud);
    extraction.extract (clusters);
    EXPECT_TRUE (sameClusters (clusters, reference)) << threads << " threads";
    EXPECT_TRUE (
        compareDiagrams (extraction.getPersistenceDiagram(), reference_diagram, 0.0)
            .equal);
  }
}

TEST (PersistentEuclideanClusterExtraction, DiagramEqualsStandardReduction)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  const Cloud::Ptr bunny = loadScan ("bunny.pcd");
  const Cloud::Ptr scene = xyzOf (*sceneObjects (sceneParameters (2, 0.002f, 0.0f)));
  Cloud::Ptr small_scene (new Cloud);
  for (std::size_t i = 0; i < scene->size(); i += 4)
    small_scene->push_back ((*scene)[i]);
  for (const auto& [cloud, radius] : {std::make_pair (bunny, 0.01),
                                      std::make_pair (bunny, 0.03),
                                      std::make_pair (small_scene, 0.04)}) {
    VietorisRipsBuilder<pcl::PointXYZ> builder;
    builder.setInputCloud (cloud);
    builder.setRadius (radius);
    FilteredComplex complex;
    ASSERT_TRUE (builder.compute (complex));
    const PersistenceDiagram expected =
        computeStandardReduction (complex).diagram (complex, 0);

    Extraction extraction;
    const auto clusters = ourClusters (cloud, radius, 1, 1000000, &extraction);
    const PersistenceDiagram& diagram = extraction.getPersistenceDiagram();
    const DiagramComparison comparison = compareDiagrams (diagram, expected, 0.0);
    EXPECT_TRUE (comparison.equal) << "radius " << radius;
    const auto essential =
        std::count_if (diagram.begin(), diagram.end(), [] (const auto& interval) {
          return interval.isEssential();
        });
    EXPECT_EQ (static_cast<std::size_t> (essential), clusters.size());
  }
}

TEST (PersistentEuclideanClusterExtraction, SteppedFiltrationRoundsDeathsUp)
{
  const Cloud::Ptr cloud = xyzOf (*sceneObjects (sceneParameters (1, 0.002f, 0.1f)));
  const double radius = 0.05;
  const unsigned int steps = 10;
  Extraction exact, stepped;
  stepped.setFiltrationSteps (steps);
  const auto exact_clusters = ourClusters (cloud, radius, 32, 1000000, &exact);
  const auto stepped_clusters = ourClusters (cloud, radius, 32, 1000000, &stepped);
  EXPECT_TRUE (sameClusters (exact_clusters, stepped_clusters));

  const auto finiteDeaths = [] (const PersistenceDiagram& diagram) {
    std::vector<double> deaths;
    for (const auto& interval : diagram)
      deaths.push_back (interval.death);
    std::sort (deaths.begin(), deaths.end());
    return deaths;
  };
  const std::vector<double> exact_deaths = finiteDeaths (exact.getPersistenceDiagram());
  const std::vector<double> stepped_deaths =
      finiteDeaths (stepped.getPersistenceDiagram());
  ASSERT_EQ (exact_deaths.size(), stepped_deaths.size());
  const double step = radius / steps;
  for (std::size_t i = 0; i < exact_deaths.size(); ++i) {
    if (std::isinf (exact_deaths[i])) {
      EXPECT_TRUE (std::isinf (stepped_deaths[i]));
      continue;
    }
    const double multiple = stepped_deaths[i] / step;
    EXPECT_NEAR (multiple, std::round (multiple), 1e-9);
    EXPECT_GE (stepped_deaths[i], exact_deaths[i]);
    EXPECT_LT (stepped_deaths[i], exact_deaths[i] + step + 1e-12);
    EXPECT_LE (stepped_deaths[i], radius);
  }
}

TEST (PersistentEuclideanClusterExtraction, OversizedComponentsReportedDroppedOrKept)
{
  const Cloud::Ptr cloud = xyzOf (*sceneObjects (sceneParameters (4, 0.002f, 0.0f)));
  const auto all = ourClusters (cloud, 0.03, 32);
  ASSERT_GE (all.size(), 3u);
  const auto max_size = static_cast<pcl::uindex_t> (all[1].indices.size() - 1);

  Extraction extraction;
  testing::internal::CaptureStderr();
  const auto dropped = ourClusters (cloud, 0.03, 32, max_size, &extraction);
  const std::string warning = testing::internal::GetCapturedStderr();
  EXPECT_NE (warning.find ("2 components have more than the max cluster size"),
             std::string::npos)
      << warning;
  EXPECT_EQ (extraction.getNumOversizedClusters(), 2u);
  EXPECT_EQ (dropped.size(), all.size() - 2);
  EXPECT_TRUE (sameClusters (
      dropped, pclEuclideanClusters<pcl::PointXYZ> (cloud, 0.03, 32, max_size)));

  extraction.setKeepOversizedClusters (true);
  const auto kept = ourClusters (cloud, 0.03, 32, max_size, &extraction);
  EXPECT_EQ (extraction.getNumOversizedClusters(), 2u);
  EXPECT_TRUE (sameClusters (kept, all));
}

TEST (PersistentEuclideanClusterExtraction,
      RecoversTabletopObjectsUnderNoiseAndOcclusion)
{
  // Occlusion: the camera sees only the visible surfaces; noise and dropout vary.
  for (const float noise : {0.001f, 0.004f})
    for (const float dropout : {0.0f, 0.3f})
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const LabelledCloud::Ptr objects =
            sceneObjects (sceneParameters (seed, noise, dropout));
        const auto clusters = ourClusters (xyzOf (*objects), 0.03, 32);
        const pcl::tda::test::ObjectScores scores = pcl::tda::test::scoreObjects (
            labelsOf (*objects), clusters, FIRST_OBJECT_LABEL);
        for (std::size_t k = 0; k < scores.best_iou.size(); ++k)
          EXPECT_GE (scores.best_iou[k], 0.5)
              << "object " << k << " seed " << seed << " noise " << noise << " dropout "
              << dropout;
      }
}

TEST (PersistentEuclideanClusterExtraction, RefusesBadInputWithClearErrors)
{
  const auto errorOf = [] (Extraction& extraction) {
    std::vector<pcl::PointIndices> clusters (1);
    testing::internal::CaptureStderr();
    extraction.extract (clusters);
    const std::string error = testing::internal::GetCapturedStderr();
    EXPECT_TRUE (clusters.empty());
    EXPECT_TRUE (extraction.getPersistenceDiagram().empty());
    return error;
  };
  const auto contains = [] (const std::string& text, const std::string& part) {
    return text.find (part) != std::string::npos;
  };
  Cloud::Ptr points (new Cloud);
  points->push_back ({0.0f, 0.0f, 0.0f});
  points->push_back ({0.01f, 0.0f, 0.0f});

  Extraction no_input;
  no_input.setMaxDistance (0.1);
  EXPECT_TRUE (contains (errorOf (no_input), "No input cloud"));

  // Indices past the cloud gave clusters with points that do not exist, here after
  // indices set for a larger cloud; a repeated index counted its point twice.
  Extraction stale_indices;
  pcl::IndicesPtr thousand (new pcl::Indices (1000));
  std::iota (thousand->begin(), thousand->end(), 0);
  stale_indices.setIndices (thousand);
  stale_indices.setInputCloud (points);
  stale_indices.setMaxDistance (0.1);
  stale_indices.setMinClusterSize (1);
  EXPECT_TRUE (contains (errorOf (stale_indices),
                         "Index 2 (at position 2 of the indices) is not a point of "
                         "the input cloud of 2 points"));
  Extraction repeated;
  repeated.setInputCloud (points);
  repeated.setIndices (pcl::IndicesPtr (new pcl::Indices{0, 1, 1}));
  repeated.setMaxDistance (0.1);
  repeated.setMinClusterSize (1);
  EXPECT_TRUE (contains (errorOf (repeated), "Index 1 appears twice"));

  Extraction empty;
  empty.setInputCloud (Cloud::Ptr (new Cloud));
  empty.setMaxDistance (0.1);
  EXPECT_TRUE (contains (errorOf (empty), "no finite point (0 points"));

  Cloud::Ptr nans (new Cloud);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  nans->push_back ({nan, nan, nan});
  nans->push_back ({0.0f, nan, 1.0f});
  Extraction all_nan;
  all_nan.setInputCloud (nans);
  all_nan.setMaxDistance (0.1);
  EXPECT_TRUE (contains (errorOf (all_nan), "no finite point (2 points"));

  for (const double distance : {0.0, -1.0, static_cast<double> (nan)}) {
    Extraction bad_distance;
    bad_distance.setInputCloud (points);
    bad_distance.setMaxDistance (distance);
    EXPECT_TRUE (contains (errorOf (bad_distance), "max distance must be positive"))
        << distance;
  }

  Extraction min_above_max;
  min_above_max.setInputCloud (points);
  min_above_max.setMaxDistance (0.1);
  min_above_max.setMinClusterSize (10);
  min_above_max.setMaxClusterSize (5);
  EXPECT_TRUE (contains (errorOf (min_above_max),
                         "min cluster size (10) is above the max cluster size (5)"));

  Extraction bad_ratio;
  bad_ratio.setInputCloud (points);
  bad_ratio.setMaxDistance (0.1);
  bad_ratio.setAutoMaxDistance (true);
  bad_ratio.setAutoGapRatio (1.0);
  EXPECT_TRUE (contains (errorOf (bad_ratio), "gap ratio"));
  bad_ratio.setAutoGapRatio (1.5);
  for (const double piece_ratio :
       {-0.1, 1.0, std::numeric_limits<double>::quiet_NaN()}) {
    bad_ratio.setAutoPieceRatio (piece_ratio);
    EXPECT_TRUE (contains (errorOf (bad_ratio), "piece ratio")) << piece_ratio;
  }

  // With the search object, a radius graph over the memory limit is refused before
  // it is stored; the limit is the only obstacle. Without one, the forest is found
  // within the limit (Borůvka's searches where a scale's edges would not fit), the
  // same as without a limit.
  Cloud::Ptr cube (new Cloud);
  std::mt19937 random (29);
  std::uniform_real_distribution<float> coordinate (0.0f, 1.0f);
  for (int i = 0; i < 5000; ++i)
    cube->push_back ({coordinate (random), coordinate (random), coordinate (random)});
  Extraction over_limit;
  over_limit.setInputCloud (cube);
  over_limit.setMaxDistance (0.5);
  over_limit.setMemoryLimit (1u << 20);
  over_limit.setSearchMethod (
      pcl::search::KdTree<pcl::PointXYZ>::Ptr (new pcl::search::KdTree<pcl::PointXYZ>));
  const std::string error = errorOf (over_limit);
  EXPECT_TRUE (contains (error, "over the memory limit of 1.0 MiB")) << error;
  EXPECT_TRUE (contains (error, "would have")) << error;
  EXPECT_TRUE (contains (error, "setMemoryLimit()")) << error;
  for (const std::size_t memory_limit : {std::size_t{1} << 20, std::size_t{0}}) {
    Extraction limited, unlimited;
    for (Extraction* extraction : {&limited, &unlimited}) {
      extraction->setInputCloud (cube);
      extraction->setMaxDistance (0.5);
      extraction->setAutoMaxDistance (true);
    }
    limited.setMemoryLimit (memory_limit);
    std::vector<pcl::PointIndices> limited_clusters, unlimited_clusters;
    limited.extract (limited_clusters);
    unlimited.extract (unlimited_clusters);
    EXPECT_TRUE (compareDiagrams (limited.getPersistenceDiagram(),
                                  unlimited.getPersistenceDiagram(),
                                  0.0)
                     .equal);
    EXPECT_EQ (limited.getChosenDistance(), unlimited.getChosenDistance());
    EXPECT_LE (limited.getNumEdges() * Extraction::BYTES_PER_EDGE,
               std::max (memory_limit, cube->size() * Extraction::BYTES_PER_EDGE));
    ASSERT_EQ (limited_clusters.size(), unlimited_clusters.size());
    for (std::size_t c = 0; c < limited_clusters.size(); ++c)
      EXPECT_EQ (limited_clusters[c].indices, unlimited_clusters[c].indices);
  }
  Extraction within_limit;
  within_limit.setInputCloud (cube);
  within_limit.setMaxDistance (0.2);
  std::vector<pcl::PointIndices> cube_clusters;
  within_limit.extract (cube_clusters);
  EXPECT_EQ (cube_clusters.size(), 1u);

  // After the errors, the same object works.
  min_above_max.setMaxClusterSize (10);
  min_above_max.setMinClusterSize (1);
  std::vector<pcl::PointIndices> clusters;
  min_above_max.extract (clusters);
  EXPECT_EQ (clusters.size(), 1u);
}

namespace {

/** Generated scenes with the table removed by RANSAC (1 cm), across 6 noise levels,
 * 2 dropouts and 10 seeds, with 1 to 6 objects: 120 scenes. With noise 0.004 and
 * above, RANSAC leaves hundreds of sparse table points that bridge the objects at
 * 2-4 cm. \a min_gap: the generator's smallest gap between objects. */
struct AutoScaleScene {
  LabelledCloud::Ptr cloud;
  std::string name;
};

std::vector<AutoScaleScene>
autoScaleScenes (std::uint64_t first_seed, float min_gap)
{
  std::vector<AutoScaleScene> scenes;
  for (const float noise : {0.001f, 0.002f, 0.003f, 0.004f, 0.005f, 0.006f})
    for (const float dropout : {0.0f, 0.25f})
      for (std::uint64_t seed = first_seed; seed < first_seed + 10; ++seed) {
        TabletopParameters parameters = sceneParameters (seed, noise, dropout);
        parameters.num_objects = 1 + seed % 6;
        parameters.min_gap = min_gap;
        scenes.push_back ({sceneObjects (parameters),
                           "seed " + std::to_string (seed) + " noise " +
                               std::to_string (noise) + " dropout " +
                               std::to_string (dropout) + " min gap " +
                               std::to_string (min_gap)});
      }
  return scenes;
}

/** The best F1 of the tolerances of a sweep. */
double
bestF1 (const std::vector<pcl::tda::test::ObjectScores>& sweep)
{
  double best = 0.0;
  for (const auto& scores : sweep)
    best = std::max (best, scores.f1());
  return best;
}

} // namespace

/** Runs the automatic distance on \a scene; true when it gives one cluster per
 * ground-truth object, each matched with IoU >= 0.5. */
bool
autoDistanceRecovers (const LabelledCloud& scene, const std::string& name)
{
  const std::vector<std::uint32_t> labels = labelsOf (scene);
  std::set<std::uint32_t> objects (labels.begin(), labels.end());
  objects.erase (TABLE_LABEL);
  Extraction extraction;
  extraction.setAutoMaxDistance (true);
  const auto clusters = ourClusters (xyzOf (scene), 0.1, 32, 1000000, &extraction);
  EXPECT_GT (extraction.getChosenDistance(), 0.0) << name;
  EXPECT_LE (extraction.getChosenDistance(), 0.1) << name;
  const auto scores =
      pcl::tda::test::scoreObjects (labels, clusters, FIRST_OBJECT_LABEL);
  const bool recovered =
      clusters.size() == objects.size() && scores.matched == objects.size();
  if (!recovered)
    std::cout << name << ": " << objects.size() << " objects, " << clusters.size()
              << " clusters, " << scores.matched << " matched, chosen distance "
              << extraction.getChosenDistance() << std::endl;
  return recovered;
}

TEST (PersistentEuclideanClusterExtraction, AutoDistanceRecoversObjectCount)
{
  // 12 scenes of the first rule's report (3 to 6 objects, noise up to 3 mm): all
  // recovered.
  for (const float noise : {0.001f, 0.003f})
    for (const float dropout : {0.0f, 0.25f})
      for (std::uint64_t seed = 11; seed <= 13; ++seed)
        EXPECT_TRUE (autoDistanceRecovers (
            *sceneObjects (sceneParameters (seed, noise, dropout)),
            "seed " + std::to_string (seed) + " noise " + std::to_string (noise) +
                " dropout " + std::to_string (dropout)));

  // 240 scenes, 1 to 6 objects, 6 noise levels, two object gaps. Known limit: with
  // noise of 5 mm and more, the sparse table remnants that RANSAC leaves become
  // components of the minimum size at 2-4 cm and bridge the objects; in 29 of these
  // scenes no split into objects lasts a factor of the gap ratio, and the rule takes
  // one cluster (or keeps a remnant clump as a cluster). In 5 more (noise 5-6 mm)
  // the distance taken past the pieces that join within the step (which gains on
  // the independent scenes, doc/persistent_euclidean_cluster_extraction.md) keeps
  // one more small cluster than there are objects.
  std::size_t recovered = 0, total = 0;
  for (const auto& [first_seed, min_gap] : {std::make_pair (std::uint64_t{11}, 0.05f),
                                            std::make_pair (std::uint64_t{101}, 0.04f)})
    for (const auto& [scene, name] : autoScaleScenes (first_seed, min_gap)) {
      recovered += autoDistanceRecovers (*scene, name);
      ++total;
    }
  EXPECT_EQ (total, 240u);
  EXPECT_GE (recovered, 206u);
}

TEST (PersistentEuclideanClusterExtraction,
      AutoDistanceTakesASmallPieceForPartOfItsObject)
{
  // Points 1 apart on a line: object A of 200 points, 20 beyond it a piece of 30
  // points, 60 beyond that object B of 200 points. The would-be clusters appear at 1;
  // the piece merges into A at 20 and A into B at 60.
  Cloud::Ptr line (new Cloud);
  const auto add_run = [&line] (float start, int points) {
    for (int i = 0; i < points; ++i)
      line->push_back ({start + static_cast<float> (i), 0.0f, 0.0f});
  };
  add_run (0.0f, 200);   // A: 0 to 199
  add_run (219.0f, 30);  // the piece: 219 to 248
  add_run (308.0f, 200); // B: 308 to 507
  for (const double piece_ratio : {Extraction::DEFAULT_PIECE_RATIO, 0.0}) {
    Extraction extraction;
    extraction.setAutoMaxDistance (true);
    extraction.setAutoPieceRatio (piece_ratio);
    const auto clusters = ourClusters (line, 100.0, 20, 1000000, &extraction);
    if (piece_ratio > 0.0) {
      // 30 < 0.2 x 230: a piece of A; 2 clusters on [1, 60). The piece joins A at
      // 20, within the step: the distance is in the rest of it, at sqrt(20 x 60),
      // not at sqrt(60), where the piece would stand apart.
      EXPECT_NEAR (extraction.getChosenDistance(), std::sqrt (20.0 * 60.0), 1e-9);
      ASSERT_EQ (clusters.size(), 2u);
      EXPECT_EQ (clusters[0].indices.size(), 230u);
      EXPECT_EQ (clusters[1].indices.size(), 200u);
    }
    else {
      // Counted: 3 clusters on [1, 20), stable over a factor of 20, at sqrt(20).
      EXPECT_NEAR (extraction.getChosenDistance(), std::sqrt (20.0), 1e-9);
      EXPECT_EQ (clusters.size(), 3u);
    }
  }

  // The piece 50 beyond A joins it late in the step [1, 60): still past its join,
  // at sqrt(50 x 60).
  line->clear();
  add_run (0.0f, 200);
  add_run (249.0f, 30);
  add_run (338.0f, 200);
  Extraction extraction;
  extraction.setAutoMaxDistance (true);
  const auto clusters = ourClusters (line, 100.0, 20, 1000000, &extraction);
  EXPECT_NEAR (extraction.getChosenDistance(), std::sqrt (50.0 * 60.0), 1e-9);
  EXPECT_EQ (clusters.size(), 2u);
}

TEST (PersistentEuclideanClusterExtraction, AutoDistanceF1OnOurGenerator)
{
  // 36 scenes of 5 cm gaps, 3 seeds per noise level and dropout. The automatic
  // distance reaches the best tolerance of pcl::EuclideanClusterExtraction up to noise
  // 4 mm; above, the table remnants (see AutoDistanceRecoversObjectCount) cost it.
  pcl::tda::test::ObjectScores low_noise, all;
  std::vector<pcl::tda::test::ObjectScores> sweep (10);
  for (const auto& [scene, name] : autoScaleScenes (11, 0.05f)) {
    if (name.find ("seed 14") != std::string::npos ||
        name.find ("seed 15") != std::string::npos)
      continue;
    const Cloud::Ptr cloud = xyzOf (*scene);
    const std::vector<std::uint32_t> labels = labelsOf (*scene);
    Extraction extraction;
    extraction.setAutoMaxDistance (true);
    const auto scores = pcl::tda::test::scoreObjects (
        labels, ourClusters (cloud, 0.1, 32, 1000000, &extraction), FIRST_OBJECT_LABEL);
    all.add (scores);
    if (name.find ("noise 0.005") == std::string::npos &&
        name.find ("noise 0.006") == std::string::npos)
      low_noise.add (scores);
    for (std::size_t k = 0; k < sweep.size(); ++k) // 0.01 to 0.1 by 0.01
      sweep[k].add (pcl::tda::test::scoreObjects (
          labels,
          pclEuclideanClusters<pcl::PointXYZ> (cloud, 0.01 * (k + 1), 32),
          FIRST_OBJECT_LABEL));
  }
  const double best = bestF1 (sweep);
  std::cout << "object-level F1: automatic " << all.f1() << " (noise <= 4 mm "
            << low_noise.f1() << "), best ECE tolerance " << best << std::endl;
  EXPECT_EQ (low_noise.f1(), 1.0);
  EXPECT_GT (all.f1(), 0.9);
}

TEST (PersistentEuclideanClusterExtraction, AutoDistanceDepthCameraScenes)
{
  // The independent generator: 4 depth camera scenes (seeds 5000-5003), table
  // removed by its label, against the F1 of pcl::EuclideanClusterExtraction at its
  // best tolerance of a sweep. The rule was revised on other scenes of this generator
  // (seed 1000 on): the longest stable split merged objects 1-3 cm apart here (F1
  // 0.973), the finest one keeps them apart (1.0).
  pcl::tda::test::ObjectScores automatic;
  std::vector<pcl::tda::test::ObjectScores> sweep (8);
  for (std::uint64_t seed = 5000; seed < 5004; ++seed) {
    DepthCameraParameters parameters;
    parameters.seed = seed;
    const DepthCameraScene scene = generateDepthCameraScene (parameters);
    LabelledCloud objects;
    for (const auto& point : *scene.cloud)
      if (pcl::isXYZFinite (point) && point.label != DEPTH_BACKGROUND_LABEL)
        objects.push_back (point);
    const Cloud::Ptr cloud = xyzOf (objects);
    const std::vector<std::uint32_t> labels = labelsOf (objects);
    Extraction extraction;
    extraction.setAutoMaxDistance (true);
    automatic.add (pcl::tda::test::scoreObjects (
        labels,
        ourClusters (cloud, 0.1, 20, 1000000, &extraction),
        DEPTH_FIRST_OBJECT_LABEL));
    for (std::size_t k = 0; k < sweep.size(); ++k) // 2.5 mm to 20 mm by 2.5 mm
      sweep[k].add (pcl::tda::test::scoreObjects (
          labels,
          pclEuclideanClusters<pcl::PointXYZ> (cloud, 0.0025 * (k + 1), 20),
          DEPTH_FIRST_OBJECT_LABEL));
  }
  const double best = bestF1 (sweep);
  std::cout << "depth camera object-level F1: automatic " << automatic.f1()
            << ", best ECE tolerance " << best << std::endl;
  EXPECT_GE (automatic.f1(), best - 0.02);
  EXPECT_GT (automatic.f1(), 0.97);
}

TEST (PersistentEuclideanClusterExtraction, AutoDistanceRealObjectScenes)
{
  // Scenes made of the real object scans (milk, rops_cloud, car6; seeds 9000-9007,
  // a draw the rule was checked on only after it was chosen), against
  // pcl::EuclideanClusterExtraction at its best tolerance of a sweep around the
  // objects' gaps.
  for (const std::string& file : pcl::tda::test::realObjectScanFiles())
    PCL_TDA_REQUIRE_DATA (file);
  const auto scans = pcl::tda::test::loadRealObjectScans (PCL_TDA_DATA_DIR);
  ASSERT_FALSE (scans.empty());
  pcl::tda::test::ObjectScores automatic;
  const std::vector<double> tolerances = {0.01, 0.0125, 0.015, 0.0175, 0.02, 0.025};
  std::vector<pcl::tda::test::ObjectScores> sweep (tolerances.size());
  for (std::uint64_t seed = 9000; seed < 9008; ++seed) {
    const LabelledCloud objects = pcl::tda::test::makeRealObjectScene (scans, seed);
    const Cloud::Ptr cloud = xyzOf (objects);
    const std::vector<std::uint32_t> labels = labelsOf (objects);
    Extraction extraction;
    extraction.setAutoMaxDistance (true);
    automatic.add (pcl::tda::test::scoreObjects (
        labels, ourClusters (cloud, 0.1, 20, 1000000, &extraction), 1));
    for (std::size_t k = 0; k < tolerances.size(); ++k)
      sweep[k].add (pcl::tda::test::scoreObjects (
          labels, pclEuclideanClusters<pcl::PointXYZ> (cloud, tolerances[k], 20), 1));
  }
  const double best = bestF1 (sweep);
  std::cout << "real-object scenes, object-level F1: automatic " << automatic.f1()
            << ", best ECE tolerance " << best << std::endl;
  EXPECT_GE (automatic.f1(), best - 0.02);
  EXPECT_GT (automatic.f1(), 0.97);
}
