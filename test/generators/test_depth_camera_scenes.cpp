// Tests of the depth camera scenes: determinism, the organized frame, labels against
// the ground truth, noise and quantization of the depth, gaps between objects, table
// removal and the parameter checks; the painting in colour regions: labels, shaded
// colours, colour differences of adjacent regions (against PCL's CIELAB conversion),
// the colour noise and the unchanged unpainted frames.

#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/exceptions.h>
#include <pcl/point_types_conversion.h>

#include <gtest/gtest.h>

#include "generators/generator_test_utils.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <vector>

using pcl::tda::DepthCameraObject;
using pcl::tda::DepthCameraParameters;
using pcl::tda::DepthCameraScene;
using pcl::tda::DepthColourRegion;
using pcl::tda::test::identical;

using pcl::tda::test::deltaE;
using pcl::tda::test::fingerprint;

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

/** A small frame painted in colour regions, the table kept. */
DepthCameraScene
paintedScene (std::uint64_t seed, float colour_noise = 0.0f)
{
  DepthCameraParameters p = smallCamera (seed);
  p.colour_regions = true;
  p.remove_table = false;
  p.colour_noise = colour_noise;
  return pcl::tda::generateDepthCameraScene (p);
}

/** The pairs (a, b), a < b, of region labels of neighbouring pixels (4-connected)
 * whose points are at most 1 cm apart. */
std::set<std::pair<std::uint32_t, std::uint32_t>>
adjacentRegions (const DepthCameraScene& scene)
{
  const auto& cloud = *scene.cloud;
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t v = 0; v < cloud.height; ++v)
    for (std::size_t u = 0; u < cloud.width; ++u) {
      const std::size_t i = v * cloud.width + u;
      for (const std::size_t j : {i + 1, i + cloud.width}) {
        if ((j == i + 1 && u + 1 == cloud.width) || j >= cloud.size())
          continue;
        const std::uint32_t a = scene.region_labels[i], b = scene.region_labels[j];
        if (a != 0 && b != 0 && a != b &&
            (cloud[i].getVector3fMap() - cloud[j].getVector3fMap()).norm() <= 0.01f)
          pairs.emplace (std::min (a, b), std::max (a, b));
      }
    }
  return pairs;
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
      [] (DepthCameraParameters& p) { p.colour_noise = -1.0f; },
      [] (DepthCameraParameters& p) { p.colour_noise = std::nanf (""); },
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

TEST (DepthCameraScenes, UnpaintedFramesAreThoseOfTheGeneratorBeforeColourRegions)
{
  // Fingerprint of this frame made by the generator before colour regions existed.
  DepthCameraParameters p = smallCamera (3);
  p.remove_table = false;
  const DepthCameraScene scene = pcl::tda::generateDepthCameraScene (p);
  EXPECT_EQ (0xebc0d7179031f2baULL, fingerprint (*scene.cloud));
  // The table is region 1, every object one region.
  ASSERT_EQ (scene.cloud->size(), scene.region_labels.size());
  ASSERT_EQ (scene.objects.size() + 1, scene.regions.size());
  EXPECT_EQ (pcl::tda::DEPTH_BACKGROUND_LABEL, scene.regions[0].object_label);
  EXPECT_EQ (scene.num_table_points, scene.regions[0].num_points);
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    EXPECT_EQ (scene.objects[k].label, scene.regions[k + 1].object_label);
    EXPECT_EQ (k + 2, scene.regions[k + 1].label);
  }
  for (std::size_t i = 0; i < scene.cloud->size(); ++i) {
    const auto& point = (*scene.cloud)[i];
    const std::uint32_t expected = !std::isfinite (point.x) ? 0u
                                   : point.label == pcl::tda::DEPTH_BACKGROUND_LABEL
                                       ? 1u
                                       : point.label + 1;
    ASSERT_EQ (expected, scene.region_labels[i]);
  }
  EXPECT_TRUE (scene.similar_regions.empty());
  // Without the table, the objects are regions 1..
  p.remove_table = true;
  const DepthCameraScene removed = pcl::tda::generateDepthCameraScene (p);
  ASSERT_EQ (scene.objects.size(), removed.regions.size());
  for (std::size_t i = 0; i < removed.cloud->size(); ++i)
    ASSERT_EQ ((*removed.cloud)[i].label, removed.region_labels[i]);
}

