// Tests of the tabletop scenes: determinism, labels and counts against the ground
// truth, geometry, gaps, colours, visibility, dropout and recoverability; the
// painting in colour regions: labels, colours, colour differences of adjacent
// regions (against PCL's CIELAB conversion) and the unchanged unpainted scenes.

#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/exceptions.h>
#include <pcl/point_types_conversion.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "generators/generator_test_utils.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>

using pcl::tda::PrimitiveType;
using pcl::tda::TabletopColourRegion;
using pcl::tda::TabletopObject;
using pcl::tda::TabletopParameters;
using pcl::tda::TabletopScene;
using pcl::tda::test::identical;
using Cloud = pcl::PointCloud<pcl::PointXYZRGBL>;

using pcl::tda::test::deltaE;
using pcl::tda::test::fingerprint;

namespace {

TabletopScene
tabletop (std::size_t objects, std::uint64_t seed, float noise = 0.001f)
{
  TabletopParameters p;
  p.num_objects = objects;
  p.seed = seed;
  p.noise_sigma = noise;
  return pcl::tda::generateTabletopScene (p);
}

/** Indices of the points of each label. */
std::map<std::uint32_t, std::vector<std::size_t>>
pointsByLabel (const Cloud& cloud)
{
  std::map<std::uint32_t, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    groups[cloud[i].label].push_back (i);
  return groups;
}

/** A point in the frame of an object: centred, yaw removed. */
Eigen::Vector3d
toObjectFrame (const TabletopObject& object, const pcl::PointXYZRGBL& p)
{
  return Eigen::AngleAxisd (-object.yaw, Eigen::Vector3d::UnitZ()) *
         (p.getVector3fMap() - object.centre).cast<double>();
}

/** Outward normal of the object's surface at a point on it, in the world frame. */
Eigen::Vector3d
outwardNormal (const TabletopObject& object, const pcl::PointXYZRGBL& p)
{
  const Eigen::Vector3d local = toObjectFrame (object, p);
  const Eigen::Vector3d half = 0.5 * object.dimensions.cast<double>();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  switch (object.type) {
  case PrimitiveType::BOX: {
    int face = 0;
    (local.array().abs() / half.array()).maxCoeff (&face);
    normal[face] = local[face] > 0 ? 1.0 : -1.0;
    break;
  }
  case PrimitiveType::CYLINDER:
    if (local.z() > half.z() - 1e-5)
      normal = Eigen::Vector3d::UnitZ();
    else
      normal << local.x(), local.y(), 0.0;
    break;
  case PrimitiveType::SPHERE:
    normal = local;
    break;
  }
  return Eigen::AngleAxisd (object.yaw, Eigen::Vector3d::UnitZ()) * normal.normalized();
}

/** Whether a point lies inside the object, deeper than margin. */
bool
insideObject (const TabletopObject& object, const Eigen::Vector3d& point, double margin)
{
  const Eigen::Vector3d local =
      Eigen::AngleAxisd (-object.yaw, Eigen::Vector3d::UnitZ()) *
      (point - object.centre.cast<double>());
  const Eigen::Vector3d half = 0.5 * object.dimensions.cast<double>();
  switch (object.type) {
  case PrimitiveType::BOX:
    return (local.array().abs() < half.array() - margin).all();
  case PrimitiveType::CYLINDER:
    return local.head<2>().norm() < half.x() - margin &&
           std::abs (local.z()) < half.z() - margin;
  case PrimitiveType::SPHERE:
    return local.norm() < half.x() - margin;
  }
  return false;
}

/** Number of points whose line of sight to the camera, walked in 1 mm steps,
 * passes inside an object other than their own. */
std::size_t
hiddenPoints (const TabletopScene& scene, const Eigen::Vector3d& camera)
{
  std::size_t count = 0;
  for (const auto& point : *scene.cloud) {
    const Eigen::Vector3d start = point.getVector3fMap().cast<double>();
    const int steps = static_cast<int> ((camera - start).norm() / 0.001);
    bool hidden = false;
    for (const TabletopObject& object : scene.objects) {
      // Only objects whose bounding sphere meets the line of sight can hide.
      const Eigen::Vector3d centre = object.centre.cast<double>();
      const double t = std::clamp ((centre - start).dot (camera - start) /
                                       (camera - start).squaredNorm(),
                                   0.0,
                                   1.0);
      if (object.label == point.label ||
          (start + t * (camera - start) - centre).norm() >
              0.5 * object.dimensions.norm())
        continue;
      for (int i = 1; i < steps && !hidden; ++i)
        hidden = insideObject (object, start + (camera - start) * i / steps, 1e-4);
    }
    count += hidden;
  }
  return count;
}

/** Connected components of the points at distance <= tolerance (union-find). */
std::vector<std::size_t>
euclideanClusters (const std::vector<Eigen::Vector3f>& points, float tolerance)
{
  std::vector<std::size_t> parent (points.size());
  std::iota (parent.begin(), parent.end(), 0);
  const std::function<std::size_t (std::size_t)> find = [&] (std::size_t i) {
    return parent[i] == i ? i : parent[i] = find (parent[i]);
  };
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      if ((points[i] - points[j]).squaredNorm() <= tolerance * tolerance)
        parent[find (i)] = find (j);
  std::vector<std::size_t> roots (points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    roots[i] = find (i);
  return roots;
}

/** A scene painted in colour regions. */
TabletopScene
regionScene (std::size_t objects,
             std::uint64_t seed,
             const pcl::tda::TabletopNoise& noise = pcl::tda::TABLETOP_NO_NOISE)
{
  TabletopParameters p;
  p.num_objects = objects;
  p.seed = seed;
  p.colour_regions = true;
  p.setNoise (noise);
  return pcl::tda::generateTabletopScene (p);
}

/** The colour of a point, object or region. */
template <typename Coloured>
std::array<int, 3>
colourOf (const Coloured& x)
{
  return {x.r, x.g, x.b};
}

/** The pairs (a, b), a < b, of region labels with points at most \a distance
 * apart. */
std::set<std::pair<std::uint32_t, std::uint32_t>>
adjacentRegions (const TabletopScene& scene, float distance)
{
  const Cloud& cloud = *scene.cloud;
  std::vector<std::size_t> order (cloud.size());
  std::iota (order.begin(), order.end(), 0);
  std::sort (order.begin(), order.end(), [&] (std::size_t a, std::size_t b) {
    return cloud[a].x < cloud[b].x;
  });
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1;
         j < order.size() && cloud[order[j]].x - cloud[order[i]].x <= distance;
         ++j) {
      const std::uint32_t a = scene.region_labels[order[i]];
      const std::uint32_t b = scene.region_labels[order[j]];
      if (a != b &&
          (cloud[order[i]].getVector3fMap() - cloud[order[j]].getVector3fMap())
                  .norm() <= distance)
        pairs.emplace (std::min (a, b), std::max (a, b));
    }
  return pairs;
}

} // namespace

