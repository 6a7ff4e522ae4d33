#include <pcl/io/pcd_io.h>
#include <pcl/tda/apps/synthetic_scenes.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <regex>
#include <set>
#include <string>
#include <vector>

using pcl::tda::CircleParameters;
using pcl::tda::PrimitiveType;
using pcl::tda::SphereParameters;
using pcl::tda::SyntheticShape;
using pcl::tda::TabletopObject;
using pcl::tda::TabletopParameters;
using pcl::tda::TabletopScene;
using pcl::tda::TorusParameters;
using Cloud = pcl::PointCloud<pcl::PointXYZRGBL>;

namespace {

/** Bitwise equality of coordinates, colour and label of every point. */
bool
identical (const Cloud& a, const Cloud& b)
{
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp (a[i].data, b[i].data, 3 * sizeof (float)) != 0 ||
        a[i].rgba != b[i].rgba || a[i].label != b[i].label)
      return false;
  return true;
}

double
distanceToCircle (const pcl::PointXYZRGBL& p, double radius)
{
  return std::hypot (std::hypot (p.x, p.y) - radius, p.z);
}

double
distanceToTorus (const pcl::PointXYZRGBL& p, double major, double minor)
{
  return std::abs (std::hypot (std::hypot (p.x, p.y) - major, p.z) - minor);
}

double
distanceToSphere (const pcl::PointXYZRGBL& p, double radius)
{
  return std::abs (p.getVector3fMap().cast<double>().norm() - radius);
}

/** Largest and mean distance of the cloud to a surface. */
std::pair<double, double>
distanceStatistics (const Cloud& cloud,
                    const std::function<double (const pcl::PointXYZRGBL&)>& distance)
{
  double largest = 0.0, sum = 0.0;
  for (const auto& p : cloud) {
    const double d = distance (p);
    largest = std::max (largest, d);
    sum += d;
  }
  return {largest, sum / cloud.size()};
}

/** One of each shape with its distance function, for parameterised checks. */
struct ShapeCase {
  std::string name;
  std::function<SyntheticShape (float noise, std::uint64_t seed)> generate;
  std::function<double (const pcl::PointXYZRGBL&)> distance;
  std::size_t num_points;
};

std::vector<ShapeCase>
shapeCases ()
{
  return {{"circle",
           [] (float noise, std::uint64_t seed) {
             CircleParameters p;
             p.noise_sigma = noise;
             p.seed = seed;
             return pcl::tda::generateCircle (p);
           },
           [] (const pcl::PointXYZRGBL& p) {
             return distanceToCircle (p, CircleParameters().radius);
           },
           CircleParameters().num_points},
          {"torus",
           [] (float noise, std::uint64_t seed) {
             TorusParameters p;
             p.noise_sigma = noise;
             p.seed = seed;
             return pcl::tda::generateTorus (p);
           },
           [] (const pcl::PointXYZRGBL& p) {
             return distanceToTorus (
                 p, TorusParameters().major_radius, TorusParameters().minor_radius);
           },
           TorusParameters().num_points},
          {"sphere",
           [] (float noise, std::uint64_t seed) {
             SphereParameters p;
             p.noise_sigma = noise;
             p.seed = seed;
             return pcl::tda::generateSphere (p);
           },
           [] (const pcl::PointXYZRGBL& p) {
             return distanceToSphere (p, SphereParameters().radius);
           },
           SphereParameters().num_points}};
}

/** A persistence interval as printed by Ripser; death is infinity for [b, ). */
struct Interval {
  int dim;
  double birth, death;
};

