// End-to-end tests of pcl_tda_viewer on a virtual X display (Xvfb): the
// screenshots of every mode on generated scenes, of the size asked for, not blank,
// holding the colours of the labels the tools wrote (and the barcode's bars), the
// Betti numbers of the -barcode overlay; and bad input refused with a message, a
// non-zero exit and no picture written.

#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/apps/barcode_overlay.h>
#include <pcl/tda/apps/cloud_picture.h>
#include <pcl/tda/generators/shapes.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "png_picture.h"
#include "tool_runner.h"
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

using pcl::tda::test::Color;
using pcl::tda::test::exists;
using pcl::tda::test::Picture;
using pcl::tda::test::readPNG;
using pcl::tda::test::run;
using pcl::tda::test::RunResult;

namespace {

/** An Xvfb server of its own for the running test process, on a display number it
 * chose itself (-displayfd), so that tests running in parallel do not collide; the
 * display number is written once it accepts clients. */
class VirtualDisplay {
public:
  VirtualDisplay()
  {
    int pipe_ends[2];
    if (::pipe (pipe_ends) != 0)
      return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::close (pipe_ends[0]);
      const std::string fd = std::to_string (pipe_ends[1]);
      ::execlp ("Xvfb",
                "Xvfb",
                "-displayfd",
                fd.c_str(),
                "-screen",
                "0",
                "1280x1024x24",
                "-nolisten",
                "tcp",
                "-noreset", // for the next viewer, when the last one has gone
                static_cast<char*> (nullptr));
      ::_exit (127);
    }
    ::close (pipe_ends[1]);
    // The number and a newline, not necessarily in one write: Xvfb stops when it
    // cannot write the rest.
    std::string number;
    char c;
    while (::read (pipe_ends[0], &c, 1) == 1 && c != '\n')
      number += c;
    ::close (pipe_ends[0]);
    if (!number.empty())
      display_ = ":" + number;
  }

  ~VirtualDisplay()
  {
    if (pid_ > 0) {
      ::kill (pid_, SIGTERM);
      ::waitpid (pid_, nullptr, 0);
    }
  }

  /** ":N", or "" when Xvfb could not be started. */
  const std::string&
  name () const
  {
    return display_;
  }

private:
  pid_t pid_ = -1;
  std::string display_;
};

class ViewerTool : public testing::Test {
protected:
  static void
  SetUpTestSuite ()
  {
    display_ = new VirtualDisplay;
  }

  static void
  TearDownTestSuite ()
  {
    delete display_;
    display_ = nullptr;
  }

  void
  SetUp () override
  {
    ASSERT_FALSE (display_->name().empty())
        << "Cannot start Xvfb (scripts/install_deps.sh installs it: package xvfb)";
  }

  static std::string
  path (const std::string& name)
  {
    return pcl::tda::test::temporaryPath ("viewer_tool", name);
  }

  static std::string
  bin (const std::string& tool)
  {
    return std::string (PCL_TDA_BIN_DIR) + "/" + tool + " ";
  }

  /** Runs the viewer on the virtual display. Mesa and VTK leave memory allocated at
   * exit, which a sanitizer build would report as leaks of the viewer's. */
  static RunResult
  viewer (const std::string& arguments)
  {
    return run ("DISPLAY=" + display_->name() +
                " ASAN_OPTIONS=${ASAN_OPTIONS:-}:detect_leaks=0 " +
                bin ("pcl_tda_viewer") + arguments);
  }

  /** Runs the tool \a tool and fails the test when it fails. */
  static void
  tool (const std::string& tool, const std::string& arguments)
  {
    const RunResult result = run (bin (tool) + arguments);
    ASSERT_EQ (result.exit_code, 0) << tool << " " << arguments << "\n"
                                    << result.output;
  }

  /** The points per label of a labelled cloud. */
  static std::map<std::uint32_t, std::size_t>
  labelSizes (const std::string& file)
  {
    pcl::PointCloud<pcl::PointXYZL> cloud;
    EXPECT_EQ (pcl::io::loadPCDFile (file, cloud), 0) << file;
    std::map<std::uint32_t, std::size_t> sizes;
    for (const auto& point : cloud)
      ++sizes[point.label];
    return sizes;
  }

  static VirtualDisplay* display_;
};

VirtualDisplay* ViewerTool::display_ = nullptr;

Color
labelColor (std::size_t label)
{
  return pcl::tda::labelColor (label);
}