TEST (TabletopScene, SameSeedGivesIdenticalScenesAndOtherSeedsDiffer)
{
  const TabletopScene a = tabletop (4, 7);
  const TabletopScene b = tabletop (4, 7);
  const TabletopScene c = tabletop (4, 8);
  EXPECT_TRUE (identical (*a.cloud, *b.cloud));
  EXPECT_FALSE (identical (*a.cloud, *c.cloud));
}

TEST (TabletopScene, LabelsAndCountsMatchTheGroundTruth)
{
  for (std::size_t k = 0; k <= pcl::tda::MAX_TABLETOP_OBJECTS; ++k) {
    SCOPED_TRACE ("objects " + std::to_string (k));
    const TabletopScene scene = tabletop (k, 100 + k);
    ASSERT_EQ (k, scene.objects.size());
    const auto groups = pointsByLabel (*scene.cloud);
    std::set<std::uint32_t> expected = {pcl::tda::TABLE_LABEL};
    for (std::size_t i = 0; i < k; ++i) {
      const TabletopObject& object = scene.objects[i];
      EXPECT_EQ (pcl::tda::FIRST_OBJECT_LABEL + i, object.label);
      expected.insert (object.label);
      ASSERT_EQ (1u, groups.count (object.label));
      EXPECT_EQ (object.num_points, groups.at (object.label).size());
      EXPECT_GE (object.num_points, 20u);
    }
    std::set<std::uint32_t> labels;
    for (const auto& group : groups)
      labels.insert (group.first);
    EXPECT_EQ (expected, labels);
    EXPECT_EQ (scene.num_table_points, groups.at (pcl::tda::TABLE_LABEL).size());
    EXPECT_GT (scene.num_table_points, 3000u);
    EXPECT_EQ (scene.cloud->size(), std::size_t (scene.cloud->width));
    EXPECT_TRUE (scene.cloud->is_dense);
  }
}

