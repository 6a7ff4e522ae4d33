// End-to-end tests of pcl_tda_generate: loadable files of every kind, the same
// tabletop, colour region, depth camera scenes, hole surfaces and object views as the
// library, and refusals that leave no files behind.

#include <pcl/io/pcd_io.h>
#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/tda/generators/hole_surfaces.h>
#include <pcl/tda/generators/object_views.h>
#include <pcl/tda/generators/tabletop_scenes.h>

#include <gtest/gtest.h>

#include "generators/generator_test_utils.h"
#include "tool_runner.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <vector>

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

/** The names of the files in \a folder. */
std::set<std::string>
fileNames (const std::string& folder)
{
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator (folder))
    names.insert (entry.path().filename().string());
  return names;
}

std::string
contents (const std::string& path)
{
  std::ifstream file (path, std::ios::binary);
  return {std::istreambuf_iterator<char> (file), std::istreambuf_iterator<char>()};
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
  EXPECT_NE (0, runTool ("circle " + file + " -objects 2"));
  EXPECT_NE (0, runTool ("sphere " + file + " -colour-noise 2"));
  EXPECT_NE (0, runTool ("regions " + file + " -colour-noise -1"));
  EXPECT_NE (0, runTool ("regions " + file + " -colour-noise 300"));
  EXPECT_NE (0, runTool ("regions " + file + " -colour-noise abc"));
  EXPECT_NE (0, runTool ("regions " + file + " -objects 9"));
  EXPECT_NE (0, runTool ("depth-regions " + file + " -n 1000"));
  EXPECT_NE (0, runTool ("depth-regions " + file + " -objects 0"));
  EXPECT_NE (0, runTool ("depth-regions " + file + " -noise -1"));
  EXPECT_NE (0, runTool ("region " + file));
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

TEST (GenerateTool, WritesColourRegionScenesLabelledByRegion)
{
  const TemporaryFolder folder;
  // Painted tabletop scenes: the library's scene, labelled by region.
  const std::string file = folder.path() + "/regions.pcd";
  ASSERT_EQ (0,
             runTool ("regions " + file +
                      " -objects 3 -seed 5 -noise 0.001 -colour-noise 6 -n 10000"));
  Cloud cloud;
  ASSERT_EQ (0, pcl::io::loadPCDFile (file, cloud));
  TabletopParameters parameters;
  parameters.colour_regions = true;
  parameters.num_objects = 3;
  parameters.seed = 5;
  parameters.noise_sigma = 0.001f;
  parameters.colour_noise = 6.0f;
  parameters.point_spacing = static_cast<float> (std::sqrt (
      static_cast<double> (parameters.table_width) * parameters.table_depth / 10000));
  const TabletopScene scene = pcl::tda::generateTabletopScene (parameters);
  EXPECT_TRUE (identical (*pcl::tda::regionLabelledCloud (scene), cloud));
  std::set<std::uint32_t> labels;
  for (const auto& point : cloud)
    labels.insert (point.label);
  EXPECT_EQ (scene.regions.size(), labels.size());
  EXPECT_EQ (1u, *labels.begin());
  EXPECT_EQ (scene.regions.size(), *labels.rbegin());
  EXPECT_GT (labels.size(), 3u + 1u);

  // By default, the moderate noise of the benchmark.
  ASSERT_EQ (0, runTool ("regions " + file + " -seed 6"));
  ASSERT_EQ (0, pcl::io::loadPCDFile (file, cloud));
  TabletopParameters moderate;
  moderate.colour_regions = true;
  moderate.seed = 6;
  moderate.setNoise (pcl::tda::TABLETOP_MODERATE_NOISE);
  EXPECT_TRUE (identical (
      *pcl::tda::regionLabelledCloud (pcl::tda::generateTabletopScene (moderate)),
      cloud));

  // -colour-noise also sets the colour noise of the unpainted scene.
  const std::string tabletop = folder.path() + "/tabletop.pcd";
  ASSERT_EQ (0, runTool ("tabletop " + tabletop + " -seed 2 -colour-noise 0"));
  ASSERT_EQ (0, pcl::io::loadPCDFile (tabletop, cloud));
  TabletopParameters plain;
  plain.seed = 2;
  plain.colour_noise = 0.0f;
  EXPECT_TRUE (identical (*pcl::tda::generateTabletopScene (plain).cloud, cloud));

  // Depth camera frames: organized, the table kept, labelled by region.
  const std::string frame = folder.path() + "/frame.pcd";
  ASSERT_EQ (0,
             runTool ("depth-regions " + frame +
                      " -objects 4 -seed 3 -noise 0.002 -colour-noise 3"));
  ASSERT_EQ (0, pcl::io::loadPCDFile (frame, cloud));
  pcl::tda::DepthCameraParameters camera;
  camera.colour_regions = true;
  camera.remove_table = false;
  camera.min_objects = camera.max_objects = 4;
  camera.seed = 3;
  camera.noise_coefficient = 0.002f;
  camera.colour_noise = 3.0f;
  const pcl::tda::DepthCameraScene depth = pcl::tda::generateDepthCameraScene (camera);
  EXPECT_EQ (640u, cloud.width);
  EXPECT_EQ (480u, cloud.height);
  EXPECT_TRUE (identical (*pcl::tda::regionLabelledCloud (depth), cloud));
  EXPECT_EQ (4u, depth.objects.size());
  EXPECT_EQ (pcl::tda::DEPTH_BACKGROUND_LABEL, depth.regions.at (0).object_label);
}

TEST (GenerateTool, WritesHoleSurfacesAndTheRemovedPoints)
{
  const TemporaryFolder folder;
  const std::string file = folder.path() + "/holes.pcd";
  const std::string removed = folder.path() + "/removed.pcd";
  ASSERT_EQ (0,
             runTool ("holes " + file +
                      " -surface torus -n 5000 -hole-radii 3,4.5 -noise 0.1 -remove "
                      "0.2 -removed " +
                      removed + " -seed 3"));
  pcl::PointCloud<pcl::PointXYZL> cloud;
  pcl::PointCloud<pcl::PointXYZ> gone;
  ASSERT_EQ (0, pcl::io::loadPCDFile (file, cloud));
  ASSERT_EQ (0, pcl::io::loadPCDFile (removed, gone));
  pcl::tda::HoleSurfaceParameters parameters;
  parameters.kind = pcl::tda::HoleSurfaceKind::TORUS;
  parameters.num_points = 5000;
  parameters.hole_radii = {3.0f, 4.5f};
  parameters.noise_sigma = 0.1f;
  parameters.removal_fraction = 0.2f;
  parameters.seed = 3;
  const pcl::tda::HoleSurface surface = pcl::tda::generateHoleSurface (parameters);
  EXPECT_TRUE (identical (*surface.cloud, cloud));
  EXPECT_TRUE (identical (*surface.removed, gone));
  EXPECT_FALSE (gone.empty());

  // The defaults: a plane with holes of radii 3, 5 and 8, no noise, no removal.
  ASSERT_EQ (0, runTool ("holes " + file + " -seed 1"));
  ASSERT_EQ (0, pcl::io::loadPCDFile (file, cloud));
  pcl::tda::HoleSurfaceParameters defaults;
  defaults.seed = 1;
  EXPECT_TRUE (identical (*pcl::tda::generateHoleSurface (defaults).cloud, cloud));

  // Every surface.
  for (const std::string surface_name :
       {"plane", "sphere", "cylinder", "torus", "heightfield"}) {
    SCOPED_TRACE (surface_name);
    ASSERT_EQ (0,
               runTool ("holes " + file + " -surface " + surface_name +
                        " -n 3000 -hole-radii 2 -seed 4"));
    ASSERT_EQ (0, pcl::io::loadPCDFile (file, cloud));
    std::set<std::uint32_t> labels;
    for (const auto& point : cloud)
      labels.insert (point.label);
    EXPECT_EQ (1u, labels.count (1u));
    EXPECT_EQ (surface_name == "sphere" || surface_name == "torus" ? 0u : 1u,
               labels.count (pcl::tda::OUTER_BORDER_LABEL));
  }
  // No temporary files are left behind.
  EXPECT_EQ ((std::set<std::string>{"holes.pcd", "removed.pcd"}),
             fileNames (folder.path()));
}

TEST (GenerateTool, HolesFailOnBadArgumentsWithoutWritingFiles)
{
  const TemporaryFolder folder;
  const std::string file = folder.path() + "/out.pcd";
  const std::string removed = folder.path() + "/removed.pcd";
  const std::vector<std::string> bad = {
      "-surface cube",
      "-surface Plane",
      "-surface",
      "-hole-radii 3,,5",
      "-hole-radii 3,",
      "-hole-radii ,3",
      "-hole-radii '3;5'", // quoted for the shell
      "-hole-radii 0.5",
      "-hole-radii -3",
      "-hole-radii abc",
      "-hole-radii 1e40",
      "-hole-radii 200", // does not fit
      "-hole-radii 10,10,10,10,10,10,10,10,10,10,10,10,10,10,10,10,10,10,10,10,10,10",
      "-noise 1",
      "-noise -0.1",
      "-remove 0.9",
      "-remove -0.1",
      "-remove 1",
      "-remove x",
      "-removed " + removed, // without -remove
      "-remove 0 -removed " + removed,
      "-remove 0.1 -removed " + folder.path() + "/removed.txt",
      "-remove 0.1 -removed " + file, // the output itself
      "-n 999",
      "-n 0",
      "-objects 2",
      "-colour-noise 3",
      "-seed -1",
      "-surface plane -surface torus",
  };
  for (const std::string& arguments : bad)
    EXPECT_NE (0, runTool ("holes " + file + " " + arguments)) << arguments;
  // The options of holes do not apply to other kinds.
  EXPECT_NE (0, runTool ("circle " + file + " -surface plane"));
  EXPECT_NE (0, runTool ("sphere " + file + " -hole-radii 3"));
  EXPECT_NE (0, runTool ("tabletop " + file + " -remove 0.1"));
  EXPECT_NE (0, runTool ("torus " + file + " -removed " + removed));
  EXPECT_TRUE (fileNames (folder.path()).empty());

  // A failed run leaves existing outputs as they were.
  ASSERT_EQ (0, runTool ("holes " + file + " -n 2000 -remove 0.1 -removed " + removed));
  const std::string before = contents (file), removed_before = contents (removed);
  EXPECT_NE (0,
             runTool ("holes " + file +
                      " -n 2000 -hole-radii 200 -remove 0.1 -removed " + removed));
  EXPECT_EQ (before, contents (file));
  EXPECT_EQ (removed_before, contents (removed));
  EXPECT_EQ ((std::set<std::string>{"out.pcd", "removed.pcd"}),
             fileNames (folder.path()));
}

TEST (GenerateTool, WritesADataSetOfObjectViewsWithItsManifest)
{
  const TemporaryFolder folder;
  const std::string out = folder.path() + "/views";
  ASSERT_EQ (0,
             runTool ("shapes " + out +
                      " -categories ring,box -instances 2 -views 2 -noise 2 -seed 4"));
  // The manifest lists every view, paths relative to its folder.
  EXPECT_EQ ("path,category,instance,view\n"
             "ring_0_0.pcd,ring,0,0\nring_0_1.pcd,ring,0,1\n"
             "ring_1_0.pcd,ring,1,0\nring_1_1.pcd,ring,1,1\n"
             "box_0_0.pcd,box,0,0\nbox_0_1.pcd,box,0,1\n"
             "box_1_0.pcd,box,1,0\nbox_1_1.pcd,box,1,1\n",
             contents (out + "/manifest.csv"));
  EXPECT_EQ ((std::set<std::string>{"manifest.csv",
                                    "ring_0_0.pcd",
                                    "ring_0_1.pcd",
                                    "ring_1_0.pcd",
                                    "ring_1_1.pcd",
                                    "box_0_0.pcd",
                                    "box_0_1.pcd",
                                    "box_1_0.pcd",
                                    "box_1_1.pcd"}),
             fileNames (out));
  // Each file is the library's view.
  pcl::tda::ObjectViewParameters parameters;
  parameters.categories = {pcl::tda::ObjectCategory::RING,
                           pcl::tda::ObjectCategory::BOX};
  parameters.instances = parameters.views = 2;
  parameters.noise_multiplier = 2.0f;
  parameters.seed = 4;
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  ASSERT_EQ (0, pcl::io::loadPCDFile (out + "/box_1_0.pcd", cloud));
  EXPECT_TRUE (identical (
      *pcl::tda::renderObjectView (parameters, pcl::tda::ObjectCategory::BOX, 1, 0)
           .cloud,
      cloud));
  EXPECT_EQ (cloud.size(), cloud.width);
  EXPECT_EQ (1u, cloud.height);

  // A second data set is never mixed into the folder.
  const std::string manifest = contents (out + "/manifest.csv");
  const pcl::tda::test::RunResult refused =
      pcl::tda::test::run (std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_generate shapes " +
                           out + " -categories cup -instances 1 -views 1");
  EXPECT_NE (0, refused.exit_code);
  EXPECT_NE (std::string::npos, refused.output.find ("manifest.csv")) << refused.output;
  EXPECT_EQ (manifest, contents (out + "/manifest.csv"));
  EXPECT_EQ (9u, fileNames (out).size());

  // An existing folder without a manifest takes a data set; its files stay.
  const std::string other = folder.path() + "/other";
  std::filesystem::create_directory (other);
  std::ofstream (other + "/notes.txt") << "mine\n";
  ASSERT_EQ (0, runTool ("shapes " + other + " -categories cup -instances 1 -views 1"));
  EXPECT_EQ ((std::set<std::string>{"cup_0_0.pcd", "manifest.csv", "notes.txt"}),
             fileNames (other));
}

TEST (GenerateTool, ObjectViewsFailOnBadArgumentsWithoutWritingFiles)
{
  const TemporaryFolder folder;
  const std::string out = folder.path() + "/views";
  const std::vector<std::string> bad = {
      "-instances 0",
      "-instances -1",
      "-instances 1001",
      "-instances many",
      "-views 0",
      "-views 1001",
      "-categories mug,foo",
      "-categories mug,mug",
      "-categories mug,",
      "-categories Mug",
      "-categories",
      "-noise -1",
      "-noise 101",
      "-noise abc",
      "-colour-noise -1",
      "-colour-noise 300",
      "-seed -1",
      "-n 100",
      "-objects 2",
      "-surface plane",
      "-remove 0.1",
      "-views 2 -views 3",
      out + "/extra",
  };
  for (const std::string& arguments : bad) {
    // Small data sets, should an argument be taken.
    const bool counts = arguments.find ("-instances") != std::string::npos ||
                        arguments.find ("-views") != std::string::npos;
    EXPECT_NE (0,
               runTool ("shapes " + out + (counts ? " " : " -instances 1 -views 1 ") +
                        arguments))
        << arguments;
  }
  // The options of shapes do not apply to other kinds.
  const std::string file = folder.path() + "/out.pcd";
  EXPECT_NE (0, runTool ("circle " + file + " -instances 2"));
  EXPECT_NE (0, runTool ("tabletop " + file + " -views 2"));
  EXPECT_NE (0, runTool ("depth-regions " + file + " -categories mug"));
  // The output must be a folder whose parent exists.
  EXPECT_NE (0, runTool ("shapes " + folder.path() + "/missing/views"));
  std::ofstream (file) << "not a folder\n";
  EXPECT_NE (0, runTool ("shapes " + file + " -instances 1 -views 1"));
  EXPECT_EQ ((std::set<std::string>{"out.pcd"}), fileNames (folder.path()));
}
