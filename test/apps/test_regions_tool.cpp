// End-to-end tests of pcl_tda_regions: one output point per input point in input
// order (organized frames keep their layout, lost pixels label 0), labels by
// decreasing region size, the quality of its defaults on generated scenes of both
// generators (adjusted Rand index against the colour-region labels), the same
// partition for a shuffled input, its pictures, and the real coloured scans.

#include <pcl/common/point_tests.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "png_picture.h"
#include "segmentation/segmentation_metrics.h"
#include "test_data.h"
#include "tool_runner.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <set>

using namespace pcl::tda;
using pcl::tda::test::isPNGFile;
using pcl::tda::test::run;
using pcl::tda::test::RunResult;
using LabelledCloud = pcl::PointCloud<pcl::PointXYZRGBL>;

namespace {

std::string
temporaryPath (const std::string& name)
{
  return pcl::tda::test::temporaryPath ("regions_tool", name);
}

RunResult
runTool (const std::string& arguments)
{
  return run (std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_regions " + arguments);
}

/** Runs the tool with \a options on \a input and reads its output, checking what
 * holds for every output: one point per input point, same positions and colours,
 * labels 1..K by decreasing size, 0 for non-finite points. */
LabelledCloud
segment (const LabelledCloud& input, const std::string& options = "")
{
  const std::string in = temporaryPath ("in.pcd"), out = temporaryPath ("out.pcd");
  pcl::io::savePCDFileBinary (in, input);
  const RunResult result = runTool (in + " " + out + " " + options);
  EXPECT_EQ (result.exit_code, 0) << result.output;
  LabelledCloud output;
  EXPECT_EQ (pcl::io::loadPCDFile (out, output), 0);
  EXPECT_EQ (output.size(), input.size());
  EXPECT_EQ (output.width, input.width);
  EXPECT_EQ (output.height, input.height);
  std::map<std::uint32_t, std::size_t> sizes;
  for (std::size_t i = 0; i < std::min (input.size(), output.size()); ++i) {
    const auto& a = input[i];
    const auto& b = output[i];
    if (!pcl::isXYZFinite (a)) {
      EXPECT_FALSE (pcl::isXYZFinite (b));
      EXPECT_EQ (b.label, 0u);
      continue;
    }
    EXPECT_EQ (a.x, b.x);
    EXPECT_EQ (a.r, b.r);
    EXPECT_EQ (a.g, b.g);
    EXPECT_EQ (a.b, b.b);
    ++sizes[b.label];
  }
  std::vector<std::size_t> by_label;
  for (const auto& [label, size] : sizes)
    if (label > 0) {
      EXPECT_EQ (label, by_label.size() + 1); // labels 1..K without gaps
      by_label.push_back (size);
    }
  EXPECT_TRUE (std::is_sorted (by_label.rbegin(), by_label.rend()));
  std::remove (in.c_str());
  std::remove (out.c_str());
  return output;
}

/** The adjusted Rand index of the output labels against the truth, over the finite
 * points; label 0 (no region) counts each point as a region of its own. */
double
ari (const LabelledCloud& output, const std::vector<std::uint32_t>& truth)
{
  std::vector<std::int64_t> found, expected;
  for (std::size_t i = 0; i < output.size(); ++i) {
    if (!pcl::isXYZFinite (output[i]))
      continue;
    found.push_back (output[i].label == 0 ? -1 - static_cast<std::int64_t> (i)
                                          : output[i].label);
    expected.push_back (truth[i]);
  }
  return pcl::tda::test::adjustedRandIndex (expected, found);
}

} // namespace

// The defaults on tabletop scenes of colour regions at the three noise levels.
TEST (RegionsTool, DefaultsFindTheColourRegionsOfTabletopScenes)
{
  for (const TabletopNoise& noise :
       {TABLETOP_NO_NOISE, TABLETOP_MODERATE_NOISE, TABLETOP_HEAVY_NOISE})
    for (const std::uint64_t seed : {11u, 12u}) {
      TabletopParameters parameters;
      parameters.colour_regions = true;
      parameters.point_spacing = 0.005f;
      parameters.setNoise (noise);
      parameters.seed = seed;
      const TabletopScene scene = generateTabletopScene (parameters);
      const LabelledCloud output = segment (*scene.cloud);
      EXPECT_GT (ari (output, scene.region_labels), 0.97)
          << noise.name << " seed " << seed;
    }
}

// The held-out generator: an organized depth frame of two-tone objects on a table,
// with lost pixels. The default radius (from the spacing) is too small for the far,
// grazing part of the table, whose rows of points are far apart at full
// resolution (see doc/persistent_region_growing_rgb.md): the radius is given, the
// automatic threshold chosen.
TEST (RegionsTool, AutomaticThresholdOnDepthFrames)
{
  for (const std::uint64_t seed : {3u, 4u}) {
    DepthCameraParameters parameters;
    parameters.colour_regions = true;
    parameters.remove_table = false;
    parameters.colour_noise = 4.0f;
    parameters.seed = seed;
    const DepthCameraScene scene = generateDepthCameraScene (parameters);
    const LabelledCloud output = segment (*scene.cloud, "-radius 0.01");
    EXPECT_GT (ari (output, scene.region_labels), 0.95) << "seed " << seed;
  }
}

// A shuffled input gives the same partition, label for label.
TEST (RegionsTool, SamePartitionForAShuffledInput)
{
  TabletopParameters parameters;
  parameters.colour_regions = true;
  parameters.setNoise (TABLETOP_HEAVY_NOISE);
  parameters.seed = 5;
  const TabletopScene scene = generateTabletopScene (parameters);
  const LabelledCloud first = segment (*scene.cloud);
  std::vector<std::size_t> order (scene.cloud->size());
  std::iota (order.begin(), order.end(), 0);
  std::shuffle (order.begin(), order.end(), std::mt19937 (2));
  LabelledCloud shuffled;
  for (const std::size_t i : order)
    shuffled.push_back ((*scene.cloud)[i]);
  const LabelledCloud second = segment (shuffled);
  for (std::size_t k = 0; k < order.size(); ++k)
    ASSERT_EQ (second[k].label, first[order[k]].label) << "point " << order[k];
}

// The barcode and the picture: an SVG with the threshold's cut, a PNG, and the
// barcode as PNG too.
TEST (RegionsTool, DrawsTheBarcodeAndThePicture)
{
  TabletopParameters parameters;
  parameters.colour_regions = true;
  parameters.seed = 7;
  const TabletopScene scene = generateTabletopScene (parameters);
  const std::string svg = temporaryPath ("bars.svg"), png = temporaryPath ("r.png");
  segment (*scene.cloud, "-svg " + svg + " -png " + png);
  std::ifstream svg_file (svg);
  const std::string text ((std::istreambuf_iterator<char> (svg_file)), {});
  EXPECT_NE (text.find ("<svg"), std::string::npos);
  EXPECT_NE (text.find ("cut"), std::string::npos);
  EXPECT_TRUE (isPNGFile (png));
  const std::string barcode_png = temporaryPath ("bars.png"); // beside its SVG
  EXPECT_TRUE (isPNGFile (barcode_png));
  for (const std::string& file : {svg, png, barcode_png})
    std::remove (file.c_str());
}

// A cloud far from the scale of metres (the scene times 1e-25 or 1e20, where a
// float's squares underflow or overflow) is drawn as the scene is: a picture of the
// same size with about as many points drawn (the scaled floats round to a
// neighbouring pixel here and there).
TEST (RegionsTool, DrawsThePictureAtAnyScale)
{
  TabletopParameters parameters;
  parameters.colour_regions = true;
  parameters.seed = 11;
  const TabletopScene scene = generateTabletopScene (parameters);
  const std::string png = temporaryPath ("scaled.png");
  std::vector<pcl::tda::test::Picture> pictures;
  for (const float scale : {1.0f, 1e-25f, 1e20f}) {
    LabelledCloud scaled = *scene.cloud;
    for (auto& point : scaled)
      point.getVector3fMap() *= scale;
    segment (scaled, "-png " + png);
    pictures.push_back (pcl::tda::test::readPNG (png));
    std::remove (png.c_str());
  }
  const auto drawn = [] (const pcl::tda::test::Picture& picture) {
    return static_cast<double> (picture.width) * picture.height -
           static_cast<double> (picture.count ({255, 255, 255}));
  };
  ASSERT_GT (pictures[0].width, 0u);
  for (std::size_t k = 1; k < pictures.size(); ++k) {
    EXPECT_EQ (pictures[k].width, pictures[0].width) << "scale " << k;
    EXPECT_EQ (pictures[k].height, pictures[0].height) << "scale " << k;
    EXPECT_NEAR (drawn (pictures[k]), drawn (pictures[0]), 0.02 * drawn (pictures[0]))
        << "scale " << k;
  }
}

// The real coloured scans: every finite point in a region, a sensible number of
// regions.
TEST (RegionsTool, RealColouredScans)
{
  for (const std::string name : {"milk_color.pcd", "colored_cloud.pcd"}) {
    if (!pcl::tda::test::haveDataFile (name))
      GTEST_SKIP() << "skipped: " << pcl::tda::test::dataFile (name)
                   << " is absent (the real scans live in ../shared/data)";
    LabelledCloud input;
    ASSERT_EQ (pcl::io::loadPCDFile (pcl::tda::test::dataFile (name), input), 0);
    const LabelledCloud output = segment (input);
    std::set<std::uint32_t> labels;
    std::size_t unlabelled = 0;
    for (const auto& point : output) {
      labels.insert (point.label);
      unlabelled += point.label == 0;
    }
    EXPECT_GE (labels.size(), 5u) << name;
    EXPECT_LE (labels.size(), 120u) << name;
    EXPECT_LT (unlabelled, output.size() / 100) << name;
  }
}