TEST (TabletopScene, ObjectsRestOnTheTableInsideItsEdges)
{
  TabletopParameters p;
  p.noise_sigma = 0.0f;
  p.num_objects = 6;
  for (std::uint64_t seed = 0; seed < 5; ++seed) {
    p.seed = seed;
    const TabletopScene scene = pcl::tda::generateTabletopScene (p);
    for (const TabletopObject& object : scene.objects)
      EXPECT_NEAR (0.5f * object.dimensions.z(), object.centre.z(), 1e-6);
    for (const auto& point : *scene.cloud) {
      ASSERT_LE (std::abs (point.x), 0.5f * p.table_width);
      ASSERT_LE (std::abs (point.y), 0.5f * p.table_depth);
      if (point.label == pcl::tda::TABLE_LABEL) {
        ASSERT_NEAR (0.0f, point.z, 1e-6);
        continue;
      }
      // Without noise every point is on its object, above the table.
      const TabletopObject& object =
          scene.objects[point.label - pcl::tda::FIRST_OBJECT_LABEL];
      ASSERT_GE (point.z, -1e-6);
      const Eigen::Vector3d local = toObjectFrame (object, point);
      const Eigen::Vector3d half = 0.5 * object.dimensions.cast<double>();
      ASSERT_TRUE ((local.array().abs() <= half.array() + 1e-5).all());
    }
  }
}

TEST (TabletopScene, NoisyObjectPointsStayAboveTheTable)
{
  for (std::uint64_t seed = 0; seed < 5; ++seed) {
    const TabletopScene scene = tabletop (5, seed, 0.003f);
    const float bound = scene.max_noise_displacement;
    EXPECT_GT (bound, 0.0f);
    std::vector<float> lowest (scene.objects.size(), 1.0f);
    for (const auto& point : *scene.cloud) {
      if (point.label == pcl::tda::TABLE_LABEL)
        ASSERT_LE (std::abs (point.z), bound + 1e-6f);
      else
        lowest[point.label - pcl::tda::FIRST_OBJECT_LABEL] =
            std::min (lowest[point.label - pcl::tda::FIRST_OBJECT_LABEL], point.z);
    }
    for (const float z : lowest)
      EXPECT_GE (z, -bound - 1e-6f);
  }
}

TEST (TabletopScene, PointsOfDifferentObjectsAreAtLeastTheGapApart)
{
  for (const float noise : {0.001f, 0.004f})
    for (std::uint64_t seed = 0; seed < 4; ++seed) {
      SCOPED_TRACE ("noise " + std::to_string (noise) + " seed " +
                    std::to_string (seed));
      TabletopParameters p;
      p.num_objects = pcl::tda::MAX_TABLETOP_OBJECTS;
      p.noise_sigma = noise;
      p.seed = seed;
      const TabletopScene scene = pcl::tda::generateTabletopScene (p);
      std::vector<std::size_t> objects;
      for (std::size_t i = 0; i < scene.cloud->size(); ++i)
        if ((*scene.cloud)[i].label != pcl::tda::TABLE_LABEL)
          objects.push_back (i);
      float closest = std::numeric_limits<float>::max();
      for (std::size_t a = 0; a < objects.size(); ++a)
        for (std::size_t b = a + 1; b < objects.size(); ++b) {
          const auto& pa = (*scene.cloud)[objects[a]];
          const auto& pb = (*scene.cloud)[objects[b]];
          if (pa.label != pb.label)
            closest =
                std::min (closest, (pa.getVector3fMap() - pb.getVector3fMap()).norm());
        }
      EXPECT_GE (closest, p.min_gap);
    }
}

