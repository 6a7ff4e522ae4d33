// End-to-end tests of pcl_tda_segment: labels against ground truth on generated
// tabletop scenes and against pcl::EuclideanClusterExtraction on the real table
// scene, its barcode and summary, and its refusals.

#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/scene_preprocessing.h>
#include <pcl/tda/generators/shapes.h>
#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "segmentation/cluster_oracles.h"
#include "test_data.h"
#include "tool_runner.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>

using namespace pcl::tda;
using pcl::tda::test::exists;
using pcl::tda::test::run;
using pcl::tda::test::RunResult;
using LabelledCloud = pcl::PointCloud<pcl::PointXYZRGBL>;

namespace {

std::string
temporaryPath (const std::string& name)
{
  return pcl::tda::test::temporaryPath ("segment_tool", name);
}

RunResult
runTool (const std::string& arguments)
{
  return run (std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_segment " + arguments);
}

std::size_t
countOccurrences (const std::string& text, const std::string& part)
{
  std::size_t count = 0;
  for (auto at = text.find (part); at != std::string::npos;
       at = text.find (part, at + 1))
    ++count;
  return count;
}

/** Labels 1..K by decreasing size, one colour each, label 0 grey; returns the
 * clusters (sorted as the extraction sorts them). */
std::vector<pcl::PointIndices>
checkLabels (const LabelledCloud& labelled)
{
  std::map<std::uint32_t, pcl::PointIndices> by_label;
  std::map<std::uint32_t, std::uint32_t> colour_of;
  for (std::size_t i = 0; i < labelled.size(); ++i) {
    const auto& point = labelled[i];
    EXPECT_TRUE (pcl::isXYZFinite (point));
    if (colour_of.count (point.label)) {
      EXPECT_EQ (colour_of[point.label], point.rgba & 0xffffff) << point.label;
    }
    colour_of[point.label] = point.rgba & 0xffffff;
    if (point.label != 0)
      by_label[point.label].indices.push_back (static_cast<pcl::index_t> (i));
  }
  std::vector<pcl::PointIndices> clusters;
  for (std::uint32_t label = 1; label <= by_label.size(); ++label) {
    EXPECT_EQ (by_label.count (label), 1u) << "labels are not 1.." << by_label.size();
    clusters.push_back (by_label[label]);
    if (label > 1) {
      EXPECT_GE (clusters[label - 2].indices.size(),
                 clusters[label - 1].indices.size());
    }
  }
  return clusters;
}

} // namespace

TEST (SegmentTool, GeneratedSceneObjectsRecovered)
{
  TabletopParameters parameters;
  parameters.seed = 7;
  parameters.num_objects = 5;
  parameters.noise_sigma = 0.002f;
  const TabletopScene scene = generateTabletopScene (parameters);
  const std::string input = temporaryPath ("scene.pcd");
  savePointCloudFile (input, *scene.cloud);
  for (const std::string& mode :
       {std::string ("-radius 0.03"), std::string ("-radius 0.1 -auto")}) {
    const std::string output = temporaryPath ("labels.pcd");
    const std::string svg = temporaryPath ("barcode.svg");
    const RunResult result =
        runTool (input + " " + output + " " + mode + " -min 32 -svg " + svg);
    ASSERT_EQ (result.exit_code, 0) << result.output;
    EXPECT_EQ (countOccurrences (result.output, "  cluster "), parameters.num_objects)
        << result.output;

    LabelledCloud labelled;
    ASSERT_EQ (pcl::io::loadPCDFile (output, labelled), 0);
    const auto clusters = checkLabels (labelled);
    ASSERT_EQ (clusters.size(), parameters.num_objects) << mode;
    // The output holds the preprocessed points: match them to the ground truth by
    // running the same preprocessing on the labelled scene.
    ScenePreprocessing options;
    const auto truth = preprocessScene (*scene.cloud, options);
    ASSERT_EQ (truth->size(), labelled.size());
    std::vector<std::uint32_t> labels;
    for (std::size_t i = 0; i < truth->size(); ++i) {
      ASSERT_EQ ((*truth)[i].x, labelled[i].x);
      labels.push_back ((*truth)[i].label);
    }
    const auto scores =
        pcl::tda::test::scoreObjects (labels, clusters, FIRST_OBJECT_LABEL);
    EXPECT_EQ (scores.matched, parameters.num_objects) << mode;

    std::ifstream picture (svg);
    const std::string text ((std::istreambuf_iterator<char> (picture)),
                            std::istreambuf_iterator<char>());
    EXPECT_NE (text.find ("<svg"), std::string::npos);
    // One red triangle per essential bar (every component left at the end).
    EXPECT_GE (countOccurrences (text, "<path d=\"M"), parameters.num_objects);
  }
}

TEST (SegmentTool, OrganizedTableSceneSameAsPCL)
{
  PCL_TDA_REQUIRE_DATA ("table_scene_mug_stereo_textured.pcd");
  const std::string input =
      pcl::tda::test::dataFile ("table_scene_mug_stereo_textured.pcd");
  const std::string output = temporaryPath ("labels.pcd");
  const RunResult result = runTool (
      input + " " + output + " -leaf 0.01 -radius 0.02 -min 32 -plane_dist 0.02");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("(organized)"), std::string::npos);
  LabelledCloud labelled;
  ASSERT_EQ (pcl::io::loadPCDFile (output, labelled), 0);
  auto clusters = checkLabels (labelled);

