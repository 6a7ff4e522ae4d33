// End-to-end tests of pcl_tda_holes: one output point per input point in input
// order with its hole's number (non-finite points kept, label 0), the holes of a
// generated surface found and labelled like the ground truth's rim bands, the CSV
// table, the filled cloud (input first, then new points inside the holes), the
// pictures, and the real scans.

#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/generators/hole_surfaces.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "test_data.h"
#include "tool_runner.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using pcl::tda::test::isPNGFile;
using pcl::tda::test::run;
using pcl::tda::test::RunResult;

namespace {

std::string
temporaryPath (const std::string& name)
{
  return pcl::tda::test::temporaryPath ("holes_tool", name);
}

RunResult
runTool (const std::string& arguments)
{
  return run (std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_holes " + arguments);
}

pcl::tda::HoleSurface
plane (std::uint64_t seed)
{
  pcl::tda::HoleSurfaceParameters parameters;
  parameters.seed = seed;
  return pcl::tda::generateHoleSurface (parameters);
}

std::vector<std::string>
lines (const std::string& path)
{
  std::ifstream file (path);
  std::vector<std::string> all;
  for (std::string line; std::getline (file, line);)
    all.push_back (line);
  return all;
}

TEST (HolesTool, LabelsTheRimBandsOfEveryHole)
{
  const pcl::tda::HoleSurface surface = plane (11);
  pcl::PointCloud<pcl::PointXYZL> input = *surface.cloud;
  input.push_back (pcl::PointXYZL (std::numeric_limits<float>::quiet_NaN(), 0, 0, 7));
  const std::string in = temporaryPath ("in.pcd"), out = temporaryPath ("out.pcd"),
                    csv = temporaryPath ("holes.csv"), filled = temporaryPath ("f.pcd"),
                    svg = temporaryPath ("b.svg"), png = temporaryPath ("p.png");
  pcl::io::savePCDFileBinary (in, input);
  const RunResult result = runTool (in + " " + out + " -csv " + csv + " -fill " +
                                    filled + " -svg " + svg + " -png " + png);
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("3 holes"), std::string::npos) << result.output;

  pcl::PointCloud<pcl::PointXYZL> output;
  ASSERT_EQ (pcl::io::loadPCDFile (out, output), 0);
  ASSERT_EQ (output.size(), input.size());
  EXPECT_FALSE (pcl::isXYZFinite (output.back()));
  EXPECT_EQ (output.back().label, 0u);
  // Each found hole's points lie around one true hole, and mostly on its band.
  std::size_t agree = 0, labelled = 0;
  for (std::size_t i = 0; i + 1 < input.size(); ++i) {
    EXPECT_EQ (output[i].x, input[i].x);
    if (output[i].label == 0)
      continue;
    ++labelled;
    agree += input[i].label != pcl::tda::SURFACE_LABEL &&
             input[i].label != pcl::tda::OUTER_BORDER_LABEL;
  }
  EXPECT_GT (labelled, 100u);
  EXPECT_GT (agree, labelled * 7 / 10);

  const std::vector<std::string> table = lines (csv);
  ASSERT_EQ (table.size(), 4u);
  EXPECT_EQ (table[0].rfind ("id,rim_points,perimeter,area,", 0), 0u);
  std::size_t previous_rim = std::numeric_limits<std::size_t>::max();
  for (std::size_t k = 1; k < table.size(); ++k) {
    std::istringstream row (table[k]);
    std::string id, rim_points;
    std::getline (row, id, ',');
    std::getline (row, rim_points, ',');
    EXPECT_EQ (id, std::to_string (k));
    EXPECT_LE (std::stoul (rim_points), previous_rim); // by decreasing rim points
    previous_rim = std::stoul (rim_points);
    // The last column lists the rim's input indices, each of a labelled point.
    std::istringstream rim (table[k].substr (table[k].rfind (',') + 1));
    std::vector<std::size_t> indices;
    for (std::size_t index; rim >> index;) {
      ASSERT_LT (index, output.size());
      indices.push_back (index);
    }
    EXPECT_EQ (indices.size(), previous_rim);
    // The birth (13th column) reads back as the rim's longest edge, to the last bit;
    // no number is written as -0.
    double longest = 0.0;
    for (std::size_t i = 0; i < indices.size(); ++i) {
      const auto& p = input[indices[i]];
      const auto& q = input[indices[(i + 1) % indices.size()]];
      longest =
          std::max (longest, pcl::tda::distance ({p.x, p.y, p.z}, {q.x, q.y, q.z}));
    }
    std::string field;
    std::istringstream fields (table[k]);
    for (int column = 0; column < 13; ++column)
      std::getline (fields, field, ',');
    EXPECT_EQ (std::stod (field), longest) << table[k];
    EXPECT_EQ (table[k].find (",-0,"), std::string::npos) << table[k];
  }

  pcl::PointCloud<pcl::PointXYZ> with_fill;
  ASSERT_EQ (pcl::io::loadPCDFile (filled, with_fill), 0);
  ASSERT_GT (with_fill.size(), input.size());
  for (std::size_t i = input.size(); i < with_fill.size(); ++i) {
    bool inside = false;
    for (const auto& hole : surface.holes)
      inside |= (with_fill[i].getVector3fMap() - hole.center).norm() <
                hole.radius + 2.0f * surface.spacing;
    EXPECT_TRUE (inside) << i;
  }
  EXPECT_GT (lines (svg).size(), 3u);
  EXPECT_TRUE (isPNGFile (png));
  EXPECT_TRUE (isPNGFile (temporaryPath ("b.png"))); // the barcode, beside its SVG
}

// The filled cloud keeps every field of the input file: the input points as they
// were, the new points with the fields of the rim point nearest to each (the rims
// of the CSV table) and their own x, y, z.
TEST (HolesTool, FilledCloudKeepsTheInputFields)
{
  const pcl::tda::HoleSurface surface = plane (13);
  pcl::PointCloud<pcl::PointXYZRGBNormal> input;
  pcl::copyPointCloud (*surface.cloud, input);
  for (std::size_t i = 0; i < input.size(); ++i) {
    input[i].r = static_cast<std::uint8_t> (i % 256);
    input[i].g = static_cast<std::uint8_t> (i / 256);
    input[i].b = 7;
    input[i].normal_x = input[i].normal_y = 0.0f;
    input[i].normal_z = 1.0f;
    input[i].curvature = static_cast<float> (i); // names the point
  }
  const std::string in = temporaryPath ("in.pcd"), out = temporaryPath ("out.pcd"),
                    csv = temporaryPath ("holes.csv"), filled = temporaryPath ("f.pcd");
  pcl::io::savePCDFileBinary (in, input);
  const RunResult result =
      runTool (in + " " + out + " -csv " + csv + " -fill " + filled);
  ASSERT_EQ (result.exit_code, 0) << result.output;

  std::vector<std::size_t> rims;
  const std::vector<std::string> table = lines (csv);
  for (std::size_t k = 1; k < table.size(); ++k) {
    std::istringstream rim (table[k].substr (table[k].rfind (',') + 1));
    for (std::size_t index; rim >> index;)
      rims.push_back (index);
  }
  ASSERT_FALSE (rims.empty());
  pcl::PointCloud<pcl::PointXYZRGBNormal> with_fill;
  ASSERT_EQ (pcl::io::loadPCDFile (filled, with_fill), 0);
  ASSERT_GT (with_fill.size(), input.size());
  for (std::size_t i = 0; i < input.size(); ++i) {
    ASSERT_EQ (with_fill[i].getVector3fMap(), input[i].getVector3fMap()) << i;
    ASSERT_EQ (with_fill[i].rgba, input[i].rgba) << i;
    ASSERT_EQ (with_fill[i].curvature, input[i].curvature) << i;
  }
  for (std::size_t i = input.size(); i < with_fill.size(); ++i) {
    const auto distance = [&] (std::size_t rim_point) {
      return (input[rim_point].getVector3fMap() - with_fill[i].getVector3fMap())
          .squaredNorm();
    };
    const std::size_t nearest = *std::min_element (
        rims.begin(), rims.end(), [&] (std::size_t a, std::size_t b) {
          return distance (a) < distance (b);
        });
    const auto source = static_cast<std::size_t> (with_fill[i].curvature);
    ASSERT_LT (source, input.size()) << i;
    EXPECT_FLOAT_EQ (distance (source), distance (nearest)) << i;
    EXPECT_EQ (with_fill[i].rgba, input[source].rgba) << i;
    EXPECT_EQ (with_fill[i].normal_z, 1.0f) << i;
    EXPECT_NE (with_fill[i].getVector3fMap(), input[source].getVector3fMap()) << i;
  }
}

TEST (HolesTool, SmallestHoleRadius)
{
  // The generated holes have radii 3, 5 and 8 spacings: with -min-hole between the
  // two largest, only the largest is a hole.
  const pcl::tda::HoleSurface surface = plane (12);
  std::vector<float> radii;
  for (const auto& hole : surface.holes)
    radii.push_back (hole.radius);
  std::sort (radii.begin(), radii.end());
  ASSERT_EQ (radii.size(), 3u);
  const std::string in = temporaryPath ("min_in.pcd"), out = temporaryPath ("min.pcd");
  pcl::io::savePCDFileBinary (in, *surface.cloud);
  const RunResult all = runTool (in + " " + out);
  ASSERT_EQ (all.exit_code, 0) << all.output;
  EXPECT_NE (all.output.find (": 3 holes"), std::string::npos) << all.output;
  const RunResult largest = runTool (in + " " + out + " -min-hole " +
                                     std::to_string ((radii[1] + radii[2]) / 2));
  ASSERT_EQ (largest.exit_code, 0) << largest.output;
  EXPECT_NE (largest.output.find (": 1 hole,"), std::string::npos) << largest.output;
}

TEST (HolesTool, AdvisesOnlyWhatApplies)
{
  // No surface (every point the same): the reason and the advice on coincident points,
  // not the advice for a complex over the memory limit, nothing written.
  pcl::PointCloud<pcl::PointXYZ> same (200, 1, pcl::PointXYZ (0.5f, 0.5f, 0.5f));
  const std::string in = temporaryPath ("same.pcd"),
                    out = temporaryPath ("same_out.pcd");
  pcl::io::savePCDFileBinary (in, same);
  std::remove (out.c_str());
  const RunResult no_surface = runTool (in + " " + out);
  EXPECT_EQ (no_surface.exit_code, 1) << no_surface.output;
  EXPECT_NE (no_surface.output.find ("there is no surface"), std::string::npos)
      << no_surface.output;
  EXPECT_NE (no_surface.output.find ("199 of the 200 points repeat"), std::string::npos)
      << no_surface.output;
  EXPECT_EQ (no_surface.output.find ("-memory"), std::string::npos)
      << no_surface.output;
  EXPECT_FALSE (std::ifstream (out).good());
  // A complex over the memory limit: the advice names the option.
  const std::string surface = temporaryPath ("surface.pcd");
  pcl::io::savePCDFileBinary (surface, *plane (3).cloud);
  const RunResult refused = runTool (surface + " " + out + " -memory 0.01");
  EXPECT_EQ (refused.exit_code, 1) << refused.output;
  EXPECT_NE (refused.output.find ("set a larger one with -memory M (MiB)"),
             std::string::npos)
      << refused.output;
  EXPECT_FALSE (std::ifstream (out).good());
}

TEST (HolesTool, CentroidFillAndShuffledInput)
{
  const pcl::tda::HoleSurface surface = plane (12);
  const std::string in = temporaryPath ("in.pcd"), out = temporaryPath ("out.pcd"),
                    filled = temporaryPath ("f.pcd");
  pcl::io::savePCDFileBinary (in, *surface.cloud);
  const RunResult result =
      runTool (in + " " + out + " -fill " + filled + " -fill-mode centroid");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  pcl::PointCloud<pcl::PointXYZ> with_fill;
  ASSERT_EQ (pcl::io::loadPCDFile (filled, with_fill), 0);
  EXPECT_EQ (with_fill.size(), surface.cloud->size() + surface.holes.size());

  // Reversed input order: the same labels, point by point.
  pcl::PointCloud<pcl::PointXYZL> output, reversed_output;
  ASSERT_EQ (pcl::io::loadPCDFile (out, output), 0);
  pcl::PointCloud<pcl::PointXYZL> reversed;
  for (auto point = surface.cloud->rbegin(); point != surface.cloud->rend(); ++point)
    reversed.push_back (*point);
  const std::string reversed_in = temporaryPath ("reversed.pcd");
  pcl::io::savePCDFileBinary (reversed_in, reversed);
  ASSERT_EQ (runTool (reversed_in + " " + out).exit_code, 0);
  ASSERT_EQ (pcl::io::loadPCDFile (out, reversed_output), 0);
  ASSERT_EQ (reversed_output.size(), output.size());
  for (std::size_t i = 0; i < output.size(); ++i)
    ASSERT_EQ (output[i].label, reversed_output[output.size() - 1 - i].label) << i;
}

TEST (HolesTool, RealScans)
{
  for (const char* name : {"milk.pcd", "bunny.pcd"}) {
    PCL_TDA_REQUIRE_DATA (name);
    const std::string out = temporaryPath ("real.pcd");
    const RunResult result = runTool (pcl::tda::test::dataFile (name) + " " + out);
    EXPECT_EQ (result.exit_code, 0) << name << "\n" << result.output;
    pcl::PointCloud<pcl::PointXYZL> output;
    ASSERT_EQ (pcl::io::loadPCDFile (out, output), 0);
    pcl::PointCloud<pcl::PointXYZ> input;
    ASSERT_EQ (pcl::io::loadPCDFile (pcl::tda::test::dataFile (name), input), 0);
    EXPECT_EQ (output.size(), input.size());
  }
}

} // namespace
