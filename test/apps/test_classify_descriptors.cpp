// Tests of the descriptors of pcl_tda_classify: PCL's ESF made deterministic, the
// descriptors of a view and their failures, the list of descriptors and their
// combinations, the CSV fields, and the confusion matrix pictures.

#include <pcl/common/io.h>
#include <pcl/tda/apps/confusion_matrix_plot.h>
#include <pcl/tda/apps/csv_fields.h>
#include <pcl/tda/apps/descriptor_list.h>
#include <pcl/tda/apps/sanitizer_options.h> // this program runs PCL's GRSD and CVFH
#include <pcl/tda/apps/seeded_esf.h>
#include <pcl/tda/apps/view_descriptors.h>
#include <pcl/tda/generators/random_sampling.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include "tool_runner.h"
#include <omp.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace pcl::tda;

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/** \a count points on a half sphere of radius 0.1 m, 0.5 m in front of the sensor
 * at the origin: a view of a ball. */
Cloud::Ptr
ballView (std::size_t count, std::uint64_t seed)
{
  PortableRandom random (seed);
  Cloud::Ptr cloud (new Cloud);
  while (cloud->size() < count) {
    Eigen::Vector3d direction (random.normal(), random.normal(), random.normal());
    direction.normalize();
    if (direction.z() > 0.0)
      direction.z() = -direction.z(); // the side that faces the sensor
    const Eigen::Vector3d point = Eigen::Vector3d (0, 0, 0.5) + 0.1 * direction;
    cloud->push_back (pcl::PointXYZ (static_cast<float> (point.x()),
                                     static_cast<float> (point.y()),
                                     static_cast<float> (point.z())));
  }
  return cloud;
}

/** \a cloud with every point of colour (r, g, b), or with \a striped every other
 * point of the complementary colour. */
pcl::PointCloud<pcl::PointXYZRGB>
painted (const Cloud& cloud,
         std::uint8_t r,
         std::uint8_t g,
         std::uint8_t b,
         bool striped = false)
{
  pcl::PointCloud<pcl::PointXYZRGB> colored;
  pcl::copyPointCloud (cloud, colored);
  for (std::size_t i = 0; i < colored.size(); ++i) {
    const bool other = striped && i % 2 == 1;
    colored[i].r = other ? 255 - r : r;
    colored[i].g = other ? 255 - g : g;
    colored[i].b = other ? 255 - b : b;
  }
  return colored;
}

std::string
testPath (const std::string& name)
{
  return pcl::tda::test::temporaryPath ("classify_descriptors", name);
}

std::string
contentOf (const std::string& path)
{
  std::ostringstream text;
  text << std::ifstream (path, std::ios::binary).rdbuf();
  return text.str();
}

} // namespace

TEST (SeededESF, GivesTheSameHistogramForTheSameSeedOnAnyThread)
{
  const Cloud::Ptr cloud = ballView (500, 1);
  const std::vector<float> first = computeSeededESF (cloud, 17);
  ASSERT_EQ (first.size(), 640u);
  EXPECT_EQ (computeSeededESF (cloud, 17), first);
  EXPECT_NE (computeSeededESF (cloud, 18), first);
  // Two threads at once, each with its own seed, as the tool computes views.
  std::vector<std::vector<float>> parallel (4);
#pragma omp parallel for num_threads(2)
  for (int k = 0; k < 4; ++k)
    parallel[k] = computeSeededESF (cloud, k % 2 == 0 ? 17 : 18);
  EXPECT_EQ (parallel[0], first);
  EXPECT_EQ (parallel[2], first);
  EXPECT_EQ (parallel[1], computeSeededESF (cloud, 18));
}

TEST (SeededESF, RefusesCloudsOnWhichPCLWouldLoopForEver)
{
  Cloud::Ptr line (new Cloud);
  for (int i = 0; i < 100; ++i)
    line->push_back (pcl::PointXYZ (0.01f * i, 0.02f * i, 0.5f));
  EXPECT_THROW (computeSeededESF (line, 1), pcl::BadArgumentException);
  Cloud::Ptr two (new Cloud);
  two->push_back (pcl::PointXYZ (0, 0, 1));
  two->push_back (pcl::PointXYZ (1, 0, 1));
  EXPECT_THROW (computeSeededESF (two, 1), pcl::BadArgumentException);
}