/** Runs Ripser on the cloud up to threshold and returns its intervals. */
std::vector<Interval>
runRipser (const Cloud& cloud, double threshold, const std::string& folder)
{
  const std::string input = folder + "/points.txt";
  const std::string output = folder + "/ripser.txt";
  {
    std::ofstream file (input);
    file.precision (9);
    for (const auto& p : cloud)
      file << p.x << ' ' << p.y << ' ' << p.z << '\n';
  }
  const std::string command = std::string (RIPSER_EXECUTABLE) +
                              " --format point-cloud --dim 1 --threshold " +
                              std::to_string (threshold) + " " + input + " > " + output;
  EXPECT_EQ (0, std::system (command.c_str())) << command;
  std::ifstream file (output);
  std::vector<Interval> intervals;
  const std::regex header (R"(persistence intervals in dim (\d+):)");
  const std::regex interval (R"(\s*\[([^,]+),\s*([^)]*)\))");
  int dim = -1;
  std::smatch match;
  for (std::string line; std::getline (file, line);) {
    if (std::regex_match (line, match, header))
      dim = std::stoi (match[1]);
    else if (dim >= 0 && std::regex_match (line, match, interval)) {
      const std::string death = match[2];
      intervals.push_back ({dim,
                            std::stod (match[1]),
                            death.find_first_not_of (' ') == std::string::npos
                                ? std::numeric_limits<double>::infinity()
                                : std::stod (death)});
    }
  }
  return intervals;
}

int
bettiAt (const std::vector<Interval>& intervals, int dim, double r)
{
  return static_cast<int> (
      std::count_if (intervals.begin(), intervals.end(), [&] (const Interval& i) {
        return i.dim == dim && i.birth <= r && r < i.death;
      }));
}

/** A fresh folder under the system temporary folder, removed at the end. */
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

int
runTool (const std::string& arguments)
{
  const std::string command = std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_generate " +
                              arguments + " >/dev/null 2>&1";
  const int status = std::system (command.c_str());
  return WIFEXITED (status) ? WEXITSTATUS (status) : -1;
}

} // namespace

TEST (SyntheticShapes, SameSeedGivesIdenticalCloudsAndOtherSeedsDiffer)
{
  for (const ShapeCase& shape : shapeCases()) {
    SCOPED_TRACE (shape.name);
    const SyntheticShape a = shape.generate (0.01f, 42);
    const SyntheticShape b = shape.generate (0.01f, 42);
    const SyntheticShape c = shape.generate (0.01f, 43);
    EXPECT_TRUE (identical (*a.cloud, *b.cloud));
    EXPECT_EQ (a.suggested_radius, b.suggested_radius);
    EXPECT_FALSE (identical (*a.cloud, *c.cloud));
  }
}

TEST (SyntheticShapes, ExactPointCountsAndGroundTruth)
{
  const std::map<std::string, std::pair<int, int>> betti = {
      {"circle", {1, 1}}, {"torus", {1, 2}}, {"sphere", {1, 0}}};
  for (const ShapeCase& shape : shapeCases()) {
    SCOPED_TRACE (shape.name);
    const SyntheticShape s = shape.generate (0.01f, 1);
    EXPECT_EQ (shape.num_points, s.cloud->size());
    EXPECT_EQ (s.cloud->size(), std::size_t (s.cloud->width) * s.cloud->height);
    EXPECT_EQ (betti.at (shape.name).first, s.beta0);
    EXPECT_EQ (betti.at (shape.name).second, s.beta1);
    EXPECT_GT (s.suggested_radius, 0.0f);
    for (const auto& p : *s.cloud)
      ASSERT_EQ (pcl::tda::SHAPE_LABEL, p.label);
  }
  CircleParameters circle;
  circle.num_points = 777;
  EXPECT_EQ (777u, pcl::tda::generateCircle (circle).cloud->size());
  TorusParameters torus;
  torus.num_points = 3001;
  EXPECT_EQ (3001u, pcl::tda::generateTorus (torus).cloud->size());
  SphereParameters sphere;
  sphere.num_points = 1201;
  EXPECT_EQ (1201u, pcl::tda::generateSphere (sphere).cloud->size());
}

