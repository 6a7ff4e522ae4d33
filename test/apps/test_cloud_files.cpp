// Tests of the tools' input layer: loadPointCloudFile() reads float, double and
// integer coordinates alike, keeps organized layouts and other fields, and refuses
// malformed files with a message before PCL's reader allocates.

#include <pcl/io/pcd_io.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/pcd_file_check.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "apps/pcd_test_files.h"
#include "test_data.h"
#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

using namespace pcl::tda;
using pcl::tda::test::pcdHeader;
using pcl::tda::test::writeFile;

namespace {

std::string
temporaryPath (const std::string& name)
{
  return testing::TempDir() + "cloud_files_" +
         testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + name;
}

/** The message of loadPointCloudFile()'s refusal of \a path, "" when it loads. */
std::string
refusal (const std::string& path)
{
  pcl::PCLPointCloud2 cloud;
  try {
    loadPointCloudFile (path, cloud);
  }
  catch (const pcl::IOException& error) {
    return errorMessage (error);
  }
  return "";
}

/** Points on a small grid with integer coordinates, so that every type holds them. */
std::vector<std::array<int, 3>>
integerPoints ()
{
  std::vector<std::array<int, 3>> points;
  for (int i = 0; i < 60; ++i)
    points.push_back ({i % 7, (i * 3) % 11, i / 7});
  return points;
}

/** The points of integerPoints() in binary, x as an X, y as a Y, z as a Z. */
template <typename X, typename Y, typename Z>
std::string
packedPoints ()
{
  std::string data;
  for (const auto& point : integerPoints()) {
    const X x = static_cast<X> (point[0]);
    const Y y = static_cast<Y> (point[1]);
    const Z z = static_cast<Z> (point[2]);
    data.append (reinterpret_cast<const char*> (&x), sizeof (x));
    data.append (reinterpret_cast<const char*> (&y), sizeof (y));
    data.append (reinterpret_cast<const char*> (&z), sizeof (z));
  }
  return data;
}

void
expectIntegerPoints (const pcl::PointCloud<pcl::PointXYZ>& cloud)
{
  const auto points = integerPoints();
  ASSERT_EQ (cloud.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ (cloud[i].x, points[i][0]) << i;
    EXPECT_EQ (cloud[i].y, points[i][1]) << i;
    EXPECT_EQ (cloud[i].z, points[i][2]) << i;
  }
}

} // namespace

TEST (CloudFiles, ReadsDoubleAndIntegerCoordinates)
{
  const std::size_t n = integerPoints().size();
  const std::vector<std::pair<std::string, std::string>> files{
      {pcdHeader ("x y z", "4 4 4", "F F F", n, "binary"),
       packedPoints<float, float, float>()},
      {pcdHeader ("x y z", "8 8 8", "F F F", n, "binary"),
       packedPoints<double, double, double>()},
      {pcdHeader ("x y z", "4 2 1", "I U I", n, "binary"),
       packedPoints<std::int32_t, std::uint16_t, std::int8_t>()},
      {pcdHeader ("x y z", "8 4 8", "I U F", n, "binary"),
       packedPoints<std::int64_t, std::uint32_t, double>()},
  };
  for (const auto& [header, data] : files) {
    SCOPED_TRACE (header);
    const std::string path = temporaryPath ("points.pcd");
    writeFile (path, header + data);
    pcl::PointCloud<pcl::PointXYZ> cloud;
    loadPointCloudFile (path, cloud);
    expectIntegerPoints (cloud);
  }
  // ASCII integers, and doubles in binary_compressed as PCL writes them.
  std::ostringstream ascii;
  for (const auto& point : integerPoints())
    ascii << point[0] << " " << point[1] << " " << point[2] << "\n";
  const std::string ascii_path = temporaryPath ("ascii.pcd");
  writeFile (ascii_path,
             pcdHeader ("x y z", "2 2 2", "I I I", n, "ascii") + ascii.str());
  pcl::PointCloud<pcl::PointXYZ> cloud;
  loadPointCloudFile (ascii_path, cloud);
  expectIntegerPoints (cloud);

  pcl::PCLPointCloud2 doubles;
  pcl::PCDReader().read (temporaryPath ("points.pcd"), doubles); // the last: F8
  const std::string compressed = temporaryPath ("compressed.pcd");
  ASSERT_EQ (pcl::PCDWriter().writeBinaryCompressed (compressed, doubles), 0);
  loadPointCloudFile (compressed, cloud);
  expectIntegerPoints (cloud);
}