TEST (ViewDescriptors, ComputesEveryDescriptorOfAView)
{
  const Cloud::Ptr cloud = ballView (800, 2);
  cloud->push_back (pcl::PointXYZ (std::numeric_limits<float>::quiet_NaN(), 0, 0));
  const auto view = painted (*cloud, 200, 40, 40);
  const std::vector<std::string>& names = viewDescriptorNames();
  const std::vector<ViewDescriptor> computed = computeViewDescriptors (view, names, 3);
  ASSERT_EQ (computed.size(), names.size());
  const std::vector<std::pair<std::string, std::size_t>> sizes{{"vfh", 308},
                                                               {"esf", 640},
                                                               {"grsd", 21},
                                                               {"cvfh", 308},
                                                               {"ourcvfh", 308},
                                                               {"covariance", 78}};
  for (std::size_t k = 0; k < names.size(); ++k) {
    EXPECT_EQ (computed[k].failure, "") << names[k];
    EXPECT_FALSE (computed[k].values.empty()) << names[k];
    EXPECT_GE (computed[k].milliseconds, 0.0);
    for (const auto& [name, size] : sizes) {
      if (name == names[k]) {
        EXPECT_EQ (computed[k].values.size(), size) << name;
      }
    }
  }
  // Equal inputs, equal descriptors; other colours change the covariance only.
  const auto again = computeViewDescriptors (view, names, 3);
  const auto recolored =
      computeViewDescriptors (painted (*cloud, 200, 40, 40, true), names, 3);
  for (std::size_t k = 0; k < names.size(); ++k) {
    EXPECT_EQ (again[k].values, computed[k].values) << names[k];
    if (names[k] == "covariance") {
      EXPECT_NE (recolored[k].values, computed[k].values);
    }
    else {
      EXPECT_EQ (recolored[k].values, computed[k].values) << names[k];
    }
  }
  EXPECT_THROW (computeViewDescriptors (view, {"fpfh"}, 3), pcl::BadArgumentException);
}

TEST (ViewDescriptors, SaysWhyADescriptorFails)
{
  const std::vector<std::string> names{"vfh", "esf", "stpp", "covariance"};
  const auto empty =
      computeViewDescriptors (pcl::PointCloud<pcl::PointXYZRGB>(), names, 1);
  for (const ViewDescriptor& descriptor : empty) {
    EXPECT_TRUE (descriptor.values.empty());
    EXPECT_FALSE (descriptor.failure.empty());
  }
  Cloud two;
  two.push_back (pcl::PointXYZ (0, 0, 1));
  two.push_back (pcl::PointXYZ (0.01f, 0, 1));
  const auto tiny = computeViewDescriptors (painted (two, 1, 2, 3), names, 1);
  EXPECT_NE (tiny[0].failure.find ("have a normal"), std::string::npos)
      << tiny[0].failure;
  EXPECT_NE (tiny[1].failure.find ("at least 3 points"), std::string::npos)
      << tiny[1].failure;
  EXPECT_NE (tiny[3].failure.find ("have a normal"), std::string::npos)
      << tiny[3].failure;
}

TEST (DescriptorList, ParsesNamesAndCombinations)
{
  const auto defaults = parseDescriptorList (DEFAULT_DESCRIPTORS);
  EXPECT_GE (defaults.size(), 10u);
  const auto specs = parseDescriptorList ("esf,stpp+vfh,vfh");
  ASSERT_EQ (specs.size(), 3u);
  EXPECT_EQ (specs[1].name, "stpp+vfh");
  EXPECT_EQ (specs[1].parts, (std::vector<std::string>{"stpp", "vfh"}));
  EXPECT_EQ (neededViewDescriptors (specs),
             (std::vector<std::string>{"esf", "stpp", "vfh"}));
  for (const char* bad : {"", "esf,", "fpfh", "esf+fpfh", "esf,esf", "esf+esf", "+esf"})
    EXPECT_THROW (parseDescriptorList (bad), pcl::BadArgumentException) << bad;
}

