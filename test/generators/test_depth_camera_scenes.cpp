// Tests of the depth camera scenes: determinism, the organized frame, labels against
// the ground truth, noise and quantization of the depth, gaps between objects, table
// removal and the parameter checks.

#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include "generators/generator_test_utils.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <vector>

using pcl::tda::DepthCameraObject;
using pcl::tda::DepthCameraParameters;
using pcl::tda::DepthCameraScene;
using pcl::tda::test::identical;

namespace {

/** A scene with the default parameters but the seed and a smaller image. */
DepthCameraParameters
smallCamera (std::uint64_t seed)
{
  DepthCameraParameters p;
  p.width = 320;
  p.height = 240;
  p.fx = p.fy = 262.5f;
  p.cx = 159.5f;
  p.cy = 119.5f;
  p.seed = seed;
  return p;
}

/** Number of points of each label among the finite points. */
std::map<std::uint32_t, std::size_t>
labelCounts (const pcl::PointCloud<pcl::PointXYZRGBL>& cloud)
{
  std::map<std::uint32_t, std::size_t> counts;
  for (const auto& point : cloud)
    if (std::isfinite (point.x))
      ++counts[point.label];
  return counts;
}

/** Mean and standard deviation. */
std::pair<double, double>
meanAndDeviation (const std::vector<double>& values)
{
  double sum = 0.0, sum2 = 0.0;
  for (const double v : values) {
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / values.size();
  return {mean, std::sqrt (std::max (sum2 / values.size() - mean * mean, 0.0))};
}

} // namespace

TEST (DepthCameraScenes, EqualSeedsGiveIdenticalScenes)
{
  const DepthCameraScene a = pcl::tda::generateDepthCameraScene (smallCamera (3));
  const DepthCameraScene b = pcl::tda::generateDepthCameraScene (smallCamera (3));
  const DepthCameraScene c = pcl::tda::generateDepthCameraScene (smallCamera (4));
  EXPECT_TRUE (identical (*a.cloud, *b.cloud));
  EXPECT_FALSE (identical (*a.cloud, *c.cloud));
  ASSERT_EQ (a.objects.size(), b.objects.size());
  for (std::size_t k = 0; k < a.objects.size(); ++k) {
    EXPECT_EQ (a.objects[k].kind, b.objects[k].kind);
    EXPECT_EQ (a.objects[k].position, b.objects[k].position);
    EXPECT_EQ (a.objects[k].num_points, b.objects[k].num_points);
  }
  EXPECT_TRUE (a.camera_pose.isApprox (b.camera_pose, 0.0f));
}

TEST (DepthCameraScenes, OrganizedFrameOfTheCamera)
{
  for (const bool small : {false, true}) {
    const DepthCameraParameters p = small ? smallCamera (1) : DepthCameraParameters();
    const DepthCameraScene scene = pcl::tda::generateDepthCameraScene (p);
    EXPECT_EQ (scene.cloud->width, p.width);
    EXPECT_EQ (scene.cloud->height, p.height);
    EXPECT_EQ (scene.cloud->size(), p.width * p.height);
    EXPECT_TRUE (scene.cloud->isOrganized());
    EXPECT_FALSE (scene.cloud->is_dense);
    // Every finite point projects back onto its own pixel.
    std::size_t finite = 0;
    for (std::size_t v = 0; v < p.height; ++v)
      for (std::size_t u = 0; u < p.width; ++u) {
        const pcl::PointXYZRGBL& point = (*scene.cloud) (u, v);
        if (!std::isfinite (point.x)) {
          EXPECT_TRUE (std::isnan (point.y) && std::isnan (point.z));
          EXPECT_EQ (point.label, pcl::tda::DEPTH_BACKGROUND_LABEL);
          continue;
        }
        ++finite;
        ASSERT_GT (point.z, 0.0f);
        EXPECT_NEAR (p.fx * point.x / point.z + p.cx, u, 1e-3);
        EXPECT_NEAR (p.fy * point.y / point.z + p.cy, v, 1e-3);
      }
    EXPECT_GT (finite, 1000u);
  }
}

TEST (DepthCameraScenes, LabelsMatchTheObjects)
{
  std::set<pcl::tda::DepthObjectKind> kinds;
  std::size_t objects = 0, visible = 0;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const DepthCameraParameters p = smallCamera (seed);
    const DepthCameraScene scene = pcl::tda::generateDepthCameraScene (p);
    ASSERT_GE (scene.objects.size(), p.min_objects);
    ASSERT_LE (scene.objects.size(), p.max_objects);
    const auto counts = labelCounts (*scene.cloud);
    // The table is removed by default: only object labels are left.
    EXPECT_EQ (counts.count (pcl::tda::DEPTH_BACKGROUND_LABEL), 0u);
    std::size_t labelled = 0;
    for (std::size_t k = 0; k < scene.objects.size(); ++k) {
      const DepthCameraObject& object = scene.objects[k];
      EXPECT_EQ (object.label, pcl::tda::DEPTH_FIRST_OBJECT_LABEL + k);
      const auto found = counts.find (object.label);
      EXPECT_EQ (found == counts.end() ? 0u : found->second, object.num_points);
      labelled += object.num_points;
      visible += object.num_points >= 30;
      kinds.insert (object.kind);
    }
    std::size_t finite = 0;
    for (const auto& [label, count] : counts)
      finite += count;
    EXPECT_EQ (labelled, finite);
    objects += scene.objects.size();
  }
  EXPECT_EQ (kinds.size(), 5u);
  // Objects may hide one another, but most are well seen.
  EXPECT_GE (visible, objects * 9 / 10);
}