TEST (TabletopScene, EachObjectHasItsOwnConsistentColour)
{
  TabletopParameters p;
  p.num_objects = pcl::tda::MAX_TABLETOP_OBJECTS;
  p.seed = 3;
  const TabletopScene scene = pcl::tda::generateTabletopScene (p);
  const int spread = static_cast<int> (std::ceil (3.0f * p.colour_noise));
  std::set<std::array<int, 3>> colours = {
      {scene.table_r, scene.table_g, scene.table_b}};
  for (const TabletopObject& object : scene.objects)
    colours.insert ({object.r, object.g, object.b});
  EXPECT_EQ (scene.objects.size() + 1, colours.size());
  for (const auto& point : *scene.cloud) {
    std::array<int, 3> base = {scene.table_r, scene.table_g, scene.table_b};
    if (point.label != pcl::tda::TABLE_LABEL) {
      const TabletopObject& object =
          scene.objects[point.label - pcl::tda::FIRST_OBJECT_LABEL];
      base = {object.r, object.g, object.b};
    }
    ASSERT_LE (std::abs (point.r - base[0]), spread);
    ASSERT_LE (std::abs (point.g - base[1]), spread);
    ASSERT_LE (std::abs (point.b - base[2]), spread);
  }
}

TEST (TabletopScene, CameraSeesOnlyFrontFacesUnlessAskedForAll)
{
  TabletopParameters p;
  p.noise_sigma = 0.0f;
  p.num_objects = 6;
  p.seed = 11;
  const Eigen::Vector3d camera = p.camera_position.cast<double>();
  const auto backFacing = [&] (const TabletopScene& scene) {
    std::size_t count = 0;
    for (const auto& point : *scene.cloud)
      if (point.label != pcl::tda::TABLE_LABEL) {
        const TabletopObject& object =
            scene.objects[point.label - pcl::tda::FIRST_OBJECT_LABEL];
        const Eigen::Vector3d position = point.getVector3fMap().cast<double>();
        if (outwardNormal (object, point).dot (camera - position) < -1e-6)
          ++count;
      }
    return count;
  };
  const TabletopScene visible = pcl::tda::generateTabletopScene (p);
  EXPECT_EQ (0u, backFacing (visible));
  EXPECT_TRUE (p.camera_position == visible.cloud->sensor_origin_.head<3>());
  p.visible_only = false;
  const TabletopScene all = pcl::tda::generateTabletopScene (p);
  EXPECT_GT (backFacing (all), 100u);
  EXPECT_GT (all.cloud->size(), visible.cloud->size());
}

TEST (TabletopScene, NoPointIsHiddenBehindAnObjectUnlessAskedForAll)
{
  TabletopParameters p;
  p.noise_sigma = 0.0f;
  p.num_objects = 6;
  p.seed = 2;
  const Eigen::Vector3d camera = p.camera_position.cast<double>();
  EXPECT_EQ (0u, hiddenPoints (pcl::tda::generateTabletopScene (p), camera));
  p.visible_only = false;
  // The table behind the objects.
  EXPECT_GT (hiddenPoints (pcl::tda::generateTabletopScene (p), camera), 100u);
}

TEST (TabletopScene, DropoutRemovesThatFractionOfThePoints)
{
  TabletopParameters p;
  p.seed = 4;
  const std::size_t full = pcl::tda::generateTabletopScene (p).cloud->size();
  p.dropout = 0.5f;
  const std::size_t half = pcl::tda::generateTabletopScene (p).cloud->size();
  EXPECT_NEAR (0.5, static_cast<double> (half) / full, 0.03);
}

