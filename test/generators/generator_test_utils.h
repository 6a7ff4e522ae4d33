#pragma once

// Helpers shared by the tests of the synthetic cloud generators and of the
// pcl_tda_generate tool: bitwise comparison of clouds and per-test temporary folders.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <string>

namespace pcl {
namespace tda {
namespace test {

/** \brief Bitwise equality of coordinates, colour and label of every point. */
inline bool
identical (const pcl::PointCloud<pcl::PointXYZRGBL>& a,
           const pcl::PointCloud<pcl::PointXYZRGBL>& b)
{
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp (a[i].data, b[i].data, 3 * sizeof (float)) != 0 ||
        a[i].rgba != b[i].rgba || a[i].label != b[i].label)
      return false;
  return true;
}

/** \brief A fresh folder under the system temporary folder, removed at the end. */
class TemporaryFolder {
public:
  TemporaryFolder()
  : path_ (std::filesystem::temp_directory_path() /
           ("pcl_tda_synthetic_" + std::to_string (::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name()))
  {
    std::filesystem::remove_all (path_);
    std::filesystem::create_directories (path_);
  }
  ~TemporaryFolder() { std::filesystem::remove_all (path_); }
  std::string
  path () const
  {
    return path_.string();
  }

private:
  std::filesystem::path path_;
};

} // namespace test
} // namespace tda
} // namespace pcl