TEST_F (ViewerTool, BarcodeOfACircleAtTwoRadii)
{
  pcl::tda::CircleParameters parameters;
  parameters.num_points = 400;
  parameters.seed = 3;
  const pcl::tda::SyntheticShape circle = pcl::tda::generateCircle (parameters);
  pcl::PointCloud<pcl::PointXYZ> points;
  pcl::copyPointCloud (*circle.cloud, points);
  const std::string in = path ("circle.pcd"), png = path ("circle.png");
  pcl::io::savePCDFileBinary (in, points);
  const std::string radius = std::to_string (circle.suggested_radius);

  // At the suggested radius: one component (label 1's colour), one 1-cycle.
  RunResult result = viewer (in + " -barcode -radius " + radius + " -screenshot " +
                             png + " -size 640x480");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("beta_0 1, beta_1 1\n400 points"), std::string::npos)
      << result.output;
  Picture picture = readPNG (png);
  ASSERT_EQ (picture.width, 640u);
  ASSERT_EQ (picture.height, 480u);
  EXPECT_GT (picture.count (labelColor (1)), 500u);
  EXPECT_EQ (picture.count (labelColor (2)), 0u);
  EXPECT_GT (picture.count (pcl::tda::BarcodeOverlay::H0_COLOR), 300u);
  EXPECT_GT (picture.count (pcl::tda::BarcodeOverlay::H1_COLOR), 30u);

  // Far below it: many components and points alone (grey); no 1-cycle yet.
  result =
      viewer (in + " -barcode -radius " + radius + " -at " +
              std::to_string (circle.suggested_radius / 8) + " -screenshot " + png);
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_EQ (result.output.find ("beta_0 1,"), std::string::npos) << result.output;
  EXPECT_NE (result.output.find (", beta_1 0\n"), std::string::npos) << result.output;
  picture = readPNG (png);
  ASSERT_EQ (picture.width, 800u); // the default size of a screenshot
  ASSERT_EQ (picture.height, 600u);
  EXPECT_GT (picture.count (labelColor (0)), 50u);
  for (std::size_t label = 1; label <= 4; ++label)
    EXPECT_GT (picture.count (labelColor (label)), 20u) << label;
}

TEST_F (ViewerTool, ClustersOfASegmentedScene)
{
  const std::string scene = path ("scene.pcd"), labels = path ("labels.pcd"),
                    png = path ("clusters.png");
  tool ("pcl_tda_generate", "tabletop " + scene + " -objects 3 -seed 5");
  tool ("pcl_tda_segment", scene + " " + labels + " -radius 0.05 -leaf 0.01 -min 32");
  const auto sizes = labelSizes (labels);
  ASSERT_EQ (sizes.size(), 3u); // three objects, every point in one
  // Non-finite points with a label of their own are in no cluster shown (they were
  // counted as a fourth).
  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ (pcl::io::loadPCDFile (labels, labelled), 0);
  const std::size_t num_points = labelled.size();
  for (int i = 0; i < 5; ++i)
    labelled.push_back (
        pcl::PointXYZL (std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f, 4));
  pcl::io::savePCDFileBinary (labels, labelled);
  const RunResult result = viewer (labels + " -clusters -screenshot " + png);
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find (std::to_string (num_points + 5) +
                                 " points, 3 clusters (" + std::to_string (num_points) +
                                 " points in them"),
             std::string::npos)
      << result.output;
  const Picture picture = readPNG (png);
  ASSERT_EQ (picture.width, 800u);
  ASSERT_EQ (picture.height, 600u);
  EXPECT_GT (picture.numColors(), 4u);
  for (const auto& [label, size] : sizes)
    EXPECT_GT (picture.count (labelColor (label)), size / 4) << label;
  EXPECT_EQ (picture.count (labelColor (4)), 0u);
}