TEST (SyntheticShapes, PointsLieOnTheSurfaceWithoutNoise)
{
  for (const ShapeCase& shape : shapeCases()) {
    SCOPED_TRACE (shape.name);
    const SyntheticShape s = shape.generate (0.0f, 5);
    EXPECT_LE (distanceStatistics (*s.cloud, shape.distance).first, 1e-5);
  }
}

TEST (SyntheticShapes, NoisyPointsStayWithinFourSigma)
{
  const float sigma = 0.01f;
  for (const ShapeCase& shape : shapeCases()) {
    SCOPED_TRACE (shape.name);
    const auto [largest, mean] =
        distanceStatistics (*shape.generate (sigma, 9).cloud, shape.distance);
    EXPECT_LE (largest, 4.0 * sigma + 1e-5);
    EXPECT_GT (largest, 2.0 * sigma); // the noise is really there
    EXPECT_GT (mean, 0.4 * sigma);
    EXPECT_LT (mean, 2.0 * sigma);
  }
}

TEST (SyntheticShapes, SuggestedRadiusScalesWithSpacingAndNoise)
{
  CircleParameters sparse, dense, noisy;
  sparse.num_points = 500;
  dense.num_points = 2000;
  noisy.noise_sigma = 0.03f;
  const float r_sparse = pcl::tda::generateCircle (sparse).suggested_radius;
  const float r_dense = pcl::tda::generateCircle (dense).suggested_radius;
  const float r_default =
      pcl::tda::generateCircle (CircleParameters()).suggested_radius;
  const float r_noisy = pcl::tda::generateCircle (noisy).suggested_radius;
  EXPECT_LT (r_dense, r_default);
  EXPECT_LT (r_default, r_sparse);
  EXPECT_LT (r_default, r_noisy);
  EXPECT_LT (r_noisy, 0.5f * CircleParameters().radius);
}

TEST (SyntheticShapes, RipserFindsTheBettiNumbersAroundTheSuggestedRadius)
{
  if (std::string (RIPSER_EXECUTABLE).empty() ||
      !std::filesystem::exists (RIPSER_EXECUTABLE))
    GTEST_SKIP() << "ripser not found (install the Debian package ripser)";
  const TemporaryFolder folder;
  for (const ShapeCase& shape : shapeCases())
    for (std::uint64_t seed : {0u, 1u, 2u}) {
      SCOPED_TRACE (shape.name + " seed " + std::to_string (seed));
      const SyntheticShape s = shape.generate (0.01f, seed);
      const double r = s.suggested_radius;
      const std::vector<Interval> intervals =
          runRipser (*s.cloud, 1.3 * r, folder.path());
      ASSERT_FALSE (intervals.empty());
      EXPECT_EQ (s.beta0, bettiAt (intervals, 0, r));
      EXPECT_EQ (s.beta1, bettiAt (intervals, 1, r));
      // Robust: right on the whole range [0.75 r, 1.3 r), checked at every event.
      std::vector<double> radii = {0.75 * r};
      for (const Interval& i : intervals)
        for (const double v : {i.birth, i.death})
          if (v > 0.75 * r && v < 1.3 * r)
            radii.push_back (v);
      for (const double x : radii) {
        ASSERT_EQ (s.beta0, bettiAt (intervals, 0, x)) << "at radius " << x;
        ASSERT_EQ (s.beta1, bettiAt (intervals, 1, x)) << "at radius " << x;
      }
    }
}