  pcl::PointCloud<pcl::PointXYZ> raw;
  pcl::io::loadPCDFile (input, raw);
  ScenePreprocessing options;
  options.leaf = 0.01;
  options.plane_distance = 0.02;
  const auto expected_cloud = preprocessScene (raw, options);
  ASSERT_EQ (expected_cloud->size(), labelled.size());
  pcl::tda::test::sortClusters (clusters);
  EXPECT_TRUE (pcl::tda::test::sameClusters (
      clusters,
      pcl::tda::test::pclEuclideanClusters<pcl::PointXYZ> (expected_cloud, 0.02, 32)));
  EXPECT_GE (clusters.size(), 2u);
}

// A distance far above the spacing, on the whole table scene: every pair of its
// 209k finite points lies within it, and the one cluster holds them all (no memory
// refusal: the spanning forest's Borůvka rounds take over). At a distance below the
// spacing every point is a cluster of its own, and only the 30 largest get a line.
TEST (SegmentTool, AnyDistanceOnTheWholeTableScene)
{
  PCL_TDA_REQUIRE_DATA ("table_scene_mug_stereo_textured.pcd");
  const std::string input =
      pcl::tda::test::dataFile ("table_scene_mug_stereo_textured.pcd");
  pcl::PointCloud<pcl::PointXYZ> raw;
  ASSERT_EQ (pcl::io::loadPCDFile (input, raw), 0);
  const auto finite = static_cast<std::size_t> (
      std::count_if (raw.begin(), raw.end(), [] (const pcl::PointXYZ& point) {
        return pcl::isXYZFinite (point);
      }));
  const std::string output = temporaryPath ("labels.pcd");

  RunResult result = runTool (input + " " + output + " -radius 10 -plane 0");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("1 cluster at distance 10"), std::string::npos)
      << result.output;
  LabelledCloud labelled;
  ASSERT_EQ (pcl::io::loadPCDFile (output, labelled), 0);
  ASSERT_EQ (labelled.size(), finite);
  EXPECT_EQ (checkLabels (labelled).size(), 1u);

  result = runTool (input + " " + output + " -radius 3e-5 -plane 0");
  ASSERT_EQ (result.exit_code, 0) << result.output.substr (0, 2000);
  ASSERT_EQ (pcl::io::loadPCDFile (output, labelled), 0);
  const std::size_t clusters = checkLabels (labelled).size();
  EXPECT_GT (clusters, 100000u);
  EXPECT_EQ (countOccurrences (result.output, "  cluster "), 30u);
  EXPECT_NE (result.output.find ("  ... and " + std::to_string (clusters - 30) +
                                 " smaller clusters"),
             std::string::npos)
      << result.output.substr (0, 2000);
}

