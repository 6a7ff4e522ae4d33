// End-to-end tests of pcl_tda_classify: a small set of clearly different generated
// shapes classified without error by ESF, results that do not depend on the
// number of threads, the outputs, failed views counted as wrong, and the refusals
// of bad manifests and options (non-zero exit, no output written).

#include <pcl/io/pcd_io.h>
#include <pcl/tda/apps/csv_fields.h>
#include <pcl/tda/generators/random_sampling.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "tool_runner.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using pcl::tda::test::run;
using pcl::tda::test::RunResult;

namespace {

std::string
testFolder ()
{
  return pcl::tda::test::temporaryFolder ("classify_tool");
}

RunResult
runTool (const std::string& arguments)
{
  return run (std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_classify " + arguments);
}

std::string
contentOf (const std::string& path)
{
  std::ostringstream text;
  text << std::ifstream (path, std::ios::binary).rdbuf();
  return text.str();
}

/** A point on the surface of a shape of \a category, of size about 1. */
Eigen::Vector3d
surfacePoint (const std::string& category,
              const Eigen::Vector3d& proportions,
              pcl::tda::PortableRandom& random)
{
  if (category == "ball") {
    Eigen::Vector3d direction (random.normal(), random.normal(), random.normal());
    return 0.5 * direction.normalized().cwiseProduct (proportions);
  }
  if (category == "box") {
    const auto face = static_cast<int> (random.index (6));
    Eigen::Vector3d point (random.uniform (-0.5, 0.5),
                           random.uniform (-0.5, 0.5),
                           random.uniform (-0.5, 0.5));
    point[face / 2] = face % 2 == 0 ? -0.5 : 0.5;
    return point.cwiseProduct (proportions);
  }
  // ring: a torus of tube radius 0.1 around a circle of radius 0.4
  const double u = random.uniform (0.0, 2.0 * M_PI),
               v = random.uniform (0.0, 2.0 * M_PI);
  const double radius = 0.4 + 0.1 * std::cos (v);
  return Eigen::Vector3d (
             radius * std::cos (u), radius * std::sin (u), 0.1 * std::sin (v))
      .cwiseProduct (proportions);
}

/** Writes the views of a small data set to \a folder and its manifest: \a instances
 * instances of each category (own proportions and size), \a views views of each
 * (own orientation and sample), 400 points 1 m in front of the sensor. */
std::string
writeShapes (const std::string& folder,
             const std::vector<std::string>& categories,
             std::size_t instances,
             std::size_t views)
{
  std::string manifest = "path,category,instance,view\n";
  for (const std::string& category : categories)
    for (std::size_t i = 0; i < instances; ++i) {
      pcl::tda::PortableRandom shape (1000 * (i + 1) + category.size());
      const Eigen::Vector3d proportions (
          shape.uniform (0.8, 1.2), shape.uniform (0.8, 1.2), shape.uniform (0.8, 1.2));
      const double size = shape.uniform (0.15, 0.3);
      for (std::size_t v = 0; v < views; ++v) {
        pcl::tda::PortableRandom random (shape.index (1u << 30));
        const Eigen::Quaterniond turn =
            Eigen::Quaterniond (
                random.normal(), random.normal(), random.normal(), random.normal())
                .normalized();
        pcl::PointCloud<pcl::PointXYZ> cloud;
        for (int k = 0; k < 400; ++k) {
          const Eigen::Vector3d point =
              turn * surfacePoint (category, proportions, random) * size +
              Eigen::Vector3d (0, 0, 1);
          cloud.push_back (pcl::PointXYZ (static_cast<float> (point.x()),
                                          static_cast<float> (point.y()),
                                          static_cast<float> (point.z())));
        }
        const std::string file = "views/" + category + "_" + std::to_string (i) + "_" +
                                 std::to_string (v) + ".pcd";
        std::filesystem::create_directories (folder + "/views");
        pcl::io::savePCDFileBinary (folder + "/" + file, cloud);
        manifest += file + "," + category + ",i" + std::to_string (i) + "," +
                    std::to_string (v) + "\n";
      }
    }
  std::ofstream (folder + "/manifest.csv") << manifest;
  return folder + "/manifest.csv";
}

/** The rows of a results CSV by descriptor, each a map from column to value. */
std::map<std::string, std::map<std::string, std::string>>
readResults (const std::string& path)
{
  std::ifstream file (path);
  std::string line;
  std::getline (file, line);
  const std::vector<std::string> header = pcl::tda::splitCSVLine (line);
  std::map<std::string, std::map<std::string, std::string>> rows;
  while (std::getline (file, line)) {
    const std::vector<std::string> fields = pcl::tda::splitCSVLine (line);
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < header.size() && k < fields.size(); ++k)
      row[header[k]] = fields[k];
    rows[row["descriptor"]] = row;
  }
  return rows;
}

} // namespace