TEST_F (ViewerTool, DrawsTinyCloudsScaledUp)
{
  // The same labelled circle in metres and times 2^-83 (about 1e-25, where VTK's
  // camera drew nothing): the same picture, and a note that it is drawn scaled.
  pcl::tda::CircleParameters parameters;
  parameters.num_points = 400;
  parameters.seed = 4;
  pcl::PointCloud<pcl::PointXYZL> labelled;
  pcl::copyPointCloud (*pcl::tda::generateCircle (parameters).cloud, labelled);
  for (std::size_t i = 0; i < labelled.size(); ++i)
    labelled[i].label = 1 + i % 2;
  const std::string in = path ("circle.pcd"), png = path ("circle.png");
  pcl::io::savePCDFileBinary (in, labelled);
  RunResult result = viewer (in + " -clusters -screenshot " + png);
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_EQ (result.output.find ("drawn multiplied"), std::string::npos)
      << result.output;
  const Picture metres = readPNG (png);
  for (auto& point : labelled)
    point.getVector3fMap() *= std::ldexp (1.0f, -83);
  pcl::io::savePCDFileBinary (in, labelled);
  result = viewer (in + " -clusters -screenshot " + png);
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("drawn multiplied by 2^"), std::string::npos)
      << result.output;
  const Picture tiny = readPNG (png);
  for (std::uint32_t label : {1u, 2u}) {
    const auto drawn = metres.count (labelColor (label));
    EXPECT_GT (drawn, 200u) << label;
    EXPECT_NEAR (static_cast<double> (tiny.count (labelColor (label))),
                 static_cast<double> (drawn),
                 0.02 * static_cast<double> (drawn))
        << label;
  }
}

TEST_F (ViewerTool, RegionsAndTheirOwnColours)
{
  const std::string scene = path ("painted.pcd"), labels = path ("regions.pcd"),
                    png = path ("regions.png");
  tool ("pcl_tda_generate", "regions " + scene + " -objects 2 -seed 4");
  tool ("pcl_tda_regions", scene + " " + labels);
  const auto sizes = labelSizes (labels);
  ASSERT_GE (sizes.size(), 3u);
  const RunResult result =
      viewer (labels + " -regions -screenshot " + png + " -size 500x400");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  const Picture picture = readPNG (png);
  ASSERT_EQ (picture.width, 500u);
  ASSERT_EQ (picture.height, 400u);
  // The table, the largest region, and every region of 100 points or more.
  EXPECT_GT (picture.count (labelColor (1)), 10000u);
  for (const auto& [label, size] : sizes) {
    if (label != 0 && size >= 100) {
      EXPECT_GT (picture.count (labelColor (label)), 10u) << label;
    }
  }
}

TEST_F (ViewerTool, HoleRimsAndNewPoints)
{
  const std::string surface = path ("surface.pcd"), labels = path ("holes.pcd"),
                    filled = path ("filled.pcd"), png = path ("holes.png");
  tool ("pcl_tda_generate", "holes " + surface + " -seed 1 -n 8000");
  tool ("pcl_tda_holes", surface + " " + labels + " -fill " + filled);
  const auto sizes = labelSizes (labels);
  ASSERT_EQ (sizes.size(), 4u); // the surface and three holes
  const RunResult result =
      viewer (labels + " -holes -fill " + filled + " -screenshot " + png);
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("3 holes"), std::string::npos) << result.output;
  const Picture picture = readPNG (png);
  EXPECT_GT (picture.count (labelColor (0)), 20000u); // the surface, grey
  for (std::uint32_t hole = 1; hole <= 3; ++hole)
    EXPECT_GT (picture.count (labelColor (hole)), 20u) << hole;
  EXPECT_GT (picture.count ({255, 255, 255}), 100u); // the new points
}

TEST_F (ViewerTool, CameraAndSize)
{
  pcl::tda::CircleParameters parameters;
  parameters.num_points = 200;
  const pcl::tda::SyntheticShape circle = pcl::tda::generateCircle (parameters);
  const std::string in = path ("circle.pcd"), png = path ("camera.png");
  pcl::io::savePCDFileBinary (in, *circle.cloud);
  // The circle in z = 0 seen from its side: a line across the picture, few pixels.
  RunResult result =
      viewer (in + " -clusters -screenshot " + png +
              " -size 320x240 -camera 0.1,100/0,0,0/0,-5,0/0,0,1/0.8575/640,480/0,0");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  const Picture side = readPNG (png);
  ASSERT_EQ (side.width, 320u);
  ASSERT_EQ (side.height, 240u);
  result = viewer (in + " -clusters -screenshot " + png + " -size 320x240");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  const Picture above = readPNG (png);
  const Color shape = labelColor (circle.cloud->front().label);
  EXPECT_GT (above.count (shape), 2 * side.count (shape));
  EXPECT_GT (side.count (shape), 0u);

  result = viewer (in + " -clusters -screenshot " + png + " -camera 1/2/3");
  EXPECT_EQ (result.exit_code, 1) << result.output;
  EXPECT_NE (result.output.find ("-camera"), std::string::npos) << result.output;
}