TEST (DepthCameraScenes, PaintingAndColourNoiseChangeOnlyTheColours)
{
  const DepthCameraScene a = paintedScene (7, 5.0f);
  const DepthCameraScene b = paintedScene (7, 5.0f);
  const DepthCameraScene c = paintedScene (8, 5.0f);
  EXPECT_TRUE (identical (*a.cloud, *b.cloud));
  EXPECT_EQ (a.region_labels, b.region_labels);
  EXPECT_EQ (a.similar_regions, b.similar_regions);
  EXPECT_FALSE (identical (*a.cloud, *c.cloud));
  DepthCameraParameters p = smallCamera (7);
  p.remove_table = false;
  const DepthCameraScene plain = pcl::tda::generateDepthCameraScene (p);
  ASSERT_EQ (plain.cloud->size(), a.cloud->size());
  std::size_t recoloured = 0;
  for (std::size_t i = 0; i < a.cloud->size(); ++i) {
    const auto& painted = (*a.cloud)[i];
    const auto& unpainted = (*plain.cloud)[i];
    ASSERT_EQ (0, std::memcmp (painted.data, unpainted.data, 3 * sizeof (float)));
    ASSERT_EQ (painted.label, unpainted.label);
    recoloured += painted.rgba != unpainted.rgba;
  }
  EXPECT_GT (recoloured, a.cloud->size() / 10);
}

TEST (DepthCameraScenes, ColourRegionLabelsAreContiguousAndCarryTheirShadedColours)
{
  std::set<std::pair<pcl::tda::DepthObjectKind, std::uint32_t>> parts_seen;
  for (std::uint64_t seed = 0; seed < 12; ++seed) {
    SCOPED_TRACE ("seed " + std::to_string (seed));
    const DepthCameraScene scene = paintedScene (seed);
    ASSERT_EQ (scene.cloud->size(), scene.region_labels.size());
    const std::size_t count = scene.regions.size();
    for (std::size_t i = 0; i < count; ++i)
      ASSERT_EQ (i + 1, scene.regions[i].label);
    ASSERT_GT (count, scene.objects.size() + 1);
    EXPECT_EQ (pcl::tda::DEPTH_BACKGROUND_LABEL, scene.regions[0].object_label);
    std::vector<std::size_t> points (count, 0);
    for (std::size_t i = 0; i < scene.cloud->size(); ++i) {
      const auto& point = (*scene.cloud)[i];
      const std::uint32_t label = scene.region_labels[i];
      if (!std::isfinite (point.x)) {
        ASSERT_EQ (0u, label);
        continue;
      }
      ASSERT_GE (label, 1u);
      ASSERT_LE (label, count);
      ++points[label - 1];
      const DepthColourRegion& region = scene.regions[label - 1];
      ASSERT_EQ (region.object_label, point.label);
      // Shaded: the region's colour times one factor in [0.35, 1], rounded.
      const std::array<double, 3> base = {
          double (region.r), double (region.g), double (region.b)};
      const std::array<double, 3> seen = {
          double (point.r), double (point.g), double (point.b)};
      const std::size_t brightest =
          std::max_element (base.begin(), base.end()) - base.begin();
      ASSERT_GT (base[brightest], 0.0);
      const double factor = seen[brightest] / base[brightest];
      ASSERT_GE (factor, 0.35 - 0.5 / base[brightest]);
      ASSERT_LE (factor, 1.0 + 1e-9);
      for (std::size_t c = 0; c < 3; ++c)
        ASSERT_NEAR (base[c] * factor, seen[c], 1.0 + 1e-9);
    }
    for (std::size_t i = 0; i < count; ++i) {
      EXPECT_GT (points[i], 0u);
      EXPECT_EQ (points[i], scene.regions[i].num_points);
      if (i > 0) {
        parts_seen.emplace (scene.objects[scene.regions[i].object_label - 1].kind,
                            scene.regions[i].part);
      }
    }
    // The cloud labelled by region.
    const auto labelled = pcl::tda::regionLabelledCloud (scene);
    ASSERT_EQ (scene.cloud->size(), labelled->size());
    EXPECT_TRUE (labelled->isOrganized());
    for (std::size_t i = 0; i < labelled->size(); ++i)
      ASSERT_EQ (scene.region_labels[i], (*labelled)[i].label);
  }
  // Every part of every kind is seen somewhere, and no other part.
  using Kind = pcl::tda::DepthObjectKind;
  const std::set<std::pair<Kind, std::uint32_t>> expected = {{Kind::BOWL, 0},
                                                             {Kind::BOWL, 1},
                                                             {Kind::CONE, 0},
                                                             {Kind::CONE, 1},
                                                             {Kind::RING, 0},
                                                             {Kind::RING, 1},
                                                             {Kind::L_BLOCK, 0},
                                                             {Kind::L_BLOCK, 1},
                                                             {Kind::CAPSULE, 0},
                                                             {Kind::CAPSULE, 1},
                                                             {Kind::CAPSULE, 2}};
  EXPECT_EQ (expected, parts_seen);
}

