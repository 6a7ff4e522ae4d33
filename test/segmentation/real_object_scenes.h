// Scenes made of real object scans, for validating automatic choices on data made
// differently from both scene generators: the objects are scans of shared/data
// (their own sampling, holes and noise), not generated surfaces.
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl {
namespace tda {
namespace test {

/** The object scans a real-object scene draws from (files of the data folder). */
const std::vector<std::string>&
realObjectScanFiles ();

/** Loads the finite points of each of realObjectScanFiles() from \a data_dir;
 * empty when one of them cannot be read. */
std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr>
loadRealObjectScans (const std::string& data_dir);

/** A scene of 3 to 6 of the \a scans (drawn with repetition, seeded by \a seed):
 * each a random subsample of 1,000 to 4,000 of its points, turned by a random
 * rotation, scaled to a bounding-box diagonal of 10 to 25 cm, and placed at a random
 * spot of a 0.8 m x 0.8 m square no closer than 1.5 cm to the objects placed
 * before it (a spot that is too close is drawn again, up to 200 times, after which
 * the object is left out). No table, no added noise. Labels: 1, 2, ... per object,
 * in the order placed. */
pcl::PointCloud<pcl::PointXYZRGBL>
makeRealObjectScene (const std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr>& scans,
                     std::uint64_t seed);

} // namespace test
} // namespace tda
} // namespace pcl