TEST (DepthCameraScenes, ObjectsDoNotOverlap)
{
  std::size_t close = 0, far = 0;
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    DepthCameraParameters p = smallCamera (seed);
    p.noise_coefficient = 0.0f;
    p.disparity_step = 0.0f;
    const DepthCameraScene scene = pcl::tda::generateDepthCameraScene (p);
    // Points in the world frame, seen from above, by object.
    std::vector<std::vector<Eigen::Vector2f>> seen (scene.objects.size());
    for (const auto& point : *scene.cloud) {
      if (!std::isfinite (point.x))
        continue;
      const Eigen::Vector3f world = scene.camera_pose * point.getVector3fMap();
      EXPECT_GT (world.z(), -1e-4f);
      const DepthCameraObject& object =
          scene.objects[point.label - pcl::tda::DEPTH_FIRST_OBJECT_LABEL];
      // Inside the object's bounding box.
      const Eigen::Vector3f local =
          Eigen::AngleAxisf (-object.yaw, Eigen::Vector3f::UnitZ()) *
          (world - object.position);
      EXPECT_LE (std::abs (local.x()), 0.5f * object.dimensions.x() + 1e-4f);
      EXPECT_LE (std::abs (local.y()), 0.5f * object.dimensions.y() + 1e-4f);
      EXPECT_LE (local.z(), object.dimensions.z() + 1e-4f);
      seen[point.label - pcl::tda::DEPTH_FIRST_OBJECT_LABEL].push_back (
          world.head<2>());
    }
    for (std::size_t k = 0; k < scene.objects.size(); ++k) {
      const float gap = scene.objects[k].gap;
      EXPECT_GE (gap, p.min_close_gap * (1.0f - 1e-5f));
      close += gap <= p.max_close_gap;
      far += gap >= p.min_far_gap;
      // Seen from above, no point of another object is nearer than the gap.
      for (std::size_t j = 0; j < scene.objects.size(); ++j) {
        if (j == k)
          continue;
        float nearest = std::numeric_limits<float>::infinity();
        for (const Eigen::Vector2f& a : seen[k])
          for (const Eigen::Vector2f& b : seen[j])
            nearest = std::min (nearest, (a - b).norm());
        EXPECT_GE (nearest, gap - 1e-4f)
            << "seed " << seed << " objects " << k << ", " << j;
      }
    }
  }
  EXPECT_GT (close, 0u);
  EXPECT_GT (far, 0u);
}

