// End-to-end tests of pcl_tda_barcode: its diagrams against Ripser's on real scans and
// generated clouds, known Betti numbers, its JSON line, and its refusals.

#include <pcl/io/pcd_io.h>
#include <pcl/tda/common/diagram_comparison.h>
#include <pcl/tda/common/diagram_io.h>
#include <pcl/tda/common/phat_io.h>
#include <pcl/tda/generators/shapes.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "test_data.h"
#include "tool_runner.h"
#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

using namespace pcl::tda;
using pcl::tda::test::exists;
using pcl::tda::test::run;
using pcl::tda::test::RunResult;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

namespace {

std::string
tool ()
{
  return std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_barcode";
}

std::string
temporaryPath (const std::string& name)
{
  return pcl::tda::test::temporaryPath ("barcode_tool", name);
}

/** Ripser's diagram of the points of \a cloud (as loaded by PCL, written with
 * enough digits to read back the same floats) up to \a radius. */
PersistenceDiagram
ripserDiagram (const Cloud& cloud, double radius)
{
  const std::string points = temporaryPath ("ripser_points.txt");
  const std::string output = temporaryPath ("ripser_output.txt");
  {
    std::ofstream out (points);
    char line[128];
    for (const auto& p : cloud) {
      std::snprintf (line, sizeof (line), "%.9g %.9g %.9g\n", p.x, p.y, p.z);
      out << line;
    }
  }
  std::ostringstream command;
  command.precision (17);
  command << RIPSER_EXECUTABLE << " --format point-cloud --dim 1 --threshold " << radius
          << " " << points << " > " << output;
  EXPECT_EQ (std::system (command.str().c_str()), 0) << command.str();
  return loadDiagram (output);
}

/** Runs the tool on \a pcd and returns its diagram. */
PersistenceDiagram
toolDiagram (const std::string& pcd, double radius, const std::string& extra = "")
{
  const std::string csv = temporaryPath ("diagram.csv");
  std::ostringstream command;
  command.precision (17);
  command << tool() << " " << pcd << " " << csv << " -radius " << radius << " "
          << extra;
  const RunResult result = run (command.str());
  EXPECT_EQ (result.exit_code, 0) << result.output;
  return loadDiagram (csv);
}

void
expectSameAsRipser (const std::string& pcd, double radius)
{
  if (std::string (RIPSER_EXECUTABLE).empty())
    GTEST_SKIP() << "skipped: ripser is not installed";
  Cloud cloud;
  ASSERT_EQ (pcl::io::loadPCDFile (pcd, cloud), 0);
  const DiagramComparison comparison =
      compareDiagrams (toolDiagram (pcd, radius), ripserDiagram (cloud, radius), 1e-5);
  EXPECT_TRUE (comparison.equal)
      << pcd << " radius " << radius << ": " << comparison.summary();
  EXPECT_GT (comparison.matched, cloud.size() / 2);
}

/** A random subsample of \a n points of a real scan, saved as a PCD file. */
std::string
subsample (const std::string& name, std::size_t n, unsigned int seed)
{
  Cloud cloud;
  EXPECT_EQ (pcl::io::loadPCDFile (test::dataFile (name), cloud), 0);
  std::mt19937 random (seed);
  std::shuffle (cloud.begin(), cloud.end(), random);
  cloud.resize (std::min (n, cloud.size()));
  cloud.width = cloud.size();
  cloud.height = 1;
  const std::string path = temporaryPath ("subsample_" + name);
  pcl::io::savePCDFileBinary (path, cloud);
  return path;
}

std::string
savedShape (const SyntheticShape& shape, const std::string& name)
{
  const std::string path = temporaryPath (name + ".pcd");
  pcl::io::savePCDFileBinary (path, *shape.cloud);
  return path;
}

std::array<std::size_t, 2>
essentialCounts (const PersistenceDiagram& diagram)
{
  std::array<std::size_t, 2> counts{0, 0};
  for (const auto& interval : diagram)
    if (interval.isEssential() && interval.dimension < 2)
      ++counts[interval.dimension];
  return counts;
}

} // namespace