TEST (SyntheticShapes, BadParametersThrow)
{
  CircleParameters circle;
  circle.num_points = 0;
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);
  circle = CircleParameters();
  circle.noise_sigma = -0.1f;
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);
  circle.noise_sigma = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);
  circle = CircleParameters();
  circle.radius = 0.0f;
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);
  circle = CircleParameters();
  circle.num_points = 20; // far too sparse for its Betti numbers
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);
  circle = CircleParameters();
  circle.noise_sigma = 0.2f; // noise swallows the hole
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);

  TorusParameters torus;
  torus.minor_radius = torus.major_radius;
  EXPECT_THROW (pcl::tda::generateTorus (torus), pcl::BadArgumentException);
  torus = TorusParameters();
  torus.minor_radius = -0.2f;
  EXPECT_THROW (pcl::tda::generateTorus (torus), pcl::BadArgumentException);
  torus = TorusParameters();
  torus.num_points = 300;
  EXPECT_THROW (pcl::tda::generateTorus (torus), pcl::BadArgumentException);

  SphereParameters sphere;
  sphere.radius = std::numeric_limits<float>::infinity();
  EXPECT_THROW (pcl::tda::generateSphere (sphere), pcl::BadArgumentException);
  sphere = SphereParameters();
  sphere.num_points = 100;
  EXPECT_THROW (pcl::tda::generateSphere (sphere), pcl::BadArgumentException);
}

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

TEST (GenerateTool, WritesEveryKindAsLoadablePCD)
{
  const TemporaryFolder folder;
  const std::map<std::string, std::size_t> sizes = {
      {"circle", 800}, {"torus", 3000}, {"sphere", 1200}};
  for (const auto& [kind, size] : sizes) {
    SCOPED_TRACE (kind);
    const std::string file = folder.path() + "/" + kind + ".pcd";
    ASSERT_EQ (0,
               runTool (kind + " " + file + " -n " + std::to_string (size) +
                        " -noise 0.005 -seed 3"));
    Cloud cloud;
    ASSERT_EQ (0, pcl::io::loadPCDFile (file, cloud));
    EXPECT_EQ (size, cloud.size());
  }
  const std::string file = folder.path() + "/tabletop.pcd";
  ASSERT_EQ (0, runTool ("tabletop " + file + " -objects 3 -seed 5"));
  Cloud cloud;
  ASSERT_EQ (0, pcl::io::loadPCDFile (file, cloud));
  const TabletopScene scene = tabletop (3, 5);
  EXPECT_TRUE (identical (*scene.cloud, cloud));
  // No temporary files are left behind.
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator (folder.path()))
    names.insert (entry.path().filename().string());
  const std::set<std::string> expected = {
      "circle.pcd", "sphere.pcd", "tabletop.pcd", "torus.pcd"};
  EXPECT_EQ (expected, names);
}

TEST (GenerateTool, FailsOnBadArgumentsWithoutLeavingFiles)
{
  const TemporaryFolder folder;
  const std::string file = folder.path() + "/out.pcd";
  EXPECT_NE (0, runTool ("cube " + file));
  EXPECT_NE (0, runTool ("circle " + file + " -n 0"));
  EXPECT_NE (0, runTool ("circle " + file + " -n -5"));
  EXPECT_NE (0, runTool ("circle " + file + " -n many"));
  EXPECT_NE (0, runTool ("circle " + file + " -noise -0.1"));
  EXPECT_NE (0, runTool ("circle " + file + " -seed -1"));
  EXPECT_NE (0, runTool ("circle " + file + " -radius 2"));
  EXPECT_NE (0, runTool ("circle " + file + " -n"));
  EXPECT_NE (0, runTool ("tabletop " + file + " -objects 99"));
  EXPECT_NE (0, runTool ("circle"));
  EXPECT_FALSE (std::filesystem::exists (file));
  // Unwritable outputs: a path in a missing folder, and an existing folder.
  EXPECT_NE (0, runTool ("circle " + folder.path() + "/missing/out.pcd"));
  const std::string subfolder = folder.path() + "/taken";
  std::filesystem::create_directory (subfolder);
  EXPECT_NE (0, runTool ("sphere " + subfolder));
  EXPECT_TRUE (std::filesystem::is_directory (subfolder));
  // Nothing but the subfolder: no partial or temporary files.
  EXPECT_EQ (1,
             std::distance (std::filesystem::directory_iterator (folder.path()),
                            std::filesystem::directory_iterator()));
}