TEST (DepthCameraScenes, NoiseGrowsWithDepth)
{
  // Without quantization, the depth of the table pixels scatters about the plane by
  // noise_coefficient * z^2.
  std::vector<double> near, far;
  for (std::uint64_t seed = 0; seed < 4; ++seed) {
    DepthCameraParameters p = smallCamera (seed);
    p.remove_table = false;
    p.disparity_step = 0.0f;
    p.noise_coefficient = 3e-3f;
    const DepthCameraScene scene = pcl::tda::generateDepthCameraScene (p);
    EXPECT_GT (scene.num_table_points, 0u);
    const Eigen::Vector3f normal = scene.table_plane.head<3>();
    for (const auto& point : *scene.cloud) {
      if (!std::isfinite (point.x) || point.label != pcl::tda::DEPTH_BACKGROUND_LABEL)
        continue;
      // The pixel's ray meets the plane at depth z.
      const Eigen::Vector3f ray = point.getVector3fMap() / point.z;
      const double z = -scene.table_plane[3] / normal.dot (ray);
      const double relative = (point.z - z) / (p.noise_coefficient * z * z);
      EXPECT_LE (std::abs (relative), 4.0 + 1e-3);
      if (z < 0.9)
        near.push_back (point.z - z);
      else if (z > 1.4)
        far.push_back (point.z - z);
    }
  }
  ASSERT_GT (near.size(), 1000u);
  ASSERT_GT (far.size(), 1000u);
  const auto [near_mean, near_sigma] = meanAndDeviation (near);
  const auto [far_mean, far_sigma] = meanAndDeviation (far);
  EXPECT_NEAR (near_mean, 0.0, 1e-4);
  EXPECT_NEAR (far_mean, 0.0, 3e-4);
  EXPECT_GT (far_sigma, 2.0 * near_sigma);
  EXPECT_LT (near_sigma, 3e-3 * 0.9 * 0.9);
  EXPECT_GT (far_sigma, 3e-3 * 1.4 * 1.4 * 0.9);
}

TEST (DepthCameraScenes, DisparityIsQuantized)
{
  DepthCameraParameters p = smallCamera (2);
  p.remove_table = false;
  const DepthCameraScene scene = pcl::tda::generateDepthCameraScene (p);
  std::set<long> levels;
  for (const auto& point : *scene.cloud) {
    if (!std::isfinite (point.x))
      continue;
    const double steps = p.fx * p.baseline / point.z / p.disparity_step;
    EXPECT_NEAR (steps, std::round (steps), 1e-3);
    levels.insert (std::lround (steps));
  }
  EXPECT_GT (levels.size(), 20u);
}

TEST (DepthCameraScenes, TableRemovalKeepsTheObjects)
{
  DepthCameraParameters p = smallCamera (5);
  const DepthCameraScene removed = pcl::tda::generateDepthCameraScene (p);
  p.remove_table = false;
  const DepthCameraScene kept = pcl::tda::generateDepthCameraScene (p);
  EXPECT_EQ (removed.num_table_points, kept.num_table_points);
  std::size_t table = 0;
  for (std::size_t i = 0; i < kept.cloud->size(); ++i) {
    const auto& a = (*kept.cloud)[i];
    const auto& b = (*removed.cloud)[i];
    if (std::isfinite (a.x) && a.label == pcl::tda::DEPTH_BACKGROUND_LABEL) {
      ++table;
      EXPECT_TRUE (std::isnan (b.x));
      continue;
    }
    EXPECT_EQ (a.label, b.label);
    EXPECT_EQ (std::isfinite (a.x), std::isfinite (b.x));
    if (std::isfinite (a.x)) {
      EXPECT_EQ (a.getVector3fMap(), b.getVector3fMap());
    }
  }
  EXPECT_EQ (table, kept.num_table_points);
  EXPECT_GT (table, 1000u);
}

