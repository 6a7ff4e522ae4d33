#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/tda/generators/object_views.h>
#include <pcl/tda/generators/parameter_checks.h>
#include <pcl/tda/generators/random_sampling.h>
#include <pcl/exceptions.h>

#include "depth_camera.h"
#include "object_categories.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pcl {
namespace tda {
namespace {

const char* const NAME = "renderObjectView";
const std::array<const char*, NUM_OBJECT_CATEGORIES> CATEGORY_NAMES = {"mug",
                                                                       "cup",
                                                                       "ring",
                                                                       "disc",
                                                                       "frame",
                                                                       "tile",
                                                                       "ball",
                                                                       "can",
                                                                       "box",
                                                                       "cone",
                                                                       "bowl",
                                                                       "bottle"};

/** Camera ranges accepted: the camera stays outside every object (whose bounding
 * spheres have radii below 0.2 m) and not straight above it (no roll defined). */
constexpr double LOWEST_DISTANCE = 0.3, FARTHEST_DISTANCE = 10.0;
constexpr double HIGHEST_ELEVATION_DEG = 89.0;
/** Camera poses drawn for a view before giving up. */
constexpr std::size_t MAX_POSE_DRAWS = 100;
/** Colours of the instances: hue, saturation and value drawn uniformly. */
constexpr double MIN_SATURATION = 0.35, MAX_SATURATION = 0.9;
constexpr double MIN_VALUE = 0.45, MAX_VALUE = 0.95;
/** Offset of the colour noise's seed from a view's seed. */
constexpr std::uint64_t COLOUR_NOISE_SEED_OFFSET = 0x94d049bb133111ebULL;
/** Offset of the perturbation's seed from a view's seed. */
constexpr std::uint64_t PERTURBATION_SEED_OFFSET = 0xbf58476d1ce4e5b9ULL;
/** The largest perturbation, in metres. */
constexpr float MAX_PERTURBATION = 0.1f;

/** SplitMix64's output function: a well-mixed 64-bit hash of \a x. */
std::uint64_t
splitMix64 (std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/** The seed of the draws of \a index under \a parent. */
std::uint64_t
childSeed (std::uint64_t parent, std::uint64_t index)
{
  return splitMix64 (splitMix64 (parent) + index);
}

/** The seed of an instance: its sizes, pose and colour are drawn from childSeed (.,
 * 0), its view v from childSeed (., v + 1). */
std::uint64_t
instanceSeed (std::uint64_t seed, ObjectCategory category, std::size_t instance)
{
  return childSeed (childSeed (seed, static_cast<std::uint64_t> (category)), instance);
}

/** The colour of hue \a hue (degrees), saturation and value (0-1) in 0-255. */
std::array<std::uint8_t, 3>
hsvToRgb (double hue, double saturation, double value)
{
  const double chroma = value * saturation;
  const double sector = hue / 60.0;
  const double x = chroma * (1.0 - std::abs (std::fmod (sector, 2.0) - 1.0));
  const std::array<std::array<double, 3>, 6> sectors = {{{chroma, x, 0.0},
                                                         {x, chroma, 0.0},
                                                         {0.0, chroma, x},
                                                         {0.0, x, chroma},
                                                         {x, 0.0, chroma},
                                                         {chroma, 0.0, x}}};
  const auto& rgb =
      sectors[std::min<std::size_t> (static_cast<std::size_t> (sector), 5)];
  std::array<std::uint8_t, 3> colour;
  for (std::size_t c = 0; c < 3; ++c)
    colour[c] = static_cast<std::uint8_t> (
        std::clamp (std::lround (255.0 * (rgb[c] + value - chroma)), 0L, 255L));
  return colour;
}

/** Checks the indices of a view (or of an instance, \a view 0) against the data set
 * of \a parameters. */
void
checkIndices (const ObjectViewParameters& parameters,
              ObjectCategory category,
              std::size_t instance,
              std::size_t view)
{
  checkObjectViewParameters (parameters);
  const auto& categories = parameters.categories;
  const std::size_t index = static_cast<std::size_t> (category);
  checkParameter (index < NUM_OBJECT_CATEGORIES &&
                      std::find (categories.begin(), categories.end(), category) !=
                          categories.end(),
                  NAME,
                  "category ",
                  index < NUM_OBJECT_CATEGORIES ? CATEGORY_NAMES[index] : "(invalid)",
                  " is not one of the data set's categories");
  checkParameter (instance < parameters.instances,
                  NAME,
                  "instance ",
                  instance,
                  " is out of range (the data set has ",
                  parameters.instances,
                  " instances per category)");
  checkParameter (view < parameters.views,
                  NAME,
                  "view ",
                  view,
                  " is out of range (the data set has ",
                  parameters.views,
                  " views per instance)");
}

/** An object instance: its solid and its ground truth. */
struct DrawnInstance {
  ObjectSolid solid;
  ObjectInstance object;
};

/** Draws an instance's solid, then its pose and colour (indices checked). */
DrawnInstance
drawInstance (const ObjectViewParameters& parameters,
              ObjectCategory category,
              std::size_t instance)
{
  PortableRandom random (
      childSeed (instanceSeed (parameters.seed, category, instance), 0));
  DrawnInstance drawn{ObjectSolid (category, random), ObjectInstance()};
  const ObjectSolid& solid = drawn.solid;
  ObjectInstance& object = drawn.object;
  object.category = category;
  object.instance = instance;
  object.dimensions = solid.dimensions().cast<float>();
  object.hole_radius = static_cast<float> (solid.holeRadius());
  object.genus = solid.genus();
  const double yaw = random.uniform (0.0, 2.0 * M_PI);
  const double tilt =
      ObjectSolid::tilted (category) ? random.uniform (0.0, 0.5 * M_PI) : 0.0;
  object.yaw = static_cast<float> (yaw);
  object.tilt = static_cast<float> (tilt);
  object.pose.linear() = (Eigen::AngleAxisd (yaw, Eigen::Vector3d::UnitZ()) *
                          Eigen::AngleAxisd (tilt, Eigen::Vector3d::UnitX()))
                             .toRotationMatrix()
                             .cast<float>();
  const double hue = random.uniform (0.0, 360.0);
  const double saturation = random.uniform (MIN_SATURATION, MAX_SATURATION);
  const double value = random.uniform (MIN_VALUE, MAX_VALUE);
  const std::array<std::uint8_t, 3> colour = hsvToRgb (hue, saturation, value);
  object.r = colour[0];
  object.g = colour[1];
  object.b = colour[2];
  return drawn;
}

} // namespace

std::vector<ObjectCategory>
allObjectCategories ()
{
  std::vector<ObjectCategory> categories;
  for (std::size_t k = 0; k < NUM_OBJECT_CATEGORIES; ++k)
    categories.push_back (static_cast<ObjectCategory> (k));
  return categories;
}

std::string
objectCategoryName (ObjectCategory category)
{
  const std::size_t index = static_cast<std::size_t> (category);
  return index < NUM_OBJECT_CATEGORIES ? CATEGORY_NAMES[index] : "";
}

std::vector<std::string>
objectCategoryNames ()
{
  return {CATEGORY_NAMES.begin(), CATEGORY_NAMES.end()};
}

bool
parseObjectCategory (const std::string& name, ObjectCategory& category)
{
  for (std::size_t k = 0; k < NUM_OBJECT_CATEGORIES; ++k)
    if (name == CATEGORY_NAMES[k]) {
      category = static_cast<ObjectCategory> (k);
      return true;
    }
  return false;
}

void
checkObjectViewParameters (const ObjectViewParameters& p)
{
  checkParameter (!p.categories.empty(), NAME, "the list of categories is empty");
  for (std::size_t i = 0; i < p.categories.size(); ++i) {
    const std::size_t index = static_cast<std::size_t> (p.categories[i]);
    checkParameter (index < NUM_OBJECT_CATEGORIES,
                    NAME,
                    "category ",
                    index,
                    " is not an ObjectCategory");
    checkParameter (std::count (p.categories.begin(),
                                p.categories.begin() + i,
                                p.categories[i]) == 0,
                    NAME,
                    "category ",
                    CATEGORY_NAMES[index],
                    " is listed twice");
  }
  checkParameter (p.instances >= 1, NAME, "the number of instances must be >= 1");
  checkParameter (p.views >= 1, NAME, "the number of views must be >= 1");
  checkNonNegative (p.noise_multiplier, NAME, "noise multiplier");
  checkNonNegative (p.colour_noise, NAME, "colour noise");
  checkNonNegative (p.perturbation, NAME, "perturbation");
  checkParameter (p.perturbation <= MAX_PERTURBATION,
                  NAME,
                  "the perturbation must be at most ",
                  MAX_PERTURBATION,
                  " m, not ",
                  p.perturbation);
  checkParameter (std::isfinite (p.min_distance) && p.min_distance >= LOWEST_DISTANCE,
                  NAME,
                  "the minimum distance must be at least ",
                  LOWEST_DISTANCE,
                  " m, not ",
                  p.min_distance);
  checkParameter (std::isfinite (p.max_distance) && p.max_distance >= p.min_distance &&
                      p.max_distance <= FARTHEST_DISTANCE,
                  NAME,
                  "the maximum distance must be from the minimum to ",
                  FARTHEST_DISTANCE,
                  " m, not ",
                  p.max_distance);
  checkParameter (p.min_elevation_deg >= 0.0f &&
                      p.min_elevation_deg <= p.max_elevation_deg &&
                      p.max_elevation_deg <= HIGHEST_ELEVATION_DEG,
                  NAME,
                  "the elevations must satisfy 0 <= min <= max <= ",
                  HIGHEST_ELEVATION_DEG,
                  " degrees, not min ",
                  p.min_elevation_deg,
                  " and max ",
                  p.max_elevation_deg);
  checkParameter (p.min_points >= 1, NAME, "the fewest points must be >= 1");
}

ObjectInstance
drawObjectInstance (const ObjectViewParameters& parameters,
                    ObjectCategory category,
                    std::size_t instance)
{
  checkIndices (parameters, category, instance, 0);
  return drawInstance (parameters, category, instance).object;
}

ObjectView
renderObjectView (const ObjectViewParameters& parameters,
                  ObjectCategory category,
                  std::size_t instance,
                  std::size_t view)
{
  checkIndices (parameters, category, instance, view);
  const DrawnInstance drawn = drawInstance (parameters, category, instance);
  const ObjectSolid& solid = drawn.solid;
  ObjectView result;
  result.object = drawn.object;
  result.view = view;
  const Eigen::Matrix3d rotation = result.object.pose.linear().cast<double>();
  const Eigen::Matrix3d to_object = rotation.transpose();
  const auto distance = [&solid] (const Eigen::Vector3d& p) {
    return solid.distance (p);
  };
  const double bound = solid.boundRadius();

  DepthSensorModel sensor = depthSensorModel (DepthCameraParameters());
  sensor.noise_coefficient *= parameters.noise_multiplier;
  const std::uint64_t seed =
      childSeed (instanceSeed (parameters.seed, category, instance), view + 1);
  PortableRandom random (seed);
  PortableRandom colour_random (seed + COLOUR_NOISE_SEED_OFFSET);
  result.cloud.reset (new pcl::PointCloud<pcl::PointXYZRGB>);
  pcl::PointCloud<pcl::PointXYZRGB>& cloud = *result.cloud;
  for (result.poses_drawn = 1;; ++result.poses_drawn) {
    const CameraPose pose = drawCameraPose (random,
                                            parameters.min_distance,
                                            parameters.max_distance,
                                            parameters.min_elevation_deg,
                                            parameters.max_elevation_deg);
    const Eigen::Vector3d camera = to_object * pose.position;
    const Eigen::Vector3d projector = projectorPosition (sensor, pose);
    // Traced in the object's frame, where t is the same as in the world frame.
    const auto intersect = [&] (const Eigen::Vector3d& direction, RayHit& hit) {
      const Eigen::Vector3d local = to_object * direction;
      double t = std::numeric_limits<double>::infinity();
      if (!sphereTrace (distance, Eigen::Vector3d::Zero(), bound, camera, local, t))
        return false;
      hit.point = pose.position + t * direction;
      hit.normal = rotation * distanceNormal (distance, camera + t * local);
      hit.solid = 0;
      const ShadowRay shadow = shadowRay (hit, projector);
      double t_shadow = shadow.length;
      return !sphereTrace (distance,
                           Eigen::Vector3d::Zero(),
                           bound,
                           to_object * shadow.origin,
                           to_object * shadow.direction,
                           t_shadow);
    };
    const auto measure = [&] (const DepthPixel& pixel) {
      pcl::PointXYZRGB point;
      point.getVector3fMap() = pixel.measured.cast<float>();
      point.r = shade (result.object.r, pixel.cos_incidence);
      point.g = shade (result.object.g, pixel.cos_incidence);
      point.b = shade (result.object.b, pixel.cos_incidence);
      if (parameters.colour_noise > 0.0f)
        addColourNoise (point, parameters.colour_noise, colour_random);
      point.a = 255;
      cloud.push_back (point);
    };
    cloud.clear();
    castDepthRays (sensor,
                   pose,
                   axisWindow (sensor, std::asin (bound / pose.distance)),
                   random,
                   intersect,
                   measure);
    if (cloud.size() >= parameters.min_points) {
      result.camera_pose.linear() = pose.rotation.cast<float>();
      result.camera_pose.translation() = pose.position.cast<float>();
      result.distance = static_cast<float> (pose.distance);
      result.elevation_deg = static_cast<float> (pose.elevation * 180.0 / M_PI);
      result.azimuth_deg = static_cast<float> (pose.azimuth * 180.0 / M_PI);
      break;
    }
    checkParameter (result.poses_drawn < MAX_POSE_DRAWS,
                    NAME,
                    MAX_POSE_DRAWS,
                    " camera poses in a row see fewer than ",
                    parameters.min_points,
                    " points of ",
                    CATEGORY_NAMES[static_cast<std::size_t> (category)],
                    " ",
                    instance,
                    "; bring the camera closer or ask for fewer points");
  }
  if (parameters.perturbation > 0.0f) {
    PortableRandom perturbation_random (seed + PERTURBATION_SEED_OFFSET);
    const double a = parameters.perturbation;
    for (pcl::PointXYZRGB& point : cloud)
      for (int axis = 0; axis < 3; ++axis)
        point.data[axis] += static_cast<float> (perturbation_random.uniform (-a, a));
  }
  cloud.width = static_cast<std::uint32_t> (cloud.size());
  cloud.height = 1;
  cloud.is_dense = true;
  return result;
}

} // namespace tda
} // namespace pcl
