// End-to-end tests of pcl_tda_generate: loadable files of every kind, the same
// tabletop scene as the library, and refusals that leave no files behind.

#include <pcl/io/pcd_io.h>
#include <pcl/tda/generators/tabletop_scenes.h>

#include <gtest/gtest.h>

#include "generators/generator_test_utils.h"
#include "tool_runner.h"

#include <filesystem>
#include <map>
#include <set>
#include <string>

using pcl::tda::TabletopParameters;
using pcl::tda::TabletopScene;
using pcl::tda::test::identical;
using pcl::tda::test::TemporaryFolder;
using Cloud = pcl::PointCloud<pcl::PointXYZRGBL>;

namespace {

/** Runs pcl_tda_generate with \a arguments and returns its exit code. */
int
runTool (const std::string& arguments)
{
  return pcl::tda::test::run (std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_generate " +
                              arguments)
      .exit_code;
}

} // namespace

TEST (GenerateTool, WritesEveryKindAsLoadablePCD)
{
  const TemporaryFolder folder;
  const std::map<std::string, std::size_t> sizes = {
      {"circle", 800}, {"torus", 3000}, {"sphere", 1200}};
  for (const auto& [kind, size] : sizes) {
    SCOPED_TRACE (kind);
    const std::string file = folder.path() + "/" + kind + ".pcd";
    ASSERT_EQ (0,
               runTool (kind + " " + file + " -n " + std::to_string (size) +
                        " -noise 0.005 -seed 3"));
    Cloud cloud;
    ASSERT_EQ (0, pcl::io::loadPCDFile (file, cloud));
    EXPECT_EQ (size, cloud.size());
  }
  const std::string file = folder.path() + "/tabletop.pcd";
  ASSERT_EQ (0, runTool ("tabletop " + file + " -objects 3 -seed 5"));
  Cloud cloud;
  ASSERT_EQ (0, pcl::io::loadPCDFile (file, cloud));
  TabletopParameters parameters;
  parameters.num_objects = 3;
  parameters.seed = 5;
  const TabletopScene scene = pcl::tda::generateTabletopScene (parameters);
  EXPECT_TRUE (identical (*scene.cloud, cloud));
  // No temporary files are left behind.
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator (folder.path()))
    names.insert (entry.path().filename().string());
  const std::set<std::string> expected = {
      "circle.pcd", "sphere.pcd", "tabletop.pcd", "torus.pcd"};
  EXPECT_EQ (expected, names);
}

TEST (GenerateTool, FailsOnBadArgumentsWithoutLeavingFiles)
{
  const TemporaryFolder folder;
  const std::string file = folder.path() + "/out.pcd";
  EXPECT_NE (0, runTool ("cube " + file));
  EXPECT_NE (0, runTool ("circle " + file + " -n 0"));
  EXPECT_NE (0, runTool ("circle " + file + " -n -5"));
  EXPECT_NE (0, runTool ("circle " + file + " -n many"));
  EXPECT_NE (0, runTool ("circle " + file + " -noise -0.1"));
  EXPECT_NE (0, runTool ("circle " + file + " -seed -1"));
  EXPECT_NE (0, runTool ("circle " + file + " -radius 2"));
  EXPECT_NE (0, runTool ("circle " + file + " -n"));
  EXPECT_NE (0, runTool ("tabletop " + file + " -objects 99"));
  EXPECT_NE (0, runTool ("circle"));
  EXPECT_FALSE (std::filesystem::exists (file));
  // Unwritable outputs: a path in a missing folder, and an existing folder.
  EXPECT_NE (0, runTool ("circle " + folder.path() + "/missing/out.pcd"));
  const std::string subfolder = folder.path() + "/taken";
  std::filesystem::create_directory (subfolder);
  EXPECT_NE (0, runTool ("sphere " + subfolder));
  EXPECT_TRUE (std::filesystem::is_directory (subfolder));
  // Nothing but the subfolder: no partial or temporary files.
  EXPECT_EQ (1,
             std::distance (std::filesystem::directory_iterator (folder.path()),
                            std::filesystem::directory_iterator()));
}