TEST (BarcodeTool, SameDiagramAsRipserOnBunny)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  for (const double radius : {0.005, 0.01, 0.02})
    expectSameAsRipser (test::dataFile ("bunny.pcd"), radius);
}

TEST (BarcodeTool, SameDiagramAsRipserOnMilkSubsample)
{
  PCL_TDA_REQUIRE_DATA ("milk.pcd");
  expectSameAsRipser (subsample ("milk.pcd", 3000, 1), 0.006);
}

TEST (BarcodeTool, SameDiagramAsRipserOnRopsCloud)
{
  PCL_TDA_REQUIRE_DATA ("rops_cloud.pcd");
  expectSameAsRipser (test::dataFile ("rops_cloud.pcd"), 0.0045);
}

TEST (BarcodeTool, SameDiagramAsRipserOnGeneratedClouds)
{
  CircleParameters circle;
  circle.seed = 3;
  const SyntheticShape shape = generateCircle (circle);
  expectSameAsRipser (savedShape (shape, "circle"), shape.suggested_radius * 1.5);
  const TorusParameters torus;
  const SyntheticShape torus_shape = generateTorus (torus);
  expectSameAsRipser (savedShape (torus_shape, "torus"), torus_shape.suggested_radius);
}

TEST (BarcodeTool, KnownBettiNumbersOfGeneratedShapes)
{
  for (unsigned int seed = 1; seed <= 3; ++seed) {
    CircleParameters circle;
    circle.seed = seed;
    TorusParameters torus;
    torus.seed = seed;
    SphereParameters sphere;
    sphere.seed = seed;
    const std::pair<std::string, SyntheticShape> shapes[] = {
        {"circle", generateCircle (circle)},
        {"torus", generateTorus (torus)},
        {"sphere", generateSphere (sphere)}};
    for (const auto& [name, shape] : shapes) {
      const auto counts = essentialCounts (
          toolDiagram (savedShape (shape, name), shape.suggested_radius));
      EXPECT_EQ (counts[0], std::size_t (shape.beta0)) << name << " seed " << seed;
      EXPECT_EQ (counts[1], std::size_t (shape.beta1)) << name << " seed " << seed;
    }
  }
}

TEST (BarcodeTool, JsonLineAndPictures)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  const std::string csv = temporaryPath ("json.csv"), svg = temporaryPath ("json.svg");
  const RunResult result = run (tool() + " " + test::dataFile ("bunny.pcd") + " " +
                                csv + " -radius 0.01 -svg " + svg + " -json");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  std::string output = result.output;
  while (!output.empty() && output.back() == '\n')
    output.pop_back();
  const std::string last_line = output.substr (output.rfind ('\n') + 1);
  EXPECT_EQ (last_line.rfind ("{\"points\": 397, ", 0), 0u) << last_line;
  for (const char* key : {"\"edges\": ",
                          "\"triangles\": ",
                          "\"intervals\": {\"0\": 397, \"1\": ",
                          "\"load\": ",
                          "\"build\": ",
                          "\"h0\": ",
                          "\"h1\": ",
                          "\"write\": ",
                          "\"total\": "})
    EXPECT_NE (last_line.find (key), std::string::npos) << key;
  EXPECT_EQ (last_line.back(), '}');
  EXPECT_NE (result.output.find ("[done, "), std::string::npos);
  std::ostringstream picture;
  picture << std::ifstream (svg).rdbuf();
  EXPECT_NE (picture.str().find ("<svg"), std::string::npos);
  EXPECT_NE (picture.str().find ("</svg>"), std::string::npos);
}