TEST (TabletopScene, EuclideanClusteringAfterPlaneRemovalRecoversTheObjects)
{
  for (std::uint64_t seed = 0; seed < 3; ++seed) {
    SCOPED_TRACE ("seed " + std::to_string (seed));
    TabletopParameters p;
    p.num_objects = 5;
    p.seed = seed;
    const TabletopScene scene = pcl::tda::generateTabletopScene (p);
    // Plane removal: drop everything within the noise band of z = 0.
    const float band = scene.max_noise_displacement + 0.005f;
    std::vector<Eigen::Vector3f> points;
    std::vector<std::uint32_t> labels;
    for (const auto& point : *scene.cloud)
      if (std::abs (point.z) > band) {
        points.push_back (point.getVector3fMap());
        labels.push_back (point.label);
      }
    const std::vector<std::size_t> roots =
        euclideanClusters (points, 3.0f * p.point_spacing);
    std::map<std::size_t, std::set<std::uint32_t>> labels_of_cluster;
    for (std::size_t i = 0; i < points.size(); ++i)
      labels_of_cluster[roots[i]].insert (labels[i]);
    ASSERT_EQ (p.num_objects, labels_of_cluster.size());
    std::set<std::uint32_t> found;
    for (const auto& cluster : labels_of_cluster) {
      ASSERT_EQ (1u, cluster.second.size());
      found.insert (*cluster.second.begin());
    }
    EXPECT_EQ (p.num_objects, found.size());
    EXPECT_EQ (0u, found.count (pcl::tda::TABLE_LABEL));
  }
}

TEST (TabletopScene, BadParametersThrow)
{
  const auto throws = [] (const std::function<void (TabletopParameters&)>& change) {
    TabletopParameters p;
    change (p);
    EXPECT_THROW (pcl::tda::generateTabletopScene (p), pcl::BadArgumentException);
  };
  throws ([] (TabletopParameters& p) {
    p.num_objects = pcl::tda::MAX_TABLETOP_OBJECTS + 1;
  });
  throws ([] (TabletopParameters& p) { p.point_spacing = 0.0f; });
  throws ([] (TabletopParameters& p) { p.point_spacing = 0.05f; });
  throws ([] (TabletopParameters& p) { p.point_spacing = 1e-5f; });
  throws ([] (TabletopParameters& p) { p.noise_sigma = -0.001f; });
  throws ([] (TabletopParameters& p) { p.colour_noise = -1.0f; });
  throws ([] (TabletopParameters& p) { p.dropout = 1.0f; });
  throws ([] (TabletopParameters& p) { p.min_gap = 0.0f; });
  throws ([] (TabletopParameters& p) { p.table_width = -1.0f; });
  throws ([] (TabletopParameters& p) { p.camera_position.z() = 0.1f; });
  throws ([] (TabletopParameters& p) {
    p.num_objects = pcl::tda::MAX_TABLETOP_OBJECTS;
    p.table_width = 0.4f;
    p.table_depth = 0.3f;
  });
}

TEST (TabletopScene, UnpaintedScenesAreThoseOfTheGeneratorBeforeColourRegions)
{
  // Fingerprint of this scene made by the generator before colour regions existed.
  TabletopParameters p;
  p.num_objects = 6;
  p.noise_sigma = 0.002f;
  p.seed = 3;
  const TabletopScene scene = pcl::tda::generateTabletopScene (p);
  EXPECT_EQ (0xd8d98c5fcd1e8d58ULL, fingerprint (*scene.cloud));
  // Every object is one region, labelled as in the cloud.
  ASSERT_EQ (scene.cloud->size(), scene.region_labels.size());
  for (std::size_t i = 0; i < scene.cloud->size(); ++i)
    ASSERT_EQ ((*scene.cloud)[i].label, scene.region_labels[i]);
  ASSERT_EQ (scene.objects.size() + 1, scene.regions.size());
  EXPECT_EQ (pcl::tda::TABLE_LABEL, scene.regions[0].object_label);
  EXPECT_EQ (scene.num_table_points, scene.regions[0].num_points);
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const TabletopColourRegion& region = scene.regions[k + 1];
    const TabletopObject& object = scene.objects[k];
    EXPECT_EQ (object.label, region.label);
    EXPECT_EQ (object.label, region.object_label);
    EXPECT_EQ (0u, region.part);
    EXPECT_EQ (colourOf (object), colourOf (region));
    EXPECT_EQ (object.num_points, region.num_points);
  }
  EXPECT_TRUE (scene.similar_regions.empty());
  EXPECT_TRUE (identical (*scene.cloud, *pcl::tda::regionLabelledCloud (scene)));
}