TEST (DescriptorList, ConcatenatesTheParts)
{
  const std::vector<std::string> names{"vfh", "esf"};
  std::vector<std::vector<ViewDescriptor>> computed (3,
                                                     std::vector<ViewDescriptor> (2));
  for (std::size_t i = 0; i < 3; ++i) {
    computed[i][0] = {{1.0f, 2.0f}, "", 1.0, 5.0};
    computed[i][1] = {{3.0f, 4.0f, 5.0f}, "", 2.0, 0.0};
  }
  computed[2][1] = {{}, "too few points", 2.0, 0.0};
  const DescriptorTable table =
      assembleDescriptor ({"esf+vfh", {"esf", "vfh"}}, names, computed);
  EXPECT_EQ (table.dimension, 5u);
  EXPECT_EQ (table.parts, (std::vector<std::size_t>{3, 2}));
  EXPECT_EQ (table.rows[0], (std::vector<float>{3, 4, 5, 1, 2}));
  EXPECT_TRUE (table.rows[2].empty());
  EXPECT_EQ (table.failures[2], "esf: too few points");
  // Each part's time, and the normals once.
  EXPECT_DOUBLE_EQ (table.milliseconds[0], 1.0 + 2.0 + 5.0);
  computed[1][0].values = {1.0f};
  EXPECT_THROW (assembleDescriptor ({"vfh", {"vfh"}}, names, computed),
                pcl::BadArgumentException);
}

TEST (CSVFields, SplitsAndQuotes)
{
  EXPECT_EQ (splitCSVLine ("a,b,,c\r"), (std::vector<std::string>{"a", "b", "", "c"}));
  EXPECT_EQ (splitCSVLine ("\"x,y\",\"say \"\"hi\"\"\""),
             (std::vector<std::string>{"x,y", "say \"hi\""}));
  for (const std::string text : {"plain", "with,comma", "with \"quote\"", ""})
    EXPECT_EQ (splitCSVLine (csvField (text) + ",z"),
               (std::vector<std::string>{text, "z"}));
  EXPECT_THROW (splitCSVLine ("\"open"), pcl::BadArgumentException);
  EXPECT_THROW (splitCSVLine ("\"a\"b"), pcl::BadArgumentException);
}

TEST (ConfusionMatrixPlot, DrawsSharesAndNames)
{
  ConfusionPlot plot;
  plot.title = "esf <test>";
  plot.categories = {"ball", "box & crate"};
  plot.counts = {{9, 1, 0}, {0, 8, 2}};
  std::ostringstream svg;
  writeConfusionMatrixSVG (svg, plot);
  const std::string text = svg.str();
  for (const char* expected : {"esf &lt;test&gt;",
                               "ball (10)",
                               "box &amp; crate (10)",
                               ">0.90<",
                               ">0.10<",
                               ">0.80<",
                               ">0.20<",
                               "(failed)",
                               "true category",
                               "predicted category"})
    EXPECT_NE (text.find (expected), std::string::npos) << expected;
  // No failures, no column for them.
  plot.counts = {{9, 1, 0}, {0, 10, 0}};
  std::ostringstream clean;
  writeConfusionMatrixSVG (clean, plot);
  EXPECT_EQ (clean.str().find ("(failed)"), std::string::npos);

  const std::string png = testPath ("matrix.png");
  saveConfusionMatrixPNG (png, plot);
  EXPECT_EQ (contentOf (png).substr (1, 3), "PNG");
  plot.counts = {{1}};
  EXPECT_THROW (saveConfusionMatrixSVG (testPath ("bad.svg"), plot),
                pcl::BadArgumentException);
  EXPECT_FALSE (std::filesystem::exists (testPath ("bad.svg")));
}