TEST (BarcodeTool, EveryEngineWritesTheSameDiagram)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  const std::string bunny = test::dataFile ("bunny.pcd");
  std::string reference;
  for (const char* engine : {"cohomology", "fip", "incremental", "standard"}) {
    const std::string csv = temporaryPath (std::string (engine) + ".csv");
    const RunResult result =
        run (tool() + " " + bunny + " " + csv + " -radius 0.02 -engine " + engine);
    ASSERT_EQ (result.exit_code, 0) << result.output;
    EXPECT_NE (result.output.find (std::string ("H1 (") + engine + ")"),
               std::string::npos);
    std::ostringstream text;
    text << std::ifstream (csv).rdbuf();
    if (reference.empty())
      reference = text.str();
    EXPECT_EQ (text.str(), reference) << engine;
  }
  EXPECT_GT (std::count (reference.begin(), reference.end(), '\n'), 500);
}

// -gpu builds the complex with gpu::VietorisRipsBuilder: the same complex, hence the
// same diagram and PHAT matrix byte for byte; the JSON line names the builder, and a
// complex over the memory limit is refused as without -gpu.
TEST (BarcodeTool, GpuBuilderWritesTheSameOutputs)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  const std::string bunny = test::dataFile ("bunny.pcd");
  std::string outputs[2];
  for (const bool gpu : {false, true}) {
    const std::string name = gpu ? "gpu" : "cpu";
    const std::string csv = temporaryPath (name + ".csv");
    const std::string matrix = temporaryPath (name + ".bin");
    const RunResult result =
        run (tool() + " " + bunny + " " + csv + " -radius 0.02 -json -export-phat " +
             matrix + (gpu ? " -gpu" : ""));
    ASSERT_EQ (result.exit_code, 0) << result.output;
    EXPECT_NE (
        result.output.find (gpu ? "\"builder\": \"gpu " : "\"builder\": \"cpu\""),
        std::string::npos)
        << result.output;
    std::ostringstream text;
    text << std::ifstream (csv).rdbuf()
         << std::ifstream (matrix, std::ios::binary).rdbuf();
    outputs[gpu] = text.str();
  }
  EXPECT_GT (outputs[0].size(), 10000u);
  EXPECT_TRUE (outputs[0] == outputs[1]);

  const std::string refused = temporaryPath ("gpu_refused.csv");
  std::remove (refused.c_str());
  for (const bool gpu : {false, true}) {
    const RunResult result = run (tool() + " " + bunny + " " + refused +
                                  " -radius 0.05 -memory 0.01" + (gpu ? " -gpu" : ""));
    EXPECT_EQ (result.exit_code, 1) << result.output;
    EXPECT_NE (result.output.find ("over the memory limit of 10.2 KiB"),
               std::string::npos)
        << result.output;
    EXPECT_FALSE (exists (refused));
  }
}

// The default engine goes through the triangles without listing them: over -memory
// they are refused as the other engines' listed ones are (the complete graph of a
// 13.7k-point scan ran for hours), from the edges' count pass and a sample. The
// complete graph of the bunny: 78,606 edges (4.8 MiB), 10.4 million triangles.
TEST (BarcodeTool, DefaultEngineRefusesTrianglesOverTheLimit)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  const std::string bunny = test::dataFile ("bunny.pcd");
  const std::string csv = temporaryPath ("complete.csv");
  std::remove (csv.c_str());
  for (const char* options : {"", " -gpu", " -engine fip"}) {
    const RunResult result =
        run (tool() + " " + bunny + " " + csv + " -radius 1e30 -memory 20" + options);
    EXPECT_EQ (result.exit_code, 1) << result.output;
    EXPECT_NE (result.output.find (" triangles"), std::string::npos) << result.output;
    EXPECT_NE (result.output.find ("over the memory limit of 20.0 MiB"),
               std::string::npos)
        << result.output;
    EXPECT_FALSE (exists (csv));
  }
  // H0 needs the edges alone, which fit.
  const RunResult h0 =
      run (tool() + " " + bunny + " " + csv + " -radius 1e30 -memory 20 -dim 0");
  EXPECT_EQ (h0.exit_code, 0) << h0.output;
  EXPECT_TRUE (exists (csv));
}

