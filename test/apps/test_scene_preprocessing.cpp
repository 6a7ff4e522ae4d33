#include <pcl/io/pcd_io.h>
#include <pcl/tda/apps/scene_preprocessing.h>

#include <gtest/gtest.h>

#include "test_data.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

using namespace pcl::tda;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

namespace {

/** The points of \a cloud as sorted (x, y, z) triples. */
std::vector<std::tuple<float, float, float>>
sortedPoints (const Cloud& cloud)
{
  std::vector<std::tuple<float, float, float>> points;
  for (const auto& point : cloud)
    points.emplace_back (point.x, point.y, point.z);
  std::sort (points.begin(), points.end());
  return points;
}

/** The table scene and the segmentation tool's preprocessing of it (depth cut-off
 * 1.5 m, plane removal). */
class TableScene : public ::testing::Test {
protected:
  void
  SetUp () override
  {
    PCL_TDA_REQUIRE_DATA ("table_scene_mug_stereo_textured.pcd");
    ASSERT_EQ (pcl::io::loadPCDFile (
                   test::dataFile ("table_scene_mug_stereo_textured.pcd"), scene),
               0);
    options.max_depth = 1.5;
  }

  Cloud scene;
  ScenePreprocessing options;
};

} // namespace

// The depth cut-off, RANSAC plane removal and voxel grid give the same points, in
// the same order, for shuffled copies of the table scene (RANSAC samples indices, so
// it needs a canonical order first).
TEST_F (TableScene, SamePointsForShuffledInput)
{
  PreprocessingCounts counts;
  const Cloud::Ptr expected = preprocessScene (scene, options, &counts);
  ASSERT_GT (counts.plane, 100000u);
  options.leaf = 0.01;
  const Cloud::Ptr expected_voxels = preprocessScene (scene, options);

  std::mt19937 random (31);
  for (int copy = 0; copy < 3; ++copy) {
    Cloud shuffled = scene;
    std::shuffle (shuffled.begin(), shuffled.end(), random);
    shuffled.width = static_cast<std::uint32_t> (shuffled.size());
    shuffled.height = 1;
    options.leaf = 0.0;
    PreprocessingCounts shuffled_counts;
    const Cloud::Ptr actual = preprocessScene (shuffled, options, &shuffled_counts);
    EXPECT_EQ (shuffled_counts.plane, counts.plane) << "copy " << copy;
    EXPECT_EQ (sortedPoints (*actual), sortedPoints (*expected)) << "copy " << copy;
    options.leaf = 0.01;
    const Cloud::Ptr voxels = preprocessScene (shuffled, options);
    ASSERT_EQ (voxels->size(), expected_voxels->size());
    for (std::size_t i = 0; i < voxels->size(); ++i)
      ASSERT_EQ (std::tie ((*voxels)[i].x, (*voxels)[i].y, (*voxels)[i].z),
                 std::tie ((*expected_voxels)[i].x,
                           (*expected_voxels)[i].y,
                           (*expected_voxels)[i].z))
          << "copy " << copy << " point " << i;
  }
}

// The plane is found in any unit: the table scene in kilometres, millimetres and
// micrometres (scaled by powers of two near them, exact in float) loses the same
// plane points. PCL's collinearity test of RANSAC's samples has an absolute
// threshold, under which no sample of a scene a few centimetres wide passed.
TEST_F (TableScene, SamePlaneInAnyUnit)
{
  PreprocessingCounts counts;
  preprocessScene (scene, options, &counts);
  ASSERT_GT (counts.plane, 100000u);
  for (const int exponent : {-10, 10, 20}) {
    Cloud scaled = scene;
    const float unit = std::ldexp (1.0f, exponent);
    for (auto& point : scaled)
      point.getVector3fMap() *= unit;
    ScenePreprocessing scaled_options = options;
    scaled_options.max_depth *= unit;
    scaled_options.plane_distance *= unit;
    PreprocessingCounts scaled_counts;
    preprocessScene (scaled, scaled_options, &scaled_counts);
    EXPECT_EQ (scaled_counts.plane, counts.plane) << "unit 2^" << exponent;
  }
}