/** A command the viewer must refuse, and what its message says. */
struct BadCase {
  std::string arguments, message;
};

/** Bad input: the input files of the cases below, a picture that must stay as it
 * is, and the cases' check. */
class ViewerBadInput : public ViewerTool {
protected:
  void
  SetUp () override
  {
    for (int i = 0; i < 50; ++i)
      points_.push_back (pcl::PointXYZ (0.01f * i, 0.0f, 0.0f));
    pcl::io::savePCDFileBinary (plain_, points_);
    pcl::PointCloud<pcl::PointXYZL> with_labels;
    pcl::copyPointCloud (points_, with_labels);
    pcl::io::savePCDFileBinary (labelled_, with_labels);
  }

  /** Runs each case (\a environment before the viewer), with a picture "old" at
   * png_: exit code 1, the message, the picture unchanged. */
  void
  expectRefused (const std::vector<BadCase>& cases,
                 const std::string& environment = "") const
  {
    for (const BadCase& c : cases) {
      {
        std::ofstream (png_) << "old";
      }
      const std::string command = environment + bin ("pcl_tda_viewer") + c.arguments;
      const RunResult result = run (command);
      EXPECT_EQ (result.exit_code, 1) << command << "\n" << result.output;
      EXPECT_NE (result.output.find (c.message), std::string::npos) << command << "\n"
                                                                    << result.output;
      std::ifstream kept (png_);
      std::string content;
      kept >> content;
      EXPECT_EQ (content, "old") << command;
    }
  }

  pcl::PointCloud<pcl::PointXYZ> points_;
  const std::string plain_ = path ("plain.pcd"), labelled_ = path ("labelled.pcd"),
                    png_ = path ("out.png");
};

TEST_F (ViewerBadInput, FilesWithoutLabelsMissingFilesAndNoDisplay)
{
  // A -fill cloud with fewer points than the labelled one, and one of another input
  // (the points moved, more of them): it was shown with the other's new points.
  const std::string few = path ("few.pcd"), other = path ("other.pcd");
  pcl::PointCloud<pcl::PointXYZ> fewer, moved = points_;
  fewer.insert (fewer.end(), points_.begin(), points_.begin() + 10);
  pcl::io::savePCDFileBinary (few, fewer);
  for (auto& point : moved)
    point.x += 0.01f;
  moved.insert (moved.end(), points_.begin(), points_.begin() + 10);
  pcl::io::savePCDFileBinary (other, moved);
  const std::string missing = path ("missing.pcd"), screenshot = " -screenshot " + png_;
  expectRefused ({
      {missing + " -clusters" + screenshot, "Cannot read the PCD file"},
      {plain_ + " -clusters" + screenshot, "has no label field"},
      {plain_ + " -holes" + screenshot, "has no label field"},
      {labelled_ + " -holes -fill " + missing + screenshot, "Cannot read the PCD file"},
      {labelled_ + " -holes -fill " + few + screenshot, "does not start with the"},
      {labelled_ + " -holes -fill " + other + screenshot, "does not start with the"},
  });
  expectRefused ({{plain_ + " -barcode -radius 0.02" + screenshot, "No X display"},
                  {labelled_ + " -clusters", "No X display"}},
                 "env -u DISPLAY ASAN_OPTIONS=${ASAN_OPTIONS:-}:detect_leaks=0 ");
}

TEST_F (ViewerBadInput, Options)
{
  const std::string screenshot = " -screenshot " + png_;
  expectRefused ({
      {plain_ + screenshot, "Give one mode"},
      {plain_ + " -barcode -clusters", "Give one mode"},
      {plain_ + " -barcode" + screenshot, "-barcode needs -radius"},
      {plain_ + " -barcode -radius 0.1 -at 0.2", "beyond"},
      {labelled_ + " -clusters -radius 0.1", "-radius has no use"},
      {labelled_ + " -clusters -fill " + plain_, "-fill has no use"},
      {labelled_ + " -clusters" + screenshot + " -size 640", "-size must be WxH"},
      {labelled_ + " -clusters -screenshot " + path ("out.jpg"), "must be a .png file"},
  });
  EXPECT_FALSE (exists (path ("out.jpg")));
}

} // namespace