TEST (BarcodeTool, ExportsTheComplexForPHAT)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  for (const char* name : {"complex.bin", "complex.txt"}) {
    const std::string matrix = temporaryPath (name);
    const RunResult result =
        run (tool() + " " + test::dataFile ("bunny.pcd") + " " +
             temporaryPath ("phat.csv") + " -radius 0.02 -json -export-phat " + matrix);
    ASSERT_EQ (result.exit_code, 0) << result.output;
    const bool binary = std::string (name).find (".bin") != std::string::npos;
    const FilteredComplex complex = loadPHATBoundaryMatrix (
        matrix, binary ? PHATFormat::BINARY : PHATFormat::ASCII);
    EXPECT_EQ (complex.numVertices(), 397u);
    EXPECT_NE (result.output.find ("\"edges\": " + std::to_string (complex.numEdges())),
               std::string::npos);
    EXPECT_NE (result.output.find ("\"triangles\": " +
                                   std::to_string (complex.numTriangles())),
               std::string::npos);
  }
}

TEST (BarcodeTool, DuplicatePointsAddOnlyZeroLengthBars)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  Cloud cloud;
  ASSERT_EQ (pcl::io::loadPCDFile (test::dataFile ("bunny.pcd"), cloud), 0);
  Cloud doubled = cloud;
  doubled += cloud;
  const std::string path = temporaryPath ("doubled.pcd");
  pcl::io::savePCDFileBinary (path, doubled);
  const auto comparison = compareDiagrams (
      toolDiagram (path, 0.01), toolDiagram (test::dataFile ("bunny.pcd"), 0.01));
  EXPECT_TRUE (comparison.equal) << comparison.summary();
}

TEST (BarcodeTool, VoxelGridReducesThePoints)
{
  PCL_TDA_REQUIRE_DATA ("milk.pcd");
  const RunResult result =
      run (tool() + " " + test::dataFile ("milk.pcd") + " " +
           temporaryPath ("leaf.csv") + " -radius 0.01 -dim 0 -leaf 0.005 -json");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  const auto points = result.output.find ("{\"points\": ");
  ASSERT_NE (points, std::string::npos);
  const int kept = std::stoi (result.output.substr (points + 11));
  EXPECT_GT (kept, 100);
  EXPECT_LT (kept, 13704);
  EXPECT_NE (result.output.find ("\"triangles\": 0,"), std::string::npos);

  // The same diagram, byte for byte, for shuffled copies of the scan (a cell's
  // centroid depended on the order of its points in the last bits).
  std::string diagrams[3];
  for (unsigned int seed = 0; seed < 3; ++seed) {
    const std::string csv = temporaryPath ("leaf_" + std::to_string (seed) + ".csv");
    const RunResult shuffled = run (tool() + " " + subsample ("milk.pcd", 13704, seed) +
                                    " " + csv + " -radius 0.02 -leaf 0.005");
    ASSERT_EQ (shuffled.exit_code, 0) << shuffled.output;
    std::ostringstream text;
    text << std::ifstream (csv).rdbuf();
    diagrams[seed] = text.str();
  }
  EXPECT_GT (diagrams[0].size(), 1000u);
  EXPECT_EQ (diagrams[0], diagrams[1]);
  EXPECT_EQ (diagrams[0], diagrams[2]);
}