TEST (TabletopScene, NoisePresetsSetTheDepthAndColourNoise)
{
  TabletopParameters p;
  p.setNoise (pcl::tda::TABLETOP_NO_NOISE);
  EXPECT_EQ (0.0f, p.noise_sigma);
  EXPECT_EQ (0.0f, p.colour_noise);
  p.setNoise (pcl::tda::TABLETOP_MODERATE_NOISE);
  EXPECT_EQ (0.0005f, p.noise_sigma);
  EXPECT_EQ (4.0f, p.colour_noise);
  p.setNoise (pcl::tda::TABLETOP_HEAVY_NOISE);
  EXPECT_EQ (0.0015f, p.noise_sigma);
  EXPECT_EQ (8.0f, p.colour_noise);
  EXPECT_STREQ ("heavy", pcl::tda::TABLETOP_HEAVY_NOISE.name);
}

TEST (TabletopScene, ColourRegionsAreDeterministicAndChangeOnlyTheColours)
{
  const TabletopScene a = regionScene (6, 21, pcl::tda::TABLETOP_MODERATE_NOISE);
  const TabletopScene b = regionScene (6, 21, pcl::tda::TABLETOP_MODERATE_NOISE);
  const TabletopScene c = regionScene (6, 22, pcl::tda::TABLETOP_MODERATE_NOISE);
  EXPECT_TRUE (identical (*a.cloud, *b.cloud));
  EXPECT_EQ (a.region_labels, b.region_labels);
  EXPECT_EQ (a.similar_regions, b.similar_regions);
  EXPECT_FALSE (identical (*a.cloud, *c.cloud));
  // The same scene unpainted: the same points, object labels and depth noise.
  TabletopParameters p;
  p.num_objects = 6;
  p.seed = 21;
  p.setNoise (pcl::tda::TABLETOP_MODERATE_NOISE);
  const TabletopScene plain = pcl::tda::generateTabletopScene (p);
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

TEST (TabletopScene, ColourRegionLabelsAreContiguousAndCarryTheirColours)
{
  for (std::uint64_t seed = 0; seed < 6; ++seed) {
    SCOPED_TRACE ("seed " + std::to_string (seed));
    const TabletopScene scene = regionScene (pcl::tda::MAX_TABLETOP_OBJECTS, seed);
    ASSERT_EQ (scene.cloud->size(), scene.region_labels.size());
    const std::size_t count = scene.regions.size();
    ASSERT_GT (count, scene.objects.size() + 1);
    for (std::size_t i = 0; i < count; ++i)
      ASSERT_EQ (i + 1, scene.regions[i].label);
    const TabletopColourRegion& table = scene.regions[0];
    EXPECT_EQ (pcl::tda::TABLE_LABEL, table.label);
    EXPECT_EQ (pcl::tda::TABLE_LABEL, table.object_label);
    EXPECT_EQ ((std::array<int, 3>{scene.table_r, scene.table_g, scene.table_b}),
               colourOf (table));
    // Without noise every point has its region's colour; each region is on one
    // object, and each object has several regions with distinct parts.
    std::vector<std::size_t> points (count, 0);
    std::map<std::uint32_t, std::set<std::uint32_t>> parts_of_object;
    for (std::size_t i = 0; i < scene.cloud->size(); ++i) {
      const std::uint32_t label = scene.region_labels[i];
      ASSERT_GE (label, 1u);
      ASSERT_LE (label, count);
      const TabletopColourRegion& region = scene.regions[label - 1];
      const auto& point = (*scene.cloud)[i];
      ASSERT_EQ (region.object_label, point.label);
      ASSERT_EQ (colourOf (region), colourOf (point));
      ++points[label - 1];
    }
    for (std::size_t i = 0; i < count; ++i) {
      EXPECT_GT (points[i], 0u);
      EXPECT_EQ (points[i], scene.regions[i].num_points);
      const TabletopColourRegion& region = scene.regions[i];
      if (i > 0) {
        EXPECT_TRUE (parts_of_object[region.object_label].insert (region.part).second);
      }
    }
    for (const TabletopObject& object : scene.objects) {
      const std::set<std::uint32_t>& parts = parts_of_object[object.label];
      EXPECT_GE (parts.size(), 2u);
      const std::uint32_t most = object.type == PrimitiveType::BOX        ? 4
                                 : object.type == PrimitiveType::CYLINDER ? 3
                                                                          : 2;
      EXPECT_LE (*parts.rbegin(), most);
    }
    // The cloud labelled by region.
    const Cloud::Ptr labelled = pcl::tda::regionLabelledCloud (scene);
    ASSERT_EQ (scene.cloud->size(), labelled->size());
    for (std::size_t i = 0; i < labelled->size(); ++i) {
      ASSERT_EQ (scene.region_labels[i], (*labelled)[i].label);
      ASSERT_EQ ((*scene.cloud)[i].rgba, (*labelled)[i].rgba);
    }
  }
}

TEST (TabletopScene, PaintedPartsFollowTheGeometry)
{
  for (std::uint64_t seed = 0; seed < 6; ++seed) {
    SCOPED_TRACE ("seed " + std::to_string (seed));
    const TabletopScene scene = regionScene (pcl::tda::MAX_TABLETOP_OBJECTS, seed);
    std::map<std::uint32_t, std::vector<double>> heights; // cylinder band heights
    std::map<std::uint32_t, std::uint32_t> last_part;     // of each object
    for (const TabletopColourRegion& region : scene.regions)
      last_part[region.object_label] =
          std::max (last_part[region.object_label], region.part);
    for (std::size_t i = 0; i < scene.cloud->size(); ++i) {
      const auto& point = (*scene.cloud)[i];
      if (point.label == pcl::tda::TABLE_LABEL)
        continue;
      const TabletopObject& object =
          scene.objects[point.label - pcl::tda::FIRST_OBJECT_LABEL];
      const TabletopColourRegion& region = scene.regions[scene.region_labels[i] - 1];
      const Eigen::Vector3d local = toObjectFrame (object, point);
      const Eigen::Vector3d half = 0.5 * object.dimensions.cast<double>();
      if (object.type == PrimitiveType::BOX) {
        // Top, -y, +y, -x, +x in the box's frame.
        const std::array<std::pair<int, double>, 5> faces = {{{2, half.z()},
                                                              {1, -half.y()},
                                                              {1, half.y()},
                                                              {0, -half.x()},
                                                              {0, half.x()}}};
        ASSERT_LT (region.part, faces.size());
        const auto& [axis, side] = faces[region.part];
        ASSERT_NEAR (side, local[axis], 1e-5);
      }
      else if (object.type == PrimitiveType::CYLINDER) {
        // The top part is the cap, the others are bands of the side.
        if (region.part == last_part[object.label]) {
          ASSERT_NEAR (half.z(), local.z(), 1e-5);
        }
        else {
          ASSERT_NEAR (half.x(), local.head<2>().norm(), 1e-5);
          heights[scene.region_labels[i]].push_back (point.z);
        }
      }
    }
    // The bands of a cylinder are stacked: each band is above the one below.
    for (const auto& [label, band] : heights) {
      const TabletopColourRegion& region = scene.regions[label - 1];
      if (region.part == 0)
        continue;
      const auto below = std::find_if (
          scene.regions.begin(), scene.regions.end(), [&] (const auto& other) {
            return other.object_label == region.object_label &&
                   other.part == region.part - 1;
          });
      if (below == scene.regions.end() || heights.count (below->label) == 0)
        continue;
      EXPECT_GE (*std::min_element (band.begin(), band.end()),
                 *std::max_element (heights[below->label].begin(),
                                    heights[below->label].end()));
    }
  }
}

TEST (TabletopScene, AdjacentRegionsHaveTheDocumentedColourDifferences)
{
  std::size_t similar = 0, similar_adjacent = 0, objects = 0, objects_with_similar = 0;
  for (std::uint64_t seed = 0; seed < 8; ++seed) {
    SCOPED_TRACE ("seed " + std::to_string (seed));
    const TabletopScene scene = regionScene (6, seed, pcl::tda::TABLETOP_HEAVY_NOISE);
    const TabletopParameters defaults;
    const std::set<std::pair<std::uint32_t, std::uint32_t>> similar_pairs (
        scene.similar_regions.begin(), scene.similar_regions.end());
    EXPECT_EQ (similar_pairs.size(), scene.similar_regions.size());
    std::set<std::uint32_t> with_similar;
    for (const auto& [a, b] : scene.similar_regions) {
      ASSERT_LT (a, b);
      ASSERT_LE (b, scene.regions.size());
      const TabletopColourRegion& ra = scene.regions[a - 1];
      const TabletopColourRegion& rb = scene.regions[b - 1];
      EXPECT_EQ (ra.object_label, rb.object_label);
      EXPECT_NE (pcl::tda::TABLE_LABEL, ra.object_label);
      const double difference = deltaE (ra, rb);
      EXPECT_GE (difference, pcl::tda::SIMILAR_REGION_MIN_DELTA_E);
      EXPECT_LE (difference, pcl::tda::SIMILAR_REGION_MAX_DELTA_E);
      with_similar.insert (ra.object_label);
    }
    similar += scene.similar_regions.size();
    objects += scene.objects.size();
    objects_with_similar += with_similar.size();
    // Adjacent regions: points within twice the point spacing.
    for (const auto& [a, b] : adjacentRegions (scene, 2.0f * defaults.point_spacing)) {
      const TabletopColourRegion& ra = scene.regions[a - 1];
      const TabletopColourRegion& rb = scene.regions[b - 1];
      const double difference = deltaE (ra, rb);
      SCOPED_TRACE ("regions " + std::to_string (a) + " and " + std::to_string (b));
      EXPECT_GE (difference, pcl::tda::SIMILAR_REGION_MIN_DELTA_E);
      if (similar_pairs.count ({a, b}) != 0) {
        ++similar_adjacent;
      }
      else if (ra.object_label == rb.object_label ||
               ra.object_label == pcl::tda::TABLE_LABEL) {
        EXPECT_GE (difference, pcl::tda::DISTINCT_REGION_MIN_DELTA_E);
      }
    }
    // Regions of different objects differ too.
    for (const TabletopColourRegion& ra : scene.regions)
      for (const TabletopColourRegion& rb : scene.regions)
        if (ra.label < rb.label && ra.object_label != rb.object_label) {
          EXPECT_GE (deltaE (ra, rb), pcl::tda::SIMILAR_REGION_MIN_DELTA_E);
        }
    // The colour noise stays within 3 standard deviations (24 levels).
    for (std::size_t i = 0; i < scene.cloud->size(); ++i) {
      const std::array<int, 3> noisy = colourOf ((*scene.cloud)[i]);
      const std::array<int, 3> base =
          colourOf (scene.regions[scene.region_labels[i] - 1]);
      for (std::size_t c = 0; c < 3; ++c)
        ASSERT_LE (std::abs (noisy[c] - base[c]), 24);
    }
  }
  EXPECT_GE (similar, objects * 3 / 4);
  EXPECT_GE (objects_with_similar, objects * 9 / 10);
  EXPECT_GE (similar_adjacent, similar * 9 / 10);
}