TEST (DepthCameraScenes, AdjacentRegionsHaveTheDocumentedColourDifferences)
{
  std::size_t subtle = 0, painted = 0, similar_adjacent = 0, similar = 0;
  for (std::uint64_t seed = 0; seed < 16; ++seed) {
    SCOPED_TRACE ("seed " + std::to_string (seed));
    const DepthCameraScene scene = paintedScene (seed, 4.0f);
    const std::set<std::pair<std::uint32_t, std::uint32_t>> similar_pairs (
        scene.similar_regions.begin(), scene.similar_regions.end());
    std::set<std::uint32_t> subtle_objects;
    for (const auto& [a, b] : scene.similar_regions) {
      const DepthColourRegion& ra = scene.regions[a - 1];
      const DepthColourRegion& rb = scene.regions[b - 1];
      EXPECT_EQ (ra.object_label, rb.object_label);
      EXPECT_NE (pcl::tda::DEPTH_BACKGROUND_LABEL, ra.object_label);
      EXPECT_GE (deltaE (ra, rb), pcl::tda::DEPTH_SUBTLE_MIN_DELTA_E);
      EXPECT_LE (deltaE (ra, rb), pcl::tda::DEPTH_SUBTLE_MAX_DELTA_E);
      subtle_objects.insert (ra.object_label);
    }
    similar += similar_pairs.size();
    subtle += subtle_objects.size();
    painted += scene.objects.size();
    for (const auto& [a, b] : adjacentRegions (scene)) {
      const DepthColourRegion& ra = scene.regions[a - 1];
      const DepthColourRegion& rb = scene.regions[b - 1];
      const double difference = deltaE (ra, rb);
      SCOPED_TRACE ("regions " + std::to_string (a) + " and " + std::to_string (b));
      if (similar_pairs.count ({a, b}) != 0) {
        ++similar_adjacent;
      }
      else if (ra.object_label == pcl::tda::DEPTH_BACKGROUND_LABEL) {
        EXPECT_GE (difference, pcl::tda::DEPTH_TABLE_MIN_DELTA_E);
      }
      else if (ra.object_label == rb.object_label) {
        EXPECT_GE (difference, pcl::tda::DEPTH_CONTRAST_MIN_DELTA_E);
      }
      else {
        EXPECT_GE (difference, pcl::tda::DEPTH_OBJECTS_MIN_DELTA_E);
      }
    }
    // Regions of different objects differ, whether adjacent or not, and every
    // object region differs from the table.
    for (const DepthColourRegion& ra : scene.regions)
      for (const DepthColourRegion& rb : scene.regions)
        if (ra.label < rb.label && ra.object_label != rb.object_label) {
          EXPECT_GE (deltaE (ra, rb),
                     ra.object_label == pcl::tda::DEPTH_BACKGROUND_LABEL
                         ? pcl::tda::DEPTH_TABLE_MIN_DELTA_E
                         : pcl::tda::DEPTH_OBJECTS_MIN_DELTA_E);
        }
  }
  // About half of the objects are subtle; most subtle pairs touch in the image.
  EXPECT_GT (subtle, painted / 4);
  EXPECT_LT (subtle, painted * 3 / 4);
  EXPECT_GE (similar_adjacent, similar * 3 / 4);
}

TEST (DepthCameraScenes, ColourNoiseIsABrightnessPlusAChannelOffset)
{
  const DepthCameraScene clean = paintedScene (2);
  const float sigma = 6.0f;
  const DepthCameraScene noisy = paintedScene (2, sigma);
  std::array<std::vector<double>, 3> offsets;
  for (std::size_t i = 0; i < clean.cloud->size(); ++i) {
    const auto& a = (*clean.cloud)[i];
    const auto& b = (*noisy.cloud)[i];
    if (!std::isfinite (a.x))
      continue;
    const std::array<int, 3> before = {a.r, a.g, a.b}, after = {b.r, b.g, b.b};
    for (std::size_t c = 0; c < 3; ++c) {
      // Within 4 + 2 standard deviations, rounded.
      ASSERT_LE (std::abs (after[c] - before[c]), 6.0 * sigma + 1.0);
      if (before[c] > 40 && before[c] < 215) // far from clamping
        offsets[c].push_back (after[c] - before[c]);
    }
  }
  ASSERT_GT (offsets[0].size(), 5000u);
  // Each channel: variance sigma^2 (brightness) + (sigma / 2)^2 (its own).
  for (std::size_t c = 0; c < 3; ++c) {
    const auto [mean, deviation] = meanAndDeviation (offsets[c]);
    EXPECT_NEAR (0.0, mean, 0.2);
    EXPECT_NEAR (sigma * std::sqrt (1.25), deviation, 0.05 * sigma);
  }
  // The channels are correlated by the common brightness: the difference of two
  // channels has only the channel offsets, variance 2 (sigma / 2)^2.
  std::vector<double> differences;
  for (std::size_t i = 0; i < clean.cloud->size(); ++i) {
    const auto& a = (*clean.cloud)[i];
    const auto& b = (*noisy.cloud)[i];
    if (std::isfinite (a.x) && a.r > 40 && a.r < 215 && a.g > 40 && a.g < 215)
      differences.push_back ((b.r - a.r) - (b.g - a.g));
  }
  ASSERT_GT (differences.size(), 5000u);
  EXPECT_NEAR (
      sigma * std::sqrt (0.5), meanAndDeviation (differences).second, 0.08 * sigma);
}