TEST (ClassifyTool, TellsClearlyDifferentShapesApart)
{
  const std::string folder = testFolder();
  const std::string manifest = writeShapes (folder, {"ball", "box", "ring"}, 3, 4);
  const std::string csv = folder + "/results.csv", features = folder + "/features.csv",
                    svg = folder + "/confusion.svg", png = folder + "/confusion.png";
  const RunResult result =
      runTool (manifest + " -descriptors esf,vfh -trials 4 -csv " + csv +
               " -features " + features + " -svg " + svg + " -png " + png);
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("36 views of 9 instances in 3 categories"),
             std::string::npos)
      << result.output;
  auto rows = readResults (csv);
  ASSERT_EQ (rows.count ("esf"), 1u) << contentOf (csv);
  EXPECT_EQ (rows["esf"]["accuracy_mean"], "1");
  EXPECT_EQ (rows["esf"]["accuracy_sd"], "0");
  EXPECT_EQ (rows["esf"]["dimension"], "640");
  EXPECT_EQ (rows["esf"]["failed_views"], "0");
  EXPECT_EQ (rows["esf"]["trials"], "4");
  EXPECT_EQ (rows["vfh"]["dimension"], "308");
  // Every view's descriptors, one line each.
  std::ifstream lines (features);
  std::size_t count = 0;
  for (std::string line; std::getline (lines, line);)
    ++count;
  EXPECT_EQ (count, 1u + 36 * 2);
  EXPECT_NE (contentOf (svg).find ("esf: accuracy 100.0"), std::string::npos);
  EXPECT_EQ (contentOf (png).substr (1, 3), "PNG");
}

TEST (ClassifyTool, GivesTheSameResultsOnAnyNumberOfThreads)
{
  const std::string folder = testFolder();
  const std::string manifest = writeShapes (folder, {"ball", "box", "ring"}, 3, 3);
  std::map<std::string, std::map<std::string, std::string>> results[2];
  std::string features[2];
  for (int threads = 1; threads <= 2; ++threads) {
    const std::string csv = folder + "/r" + std::to_string (threads) + ".csv";
    const std::string table = folder + "/f" + std::to_string (threads) + ".csv";
    const RunResult result = runTool (
        manifest + " -descriptors esf,grsd,stpp0,stpp0+esf -trials 3 -seed 5 " +
        "-threads " + std::to_string (threads) + " -csv " + csv + " -features " +
        table);
    ASSERT_EQ (result.exit_code, 0) << result.output;
    EXPECT_NE (result.output.find (", " + std::to_string (threads) + " threads"),
               std::string::npos);
    results[threads - 1] = readResults (csv);
    features[threads - 1] = contentOf (table);
  }
  EXPECT_EQ (features[0], features[1]);
  ASSERT_EQ (results[0].size(), 4u);
  for (auto& [descriptor, row] : results[0])
    for (const char* column : {"accuracy_mean",
                               "accuracy_sd",
                               "C",
                               "gamma",
                               "trial_accuracies",
                               "trial_C",
                               "trial_gamma"})
      EXPECT_EQ (row[column], results[1][descriptor][column])
          << descriptor << " " << column;
}

