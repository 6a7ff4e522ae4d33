#pragma once

// Helpers shared by the tests of the synthetic cloud generators and of the
// pcl_tda_generate tool: bitwise comparison and fingerprints of clouds, per-test
// temporary folders.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/point_types_conversion.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
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

/** \brief Bitwise equality of coordinates and colour of every point. */
inline bool
identical (const pcl::PointCloud<pcl::PointXYZRGB>& a,
           const pcl::PointCloud<pcl::PointXYZRGB>& b)
{
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp (a[i].data, b[i].data, 3 * sizeof (float)) != 0 ||
        a[i].rgba != b[i].rgba)
      return false;
  return true;
}

/** \brief Bitwise equality of coordinates and label of every point. */
inline bool
identical (const pcl::PointCloud<pcl::PointXYZL>& a,
           const pcl::PointCloud<pcl::PointXYZL>& b)
{
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp (a[i].data, b[i].data, 3 * sizeof (float)) != 0 ||
        a[i].label != b[i].label)
      return false;
  return true;
}

/** \brief Bitwise equality of the coordinates of every point. */
inline bool
identical (const pcl::PointCloud<pcl::PointXYZ>& a,
           const pcl::PointCloud<pcl::PointXYZ>& b)
{
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp (a[i].data, b[i].data, 3 * sizeof (float)) != 0)
      return false;
  return true;
}

/** \brief FNV-1a hash of the coordinates, colour and label of every point: a
 * fingerprint of a generated scene, to check that it stays the same. */
inline std::uint64_t
fingerprint (const pcl::PointCloud<pcl::PointXYZRGBL>& cloud)
{
  std::uint64_t hash = 14695981039346656037ULL;
  for (const auto& point : cloud) {
    unsigned char bytes[20];
    std::memcpy (bytes, &point.x, 4);
    std::memcpy (bytes + 4, &point.y, 4);
    std::memcpy (bytes + 8, &point.z, 4);
    std::memcpy (bytes + 12, &point.rgba, 4);
    std::memcpy (bytes + 16, &point.label, 4);
    for (const unsigned char byte : bytes) {
      hash ^= byte;
      hash *= 1099511628211ULL;
    }
  }
  return hash;
}

/** \brief The CIE76 colour difference of two regions' colours (members r, g, b), by
 * PCL's conversion to CIELAB, independent of the library's own. */
template <typename Region>
double
deltaE (const Region& a, const Region& b)
{
  pcl::PointXYZRGB rgb;
  pcl::PointXYZLAB lab_a, lab_b;
  rgb.r = a.r;
  rgb.g = a.g;
  rgb.b = a.b;
  pcl::PointXYZRGBtoXYZLAB (rgb, lab_a);
  rgb.r = b.r;
  rgb.g = b.g;
  rgb.b = b.b;
  pcl::PointXYZRGBtoXYZLAB (rgb, lab_b);
  return std::sqrt ((lab_a.L - lab_b.L) * (lab_a.L - lab_b.L) +
                    (lab_a.a - lab_b.a) * (lab_a.a - lab_b.a) +
                    (lab_a.b - lab_b.b) * (lab_a.b - lab_b.b));
}

/** \brief A fresh folder under the tests' temporary folder, removed at the end. */
class TemporaryFolder {
public:
  TemporaryFolder()
  : path_ (std::filesystem::path (::testing::TempDir()) /
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