TEST (DepthCameraScenes, GrazingRaysDropOut)
{
  DepthCameraParameters p = smallCamera (6);
  p.remove_table = false;
  p.grazing_start_deg = 0.0f;
  p.grazing_full_deg = 0.0f;
  const DepthCameraScene none = pcl::tda::generateDepthCameraScene (p);
  EXPECT_TRUE (std::all_of (none.cloud->begin(),
                            none.cloud->end(),
                            [] (const auto& point) { return std::isnan (point.x); }));
  // Tilted surfaces (the table, seen at 30-60 degrees of elevation) lose pixels
  // when the dropout starts early.
  p.grazing_start_deg = 20.0f;
  p.grazing_full_deg = 90.0f;
  const DepthCameraScene some = pcl::tda::generateDepthCameraScene (p);
  p.grazing_start_deg = 90.0f;
  const DepthCameraScene all = pcl::tda::generateDepthCameraScene (p);
  EXPECT_LT (some.num_table_points, all.num_table_points * 9 / 10);
  EXPECT_GT (some.num_table_points, 0u);
}

TEST (DepthCameraScenes, InvalidParametersThrow)
{
  const std::vector<std::function<void (DepthCameraParameters&)>> invalid = {
      [] (DepthCameraParameters& p) { p.min_objects = 0; },
      [] (DepthCameraParameters& p) { p.min_objects = 7; },
      [] (DepthCameraParameters& p) { p.max_objects = 9; },
      [] (DepthCameraParameters& p) { p.width = 0; },
      [] (DepthCameraParameters& p) { p.height = 5000; },
      [] (DepthCameraParameters& p) { p.fx = 0.0f; },
      [] (DepthCameraParameters& p) { p.fy = -1.0f; },
      [] (DepthCameraParameters& p) { p.cx = std::nanf (""); },
      [] (DepthCameraParameters& p) { p.min_distance = 0.0f; },
      [] (DepthCameraParameters& p) { p.max_distance = 0.5f; },
      [] (DepthCameraParameters& p) { p.min_elevation_deg = 0.0f; },
      [] (DepthCameraParameters& p) { p.max_elevation_deg = 90.0f; },
      [] (DepthCameraParameters& p) { p.min_elevation_deg = 70.0f; },
      [] (DepthCameraParameters& p) { p.min_distance = 0.3f; },
      [] (DepthCameraParameters& p) { p.table_width = 0.0f; },
      [] (DepthCameraParameters& p) { p.table_depth = INFINITY; },
      [] (DepthCameraParameters& p) { p.layout_radius = 0.5f; },
      [] (DepthCameraParameters& p) { p.close_probability = 1.5f; },
      [] (DepthCameraParameters& p) { p.min_close_gap = 0.0f; },
      [] (DepthCameraParameters& p) { p.max_close_gap = 0.005f; },
      [] (DepthCameraParameters& p) { p.min_far_gap = -0.1f; },
      [] (DepthCameraParameters& p) { p.noise_coefficient = -1e-3f; },
      [] (DepthCameraParameters& p) { p.baseline = 0.0f; },
      [] (DepthCameraParameters& p) { p.disparity_step = std::nanf (""); },
      [] (DepthCameraParameters& p) { p.grazing_start_deg = 89.0f; },
      [] (DepthCameraParameters& p) { p.grazing_full_deg = 95.0f; },
      // No layout: eight objects, each 30 cm from the others, in a 10 cm disc.
      [] (DepthCameraParameters& p) {
        p.min_objects = p.max_objects = 8;
        p.layout_radius = 0.1f;
        p.close_probability = 0.0f;
        p.min_far_gap = 0.3f;
      },
  };
  for (std::size_t i = 0; i < invalid.size(); ++i) {
    DepthCameraParameters p = smallCamera (0);
    invalid[i](p);
    EXPECT_THROW (pcl::tda::generateDepthCameraScene (p), pcl::BadArgumentException)
        << "case " << i;
  }
}