TEST (ClassifyTool, CountsViewsADescriptorFailsOnAsWrong)
{
  const std::string folder = testFolder();
  const std::string manifest = writeShapes (folder, {"ball", "box"}, 2, 2);
  // One view of two points: VFH has no normals there, ESF no triangle.
  pcl::PointCloud<pcl::PointXYZ> two;
  two.push_back (pcl::PointXYZ (0, 0, 1));
  two.push_back (pcl::PointXYZ (0.01f, 0, 1));
  pcl::io::savePCDFileBinary (folder + "/views/ball_0_0.pcd", two);
  const std::string csv = folder + "/results.csv";
  const RunResult result =
      runTool (manifest + " -descriptors esf,vfh -trials 2 -csv " + csv);
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("esf failed on views/ball_0_0.pcd"), std::string::npos)
      << result.output;
  EXPECT_NE (result.output.find ("esf failed on 1 of 8 views"), std::string::npos)
      << result.output;
  auto rows = readResults (csv);
  EXPECT_EQ (rows["esf"]["failed_views"], "1");
  EXPECT_EQ (rows["vfh"]["failed_views"], "1");
}

TEST (ClassifyTool, RefusesBadInputAndWritesNothing)
{
  const std::string folder = testFolder();
  const std::string manifest = writeShapes (folder, {"ball", "box"}, 2, 1);
  const std::string good = contentOf (manifest);
  const auto write = [&folder] (const std::string& name, const std::string& text) {
    std::ofstream (folder + "/" + name) << text;
    return folder + "/" + name;
  };
  const std::string no_column = write ("no_column.csv", "path,category,view\n");
  const std::string missing = write ("missing.csv", good + "views/none.pcd,box,i9,0\n");
  const std::string one_instance =
      write ("one.csv",
             "path,category,instance,view\nviews/ball_0_0.pcd,ball,i0,0\n"
             "views/box_0_0.pcd,box,i0,0\nviews/box_1_0.pcd,box,i1,0\n");
  const std::string unreadable = write ("views/broken.pcd", "not a point cloud\n");
  const std::string broken = write ("broken.csv", good + "views/broken.pcd,box,i7,0\n");
  const std::string out = folder + "/out.csv", picture = folder + "/out.svg";
  const std::string outputs = " -csv " + out + " -svg " + picture;
  const std::vector<std::pair<std::string, std::string>> cases{
      {no_column + outputs, "the header has no 'instance' column"},
      {missing + outputs, "the view file views/none.pcd does not exist"},
      {one_instance + outputs, "category ball has only one instance (i0)"},
      {broken + outputs, "Cannot read the view views/broken.pcd"},
      {folder + "/absent.csv" + outputs, "no such file"},
      {manifest + " -trials 0" + outputs, "Option -trials needs an integer from 1"},
      {manifest + " -trials abc" + outputs, "Option -trials needs an integer"},
      {manifest + " -folds 1" + outputs, "-folds needs at least 2 folds"},
      {manifest + " -threads 0" + outputs, "Option -threads needs an integer"},
      {manifest + " -descriptors esf,fpfh" + outputs, "Unknown descriptor 'fpfh'"},
      {manifest + " -scaling log" + outputs, "-scaling must be zscore or minmax"},
      {manifest + " -csv " + folder + "/out.txt", "-csv needs a .csv file"},
      {manifest + " -confusion vfh -descriptors esf" + outputs,
       "-confusion vfh is not one of the -descriptors"},
      {manifest + " -features " + manifest, "refusing to overwrite the input file"},
      {manifest + " extra.csv", "Need the manifest .csv file, not 2 arguments"},
  };
  for (const auto& [arguments, message] : cases) {
    const RunResult result = runTool (arguments);
    EXPECT_NE (result.exit_code, 0) << arguments;
    EXPECT_NE (result.output.find (message), std::string::npos) << arguments << "\n"
                                                                << result.output;
    EXPECT_FALSE (std::filesystem::exists (out)) << arguments;
    EXPECT_FALSE (std::filesystem::exists (picture)) << arguments;
  }
  EXPECT_EQ (contentOf (manifest), good);
  EXPECT_EQ (runTool ("").exit_code, 1);
  EXPECT_EQ (runTool ("-h").exit_code, 0);
}