// A circle of radius 1 moved to x = 20000, where floats are 2^-9 apart: the
// coordinates resolve -radius 0.3 (the check asks 100 steps of it) but not the
// 0.157 that -auto chooses near the origin; there the automatic distance stops at
// what they resolve, 100 steps (0.195).
TEST (SegmentTool, AutoDistanceNotBelowWhatTheCoordinatesResolve)
{
  CircleParameters circle;
  circle.num_points = 200;
  const auto points = generateCircle (circle).cloud;
  for (const double shift : {0.0, 20000.0}) {
    pcl::PointCloud<pcl::PointXYZ> moved;
    pcl::copyPointCloud (*points, moved);
    for (auto& point : moved)
      point.x += static_cast<float> (shift);
    const std::string input = temporaryPath ("moved_circle.pcd");
    savePointCloudFile (input, moved);
    const RunResult result = runTool (input + " " + temporaryPath ("labels.pcd") +
                                      " -radius 0.3 -auto -plane 0");
    ASSERT_EQ (result.exit_code, 0) << result.output;
    const std::string before = "1 cluster at distance ";
    const auto at = result.output.find (before);
    ASSERT_NE (at, std::string::npos) << result.output;
    const double chosen = std::stod (result.output.substr (at + before.size()));
    if (shift == 0.0)
      EXPECT_LT (chosen, 0.18) << "the circle needs a case the floor changes";
    else
      EXPECT_GE (chosen, 100.0 / 512.0);
  }
}

TEST (SegmentTool, RefusesBadInputWithClearErrors)
{
  pcl::PointCloud<pcl::PointXYZ> line, nans;
  for (int i = 0; i < 100; ++i)
    line.push_back ({0.01f * i, 0.0f, 1.0f});
  const float nan = std::numeric_limits<float>::quiet_NaN();
  nans.push_back ({nan, nan, nan});
  nans.push_back ({nan, 0.0f, nan});
  const std::string line_pcd = temporaryPath ("line.pcd");
  const std::string nan_pcd = temporaryPath ("nan.pcd");
  savePointCloudFile (line_pcd, line);
  savePointCloudFile (nan_pcd, nans);
  const std::string output = temporaryPath ("out.pcd");
  std::remove (output.c_str()); // left by an earlier run

  const std::vector<std::pair<std::string, std::string>> cases{
      {temporaryPath ("missing.pcd") + " " + output + " -radius 0.02",
       "Cannot read the PCD file"},
      {line_pcd + " " + output, "Option -radius is required"},
      {line_pcd + " " + output + " -radius 0", "Option -radius needs a number > 0"},
      {line_pcd + " " + output + " -radius -1", "Option -radius needs a number > 0"},
      {line_pcd + " " + output + " -radius 0.02 -min 10 -max 5",
       "Need 1 <= -min <= -max"},
      {line_pcd + " " + output + " -radius 0.02", "no plane found"},
      {nan_pcd + " " + output + " -radius 0.02 -plane 0", "are NaN or infinite"},
      {line_pcd + " " + line_pcd + " -radius 0.02 -plane 0", "refusing to overwrite"},
      {line_pcd + " " + output + " -radius 0.02 -plane 2",
       "Option -plane needs an integer from 0 to 1"},
  };
  for (const auto& [arguments, message] : cases) {
    const RunResult result = runTool (arguments);
    EXPECT_NE (result.exit_code, 0) << arguments;
    EXPECT_NE (result.output.find (message), std::string::npos) << arguments << "\n"
                                                                << result.output;
    EXPECT_FALSE (exists (output)) << arguments;
  }
  // The line itself, without plane removal, is one cluster.
  const RunResult result = runTool (line_pcd + " " + output + " -radius 0.02 -plane 0");
  EXPECT_EQ (result.exit_code, 0) << result.output;
  EXPECT_EQ (countOccurrences (result.output, "  cluster "), 1u);
  pcl::PointCloud<pcl::PointXYZ> reloaded;
  ASSERT_EQ (pcl::io::loadPCDFile (line_pcd, reloaded), 0);
  EXPECT_EQ (reloaded.size(), 100u); // the input is untouched
}
