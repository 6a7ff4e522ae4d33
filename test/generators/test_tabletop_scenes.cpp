// Tests of the tabletop scenes: determinism, labels and counts against the ground
// truth, geometry, gaps, colours, visibility, dropout and recoverability.

#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "generators/generator_test_utils.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>

using pcl::tda::PrimitiveType;
using pcl::tda::TabletopObject;
using pcl::tda::TabletopParameters;
using pcl::tda::TabletopScene;
using pcl::tda::test::identical;
using Cloud = pcl::PointCloud<pcl::PointXYZRGBL>;

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