TEST (BarcodeTool, RefusesBadInputWithoutWritingOutput)
{
  const std::string csv = temporaryPath ("refused.csv");
  std::remove (csv.c_str());

  const std::string pcd_header =
      "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
      "COUNT 1 1 1\nWIDTH %d\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 "
      "0\nPOINTS %d\nDATA %s\n";
  char header[256];
  const std::string empty_pcd = temporaryPath ("empty.pcd");
  std::snprintf (header, sizeof (header), pcd_header.c_str(), 0, 0, "ascii");
  std::ofstream (empty_pcd) << header;
  const std::string truncated_pcd = temporaryPath ("truncated.pcd");
  std::snprintf (header, sizeof (header), pcd_header.c_str(), 1000, 1000, "binary");
  std::ofstream (truncated_pcd) << header << "0123456789";
  Cloud nan_cloud;
  for (int i = 0; i < 5; ++i)
    nan_cloud.push_back ({NAN, NAN, NAN});
  const std::string nan_pcd = temporaryPath ("nan.pcd");
  pcl::io::savePCDFileBinary (nan_pcd, nan_cloud);
  const std::string garbage_pcd = temporaryPath ("garbage.pcd");
  std::ofstream (garbage_pcd) << "this is not a point cloud\n";
  pcl::PointCloud<pcl::Normal> normals;
  normals.push_back (pcl::Normal (0, 0, 1));
  const std::string normals_pcd = temporaryPath ("normals.pcd");
  pcl::io::savePCDFileASCII (normals_pcd, normals);

  const std::string bunny = test::dataFile ("bunny.pcd");
  // The input, reached through a link with another name.
  const std::string bunny_copy = temporaryPath ("bunny.pcd");
  const std::string link_to_copy = temporaryPath ("link.svg");
  std::remove (link_to_copy.c_str());
  if (test::haveDataFile ("bunny.pcd")) {
    std::ofstream (bunny_copy) << std::ifstream (bunny).rdbuf();
    EXPECT_EQ (::symlink (bunny_copy.c_str(), link_to_copy.c_str()), 0);
  }
  struct Case {
    std::string arguments, expected_message;
  };
  std::vector<Case> cases{
      {empty_pcd + " " + csv + " -radius 0.1", "no finite point"},
      {nan_pcd + " " + csv + " -radius 0.1", "no finite point"},
      {garbage_pcd + " " + csv + " -radius 0.1", "is not a PCD header line"},
      {truncated_pcd + " " + csv + " -radius 0.1", "Cannot read"},
      {normals_pcd + " " + csv + " -radius 0.1", "no 'x' field"},
      {temporaryPath ("missing.pcd") + " " + csv + " -radius 0.1", "cannot open"},
      {bunny + " " + csv, "Option -radius is required"},
      {bunny + " " + csv + " -radius 0", "needs a number > 0"},
      {bunny + " " + csv + " -radius -0.5", "needs a number > 0"},
      {bunny + " " + csv + " -radius 0.01 -dim 2",
       "Option -dim needs an integer from 0 to 1"},
      {bunny + " " + csv + " -radius 0.01 -leaf -1",
       "Option -leaf needs a number >= 0"},
      {bunny + " " + csv + " -radius 0.01 -engine ripser", "Unknown engine ripser"},
      {bunny + " " + csv + " -radius 0.05 -memory 1", "memory limit"},
      {bunny + " /nonexistent_dir/out.csv -radius 0.01", "cannot write"},
      {bunny_copy + " " + csv + " -radius 0.01 -svg " + link_to_copy,
       "refusing to overwrite"},
      {bunny, "Syntax is"},
  };
  if (!test::haveDataFile ("bunny.pcd"))
    cases.resize (6);
  for (const Case& c : cases) {
    const RunResult result = run (tool() + " " + c.arguments);
    EXPECT_NE (result.exit_code, 0) << c.arguments << "\n" << result.output;
    EXPECT_NE (result.output.find (c.expected_message), std::string::npos)
        << c.arguments << "\n"
        << result.output;
    EXPECT_FALSE (exists (csv)) << c.arguments;
  }
  if (test::haveDataFile ("bunny.pcd")) {
    Cloud still_bunny;
    EXPECT_EQ (pcl::io::loadPCDFile (bunny_copy, still_bunny), 0);
    EXPECT_EQ (still_bunny.size(), 397u);
  }
}