TEST (CloudFiles, KeepsOtherFieldsAndOrganizedLayouts)
{
  // Double coordinates with a colour after them, 6 x 10 organized.
  std::string data;
  for (const auto& point : integerPoints()) {
    const double xyz[3] = {double (point[0]), double (point[1]), double (point[2])};
    const std::uint32_t rgb = 0x00ff8000u + static_cast<std::uint32_t> (point[0]);
    data.append (reinterpret_cast<const char*> (xyz), sizeof (xyz));
    data.append (reinterpret_cast<const char*> (&rgb), sizeof (rgb));
  }
  const std::string path = temporaryPath ("organized.pcd");
  writeFile (path,
             pcdHeader ("x y z rgb", "8 8 8 4", "F F F U", 60, "binary", 10, 6) + data);
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  loadPointCloudFile (path, cloud);
  EXPECT_EQ (cloud.width, 10u);
  EXPECT_EQ (cloud.height, 6u);
  EXPECT_TRUE (cloud.isOrganized());
  const auto points = integerPoints();
  ASSERT_EQ (cloud.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ (cloud[i].x, points[i][0]);
    EXPECT_EQ (cloud[i].z, points[i][2]);
    EXPECT_EQ (cloud[i].rgba & 0xffffffu, 0xff8000u + points[i][0]);
  }
}

TEST (CloudFiles, ReadsTheRealScans)
{
  // ASCII, binary_compressed and binary files, as PCL reads them.
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  PCL_TDA_REQUIRE_DATA ("milk.pcd");
  PCL_TDA_REQUIRE_DATA ("colored_cloud.pcd");
  for (const char* name : {"bunny.pcd", "milk.pcd", "colored_cloud.pcd"}) {
    pcl::PointCloud<pcl::PointXYZ> ours, reference;
    loadPointCloudFile (test::dataFile (name), ours);
    ASSERT_EQ (pcl::io::loadPCDFile (test::dataFile (name), reference), 0);
    ASSERT_EQ (ours.size(), reference.size()) << name;
    for (std::size_t i = 0; i < ours.size(); ++i)
      ASSERT_EQ (ours[i].getVector3fMap(), reference[i].getVector3fMap()) << name;
  }
}

TEST (CloudFiles, RefusesWhatIsNotARegularFile)
{
  const std::string folder = temporaryPath ("folder.pcd");
  std::filesystem::create_directories (folder);
  EXPECT_NE (refusal (folder).find ("is a directory"), std::string::npos);
  const std::string fifo = temporaryPath ("fifo.pcd");
  std::remove (fifo.c_str());
  ASSERT_EQ (::mkfifo (fifo.c_str(), 0600), 0);
  EXPECT_NE (refusal (fifo).find ("not a regular file"), std::string::npos);
  EXPECT_NE (refusal (temporaryPath ("missing.pcd")).find ("No such file"),
             std::string::npos);
}

TEST (CloudFiles, RefusesMalformedFilesSayingWhy)
{
  for (const auto& [content, message] : pcl::tda::test::malformedPCDFiles()) {
    const std::string path = temporaryPath ("malformed.pcd");
    writeFile (path, content);
    EXPECT_NE (refusal (path).find (message), std::string::npos)
        << content.substr (0, 400) << "\nrefusal: " << refusal (path)
        << "\nexpected: " << message;
  }
}

TEST (CloudFiles, RefusesAHugeClaimAtOnce)
{
  // 168 KB of points whose header claims 300 million (3.6 GB) or 400 million.
  for (const std::size_t claimed : {300000000u, 400000000u}) {
    const std::string path = temporaryPath ("huge.pcd");
    writeFile (path,
               pcdHeader ("x y z", "4 4 4", "F F F", claimed, "binary") +
                   std::string (168000, '\0'));
    const auto start = std::chrono::steady_clock::now();
    const std::string message = refusal (path);
    const std::chrono::duration<double> seconds =
        std::chrono::steady_clock::now() - start;
    EXPECT_NE (message.find (std::to_string (claimed) + " points"), std::string::npos)
        << message;
    EXPECT_LT (seconds.count(), 1.0);
  }
}

TEST (CloudFiles, LayoutOfAHeader)
{
  std::istringstream file (
      pcdHeader ("x y z rgb", "4 4 4 4", "F F F U", 6, "binary", 3, 2) +
      std::string (6 * 16, '\0'));
  const PCDLayout layout = readPCDLayout (file, file.str().size());
  EXPECT_EQ (layout.data, PCDData::BINARY);
  EXPECT_EQ (layout.header.width, 3u);
  EXPECT_EQ (layout.header.height, 2u);
  EXPECT_EQ (layout.header.point_step, 16u);
  ASSERT_EQ (layout.header.fields.size(), 4u);
  EXPECT_EQ (layout.header.fields[3].offset, 12u);
  EXPECT_EQ (layout.header.fields[3].datatype, pcl::PCLPointField::UINT32);
  EXPECT_EQ (layout.data_offset, file.str().size() - 6 * 16);
}
