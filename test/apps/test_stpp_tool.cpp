// End-to-end tests of pcl_tda_stpp: one row per file with its path as given and the
// values STPPEstimation gives on it (the oracle: the class on the same file), the
// same rows for any thread count, a file that fails skipped with a non-zero exit,
// and the refusals (non-zero exit, no output written).

#include <pcl/io/pcd_io.h>
#include <pcl/tda/apps/csv_fields.h>
#include <pcl/tda/features/stpp_estimation.h>
#include <pcl/tda/generators/object_views.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "tool_runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using pcl::tda::test::exists;
using pcl::tda::test::run;
using pcl::tda::test::RunResult;

namespace {

RunResult
runTool (const std::string& arguments)
{
  return run (std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_stpp " + arguments);
}

std::vector<std::string>
linesOf (const std::string& path)
{
  std::ifstream in (path);
  std::vector<std::string> lines;
  for (std::string line; std::getline (in, line);)
    lines.push_back (line);
  return lines;
}

/** Writes views of three categories into \a folder; returns their paths. */
std::vector<std::string>
writeViews (const std::string& folder)
{
  pcl::tda::ObjectViewParameters parameters;
  parameters.seed = 7;
  std::vector<std::string> paths;
  for (const auto category : {pcl::tda::ObjectCategory::MUG,
                              pcl::tda::ObjectCategory::RING,
                              pcl::tda::ObjectCategory::BOX}) {
    const pcl::tda::ObjectView view =
        pcl::tda::renderObjectView (parameters, category, 0, 0);
    paths.push_back (folder + "/" + pcl::tda::objectCategoryName (category) + ".pcd");
    pcl::io::savePCDFileBinary (paths.back(), *view.cloud);
  }
  return paths;
}

std::string
join (const std::vector<std::string>& paths)
{
  std::string text;
  for (const std::string& path : paths)
    text += " " + path;
  return text;
}

TEST (STPPTool, WritesTheClassSignatureOfEveryFileInInputOrder)
{
  const std::string folder = pcl::tda::test::temporaryFolder ("stpp_tool");
  std::vector<std::string> paths = writeViews (folder);
  const std::string csv = folder + "/out.csv";
  const RunResult result = runTool (csv + join (paths) + " -threads 1");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  const std::vector<std::string> lines = linesOf (csv);
  ASSERT_EQ (lines.size(), paths.size() + 1);
  const std::vector<std::string> header = pcl::tda::splitCSVLine (lines[0]);
  ASSERT_EQ (header.size(), pcl::tda::STPP_SIGNATURE_SIZE + 1);
  EXPECT_EQ (header[0], "path");
  EXPECT_EQ (header[1], "f0");
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::vector<std::string> row = pcl::tda::splitCSVLine (lines[i + 1]);
    ASSERT_EQ (row.size(), header.size());
    EXPECT_EQ (row[0], paths[i]);
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
    ASSERT_EQ (pcl::io::loadPCDFile (paths[i], *cloud), 0);
    pcl::tda::STPPEstimation<pcl::PointXYZ> stpp;
    stpp.setInputCloud (cloud);
    pcl::PointCloud<pcl::tda::STPPSignature> signature;
    stpp.compute (signature);
    ASSERT_EQ (signature.size(), 1u);
    for (std::size_t k = 0; k < pcl::tda::STPP_SIGNATURE_SIZE; ++k)
      EXPECT_FLOAT_EQ (std::stof (row[k + 1]), signature[0].histogram[k])
          << paths[i] << " value " << k;
  }

  // Other threads and the inputs in reverse order: the same rows, reversed.
  const std::string reversed_csv = folder + "/reversed.csv";
  const std::vector<std::string> reversed (paths.rbegin(), paths.rend());
  ASSERT_EQ (runTool (reversed_csv + join (reversed) + " -threads 2").exit_code, 0);
  const std::vector<std::string> other = linesOf (reversed_csv);
  ASSERT_EQ (other.size(), lines.size());
  EXPECT_EQ (other[0], lines[0]);
  for (std::size_t i = 0; i < paths.size(); ++i)
    EXPECT_EQ (other[i + 1], lines[paths.size() - i]);
}

TEST (STPPTool, ReadsAListAndSelectsTheDescriptor)
{
  const std::string folder = pcl::tda::test::temporaryFolder ("stpp_tool");
  const std::vector<std::string> paths = writeViews (folder);
  // Relative to the list's folder, spaces around, a blank line, a comment and a
  // UTF-8 byte order mark.
  const std::string list = folder + "/files.txt";
  std::ofstream (list) << "\xEF\xBB\xBF# views\n  " << paths[0] << " \t\n\n"
                       << std::filesystem::path (paths[1]).filename().string()
                       << "\r\n";
  const std::string csv = folder + "/out.csv";
  const RunResult result = runTool (csv + " " + paths[2] + " -list " + list +
                                    " -descriptor stpp1 -radius 0.004");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  const std::vector<std::string> lines = linesOf (csv);
  ASSERT_EQ (lines.size(), 4u);
  EXPECT_EQ (pcl::tda::splitCSVLine (lines[1])[0], paths[2]);
  EXPECT_EQ (pcl::tda::splitCSVLine (lines[2])[0], paths[0]);
  EXPECT_EQ (pcl::tda::splitCSVLine (lines[3])[0], paths[1]);
  EXPECT_EQ (pcl::tda::splitCSVLine (lines[0]).size(),
             pcl::tda::STPP_SIZE_OFFSET - pcl::tda::STPP_BETTI1_OFFSET + 2);

  const std::string covariance_csv = folder + "/covariance.csv";
  ASSERT_EQ (
      runTool (covariance_csv + " " + paths[0] + " -descriptor covariance").exit_code,
      0);
  EXPECT_EQ (pcl::tda::splitCSVLine (linesOf (covariance_csv)[0]).size(),
             pcl::tda::COVARIANCE_SIGNATURE_SIZE + 1);

  // A view in units of about 1e-25 (2^-83 metres, exact in float) has its normals:
  // they were estimated in float, whose sums of squares underflowed ("fewer than 3
  // points have a normal").
  pcl::PointCloud<pcl::PointXYZRGB> view;
  ASSERT_EQ (pcl::io::loadPCDFile (paths[0], view), 0);
  for (auto& point : view)
    point.getVector3fMap() *= std::ldexp (1.0f, -83);
  const std::string tiny = folder + "/tiny.pcd", tiny_csv = folder + "/tiny.csv";
  pcl::io::savePCDFileBinary (tiny, view);
  const RunResult tiny_result =
      runTool (tiny_csv + " " + tiny + " -descriptor covariance");
  ASSERT_EQ (tiny_result.exit_code, 0) << tiny_result.output;
  EXPECT_EQ (pcl::tda::splitCSVLine (linesOf (tiny_csv)[1]).size(),
             pcl::tda::COVARIANCE_SIGNATURE_SIZE + 1);
}

// The descriptors do not depend on the order of a file's points: the covariance
// descriptor's normals (PCL's, sums over neighbours in point order) included.
TEST (STPPTool, SameValuesForShuffledPoints)
{
  const std::string folder = pcl::tda::test::temporaryFolder ("stpp_tool");
  const std::vector<std::string> paths = writeViews (folder);
  pcl::PointCloud<pcl::PointXYZRGB> view, shuffled;
  ASSERT_EQ (pcl::io::loadPCDFile (paths[0], view), 0);
  std::vector<std::size_t> order (view.size());
  std::iota (order.begin(), order.end(), 0);
  std::shuffle (order.begin(), order.end(), std::mt19937 (5));
  for (const std::size_t i : order)
    shuffled.push_back (view[i]);
  const std::string shuffled_path = folder + "/shuffled.pcd";
  pcl::io::savePCDFileBinary (shuffled_path, shuffled);
  for (const std::string descriptor : {"covariance", "stpp"}) {
    const std::string csv = folder + "/" + descriptor + ".csv";
    ASSERT_EQ (runTool (csv + " " + paths[0] + " " + shuffled_path + " -descriptor " +
                        descriptor)
                   .exit_code,
               0);
    const std::vector<std::string> lines = linesOf (csv);
    ASSERT_EQ (lines.size(), 3u);
    EXPECT_EQ (lines[1].substr (lines[1].find (',')),
               lines[2].substr (lines[2].find (',')))
        << descriptor;
  }
}

TEST (STPPTool, SkipsAFileThatFailsAndExitsNonZero)
{
  const std::string folder = pcl::tda::test::temporaryFolder ("stpp_tool");
  const std::vector<std::string> paths = writeViews (folder);
  const std::string broken = folder + "/broken.pcd";
  std::ofstream (broken) << "not a PCD file\n";
  const std::string csv = folder + "/out.csv";
  const RunResult result = runTool (csv + " " + paths[0] + " " + broken);
  EXPECT_EQ (result.exit_code, 1);
  EXPECT_NE (result.output.find ("Skipping " + broken), std::string::npos)
      << result.output;
  const std::vector<std::string> lines = linesOf (csv);
  ASSERT_EQ (lines.size(), 2u);
  EXPECT_EQ (pcl::tda::splitCSVLine (lines[1])[0], paths[0]);

  // Nothing described: nothing written.
  const std::string none = folder + "/none.csv";
  EXPECT_EQ (runTool (none + " " + broken).exit_code, 1);
  EXPECT_FALSE (exists (none));
}

TEST (STPPTool, RefusesComplexesOverTheMemoryLimit)
{
  // The mug's complex at radius 1 cm takes a few MiB: refused at -memory 1, by STPP
  // and by the covariance descriptor, naming -memory; described at -memory 8.
  const std::string folder = pcl::tda::test::temporaryFolder ("stpp_tool");
  const std::vector<std::string> paths = writeViews (folder);
  const std::string csv = folder + "/out.csv";
  for (const std::string descriptor : {"stpp", "covariance"}) {
    const std::string arguments =
        csv + " " + paths[0] + " -radius 0.01 -threads 1 -descriptor " + descriptor;
    const RunResult refused = runTool (arguments + " -memory 1");
    EXPECT_EQ (refused.exit_code, 1) << refused.output;
    EXPECT_NE (refused.output.find ("its complex could not be built, over the memory "
                                    "limit of 1.0 MiB (a smaller -radius or a larger "
                                    "-memory)"),
               std::string::npos)
        << refused.output;
    EXPECT_FALSE (exists (csv));
    const RunResult accepted = runTool (arguments + " -memory 8");
    EXPECT_EQ (accepted.exit_code, 0) << accepted.output;
    EXPECT_EQ (linesOf (csv).size(), 2u);
    std::remove (csv.c_str());
  }
}

TEST (STPPTool, SkipsAViewTooFarFromTheOriginForItsRadius)
{
  // The mug moved to UTM-like coordinates (x + 5e6, where floats are 0.5 apart): its
  // radius, a few millimetres, cannot be resolved; skipped, saying so, by both
  // topological descriptors.
  const std::string folder = pcl::tda::test::temporaryFolder ("stpp_tool");
  const std::vector<std::string> paths = writeViews (folder);
  pcl::PointCloud<pcl::PointXYZ> far;
  ASSERT_EQ (pcl::io::loadPCDFile (paths[0], far), 0);
  for (auto& point : far)
    point.x += 5e6f;
  const std::string far_path = folder + "/far.pcd";
  pcl::io::savePCDFileBinary (far_path, far);
  const std::string csv = folder + "/out.csv";
  for (const std::string descriptor : {"stpp", "covariance"}) {
    const RunResult result =
        runTool (csv + " " + far_path + " " + paths[1] + " -descriptor " + descriptor);
    EXPECT_EQ (result.exit_code, 1) << result.output;
    EXPECT_NE (result.output.find ("Skipping " + far_path + ": The coordinates reach"),
               std::string::npos)
        << result.output;
    EXPECT_EQ (linesOf (csv).size(), 2u); // the other view
  }
}

TEST (STPPTool, RefusesBadInputAndWritesNothing)
{
  const std::string folder = pcl::tda::test::temporaryFolder ("stpp_tool");
  const std::vector<std::string> paths = writeViews (folder);
  const std::string csv = folder + "/out.csv";
  const std::string list = folder + "/list.csv";
  std::ofstream (list) << paths[0] << "\n";
  for (const std::string& arguments : {std::string (""),
                                       csv,
                                       csv + " " + paths[0] + " -descriptor vfh",
                                       csv + " " + paths[0] + " -radius -1",
                                       csv + " " + paths[0] + " -radius abc",
                                       csv + " " + paths[0] + " -threads 0",
                                       csv + " " + paths[0] + " -threads 257",
                                       csv + " " + paths[0] + " -memory 0",
                                       csv + " " + paths[0] + " -memory abc",
                                       csv + " " + paths[0] + " -unknown 1",
                                       folder + "/out.txt " + paths[0],
                                       csv + " " + folder + "/x.ply",
                                       csv + " -list " + folder + "/missing.txt",
                                       list + " -list " + list}) {
    const RunResult result = runTool (arguments);
    EXPECT_NE (result.exit_code, 0) << arguments << "\n" << result.output;
    EXPECT_FALSE (exists (csv)) << arguments;
  }
  // The list named as the output is refused and left as it was.
  EXPECT_EQ (linesOf (list).size(), 1u);
}

} // namespace
