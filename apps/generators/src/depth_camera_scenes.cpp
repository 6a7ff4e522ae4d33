#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/tda/generators/parameter_checks.h>
#include <pcl/tda/generators/random_sampling.h>
#include <pcl/exceptions.h>
#include <pcl/point_types_conversion.h>

#include "depth_camera.h"
#include "signed_distances.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace pcl {
namespace tda {
namespace {

/** Object sizes, in metres. */
constexpr double BOWL_MIN_RADIUS = 0.05, BOWL_MAX_RADIUS = 0.09, BOWL_WALL = 0.006;
constexpr double CONE_MIN_RADIUS = 0.04, CONE_MAX_RADIUS = 0.07;
constexpr double CONE_MIN_TOP_RATIO = 0.3, CONE_MAX_TOP_RATIO = 0.7;
constexpr double CONE_MIN_HEIGHT = 0.08, CONE_MAX_HEIGHT = 0.20;
constexpr double RING_MIN_RADIUS = 0.035, RING_MAX_RADIUS = 0.06;
constexpr double RING_MIN_TUBE = 0.012, RING_MAX_TUBE = 0.025;
constexpr double BLOCK_MIN_LENGTH = 0.08, BLOCK_MAX_LENGTH = 0.16;
constexpr double BLOCK_MIN_WIDTH = 0.05, BLOCK_MAX_WIDTH = 0.10;
constexpr double BLOCK_MIN_HEIGHT = 0.06, BLOCK_MAX_HEIGHT = 0.16;
constexpr double CAPSULE_MIN_RADIUS = 0.025, CAPSULE_MAX_RADIUS = 0.045;
constexpr double CAPSULE_MIN_LENGTH = 0.05, CAPSULE_MAX_LENGTH = 0.14;
/** The tallest object (a cone), in metres: the camera must be above it. */
constexpr double MAX_OBJECT_HEIGHT = CONE_MAX_HEIGHT;
constexpr std::size_t NUM_KINDS = 5;

constexpr std::size_t MAX_IMAGE_SIDE = 4096;
constexpr int MAX_PLACEMENT_ATTEMPTS = 300;
constexpr int MAX_LAYOUT_ATTEMPTS = 100;
constexpr int GAP_BISECTION_STEPS = 60;

using Colour = std::array<std::uint8_t, 3>;
const Colour TABLE_COLOUR = {165, 150, 125};
const std::array<Colour, MAX_DEPTH_CAMERA_OBJECTS> OBJECT_PALETTE = {{{200, 60, 50},
                                                                      {60, 150, 80},
                                                                      {50, 90, 190},
                                                                      {220, 180, 40},
                                                                      {150, 70, 170},
                                                                      {40, 170, 170},
                                                                      {230, 120, 40},
                                                                      {90, 90, 90}}};

/** Colour regions: the bounds of DepthCameraParameters::colour_regions with
 * margins, so that other conversions to CIELAB agree. */
constexpr double SUBTLE_LOW = DEPTH_SUBTLE_MIN_DELTA_E + 0.5;
constexpr double SUBTLE_HIGH = DEPTH_SUBTLE_MAX_DELTA_E - 0.5;
constexpr double CONTRAST_LOW = DEPTH_CONTRAST_MIN_DELTA_E + 1.0;
constexpr double TABLE_CONTRAST = DEPTH_TABLE_MIN_DELTA_E + 1.0;
constexpr double OBJECTS_CONTRAST = DEPTH_OBJECTS_MIN_DELTA_E + 0.5;
/** Probability that an object's tones are subtle. */
constexpr double SUBTLE_PROBABILITY = 0.5;
/** Largest change of a channel from the first tone to a subtle second tone. */
constexpr int SUBTLE_STEP = 32;
/** The cone's regions meet at this fraction of its height, drawn uniformly. */
constexpr double CONE_MIN_SPLIT = 0.35, CONE_MAX_SPLIT = 0.65;
/** Tolerance of the boundary between the L-shaped block's base and upright, and of
 * the bowl's rim, in metres (hits are within HIT_EPSILON of the surface). */
constexpr double PART_TOLERANCE = 1e-4;
constexpr int MAX_TONE_DRAWS = 20000;
/** Offsets of the seeds of the painting's and the colour noise's random generators
 * from the scene's seed. */
constexpr std::uint64_t PAINT_SEED_OFFSET = 0x2545f4914f6cdd1dULL;
constexpr std::uint64_t COLOUR_NOISE_SEED_OFFSET = 0x94d049bb133111ebULL;

// Footprints (outlines seen from above): a convex core (one point, a segment, or a
// rectangle counter-clockwise) grown by a radius, with exact distances.

struct Footprint {
  std::vector<Eigen::Vector2d> core;
  double radius = 0.0;
};

double
cross2 (const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return a.x() * b.y() - a.y() * b.x();
}

double
pointSegmentDistance (const Eigen::Vector2d& p,
                      const Eigen::Vector2d& a,
                      const Eigen::Vector2d& b)
{
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t =
      length2 > 0.0 ? std::clamp ((p - a).dot (ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

/** Whether the segments ab and cd cross at a point inside both. */
bool
segmentsCross (const Eigen::Vector2d& a,
               const Eigen::Vector2d& b,
               const Eigen::Vector2d& c,
               const Eigen::Vector2d& d)
{
  const double d1 = cross2 (b - a, c - a), d2 = cross2 (b - a, d - a);
  const double d3 = cross2 (d - c, a - c), d4 = cross2 (d - c, b - c);
  return ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) &&
         ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0));
}

/** Whether p lies in the convex counter-clockwise polygon (false for a point or a
 * segment). */
bool
insidePolygon (const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& polygon)
{
  if (polygon.size() < 3)
    return false;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    if (cross2 (b - a, p - a) < 0.0)
      return false;
  }
  return true;
}

/** The sides of a core: a polygon's sides, a segment, or a point as a zero-length
 * side. */
std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>
sides (const std::vector<Eigen::Vector2d>& core)
{
  if (core.size() <= 2)
    return {{core.front(), core.back()}};
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> result;
  for (std::size_t i = 0; i < core.size(); ++i)
    result.emplace_back (core[i], core[(i + 1) % core.size()]);
  return result;
}

/** Distance between two convex cores (0 when they meet). */
double
coreDistance (const std::vector<Eigen::Vector2d>& p,
              const std::vector<Eigen::Vector2d>& q)
{
  for (const Eigen::Vector2d& v : p)
    if (insidePolygon (v, q))
      return 0.0;
  for (const Eigen::Vector2d& v : q)
    if (insidePolygon (v, p))
      return 0.0;
  double distance = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : sides (p))
    for (const auto& [c, d] : sides (q)) {
      if (segmentsCross (a, b, c, d))
        return 0.0;
      distance = std::min ({distance,
                            pointSegmentDistance (a, c, d),
                            pointSegmentDistance (b, c, d),
                            pointSegmentDistance (c, a, b),
                            pointSegmentDistance (d, a, b)});
    }
  return distance;
}

/** Distance between two footprints; <= 0 when they overlap. */
double
footprintGap (const Footprint& a, const Footprint& b)
{
  return coreDistance (a.core, b.core) - a.radius - b.radius;
}

/** An object on the table: its geometry as a distance bound for sphere tracing and
 * as a footprint for the layout. */
struct Solid {
  DepthObjectKind kind = DepthObjectKind::BOWL;
  /** Centre of the footprint, z = 0. */
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double yaw = 0.0;
  /** Bounding box in the object's frame, as DepthCameraObject::dimensions. */
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  double top_radius = 0.0;

  /** The point p (world frame) in the object's frame. */
  Eigen::Vector3d
  toLocal (const Eigen::Vector3d& p) const
  {
    const double c = std::cos (yaw), s = std::sin (yaw);
    const Eigen::Vector3d d = p - position;
    return {c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z()};
  }

  /** A lower bound on the distance from p (world frame) to the object, exact
   * outside but for the bowl's rim, negative inside. */
  double
  distance (const Eigen::Vector3d& world) const
  {
    const Eigen::Vector3d p = toLocal (world);
    switch (kind) {
    case DepthObjectKind::BOWL: {
      const double radius = size.z();
      return hemisphericalShellDistance (
          p - Eigen::Vector3d (0.0, 0.0, radius), radius, BOWL_WALL);
    }
    case DepthObjectKind::CONE:
      return coneDistance (p, 0.5 * size.x(), top_radius, size.z());
    case DepthObjectKind::RING: {
      const double tube = 0.5 * size.z();
      return torusDistance (
          p - Eigen::Vector3d (0.0, 0.0, tube), 0.5 * size.x() - tube, tube);
    }
    case DepthObjectKind::L_BLOCK: {
      const double length = size.x(), width = size.y(), height = size.z();
      const Eigen::Vector3d base_half (0.5 * length, 0.5 * width, height / 6.0);
      const Eigen::Vector3d upright_half (length / 6.0, 0.5 * width, 0.5 * height);
      return std::min (
          boxDistance (p - Eigen::Vector3d (0.0, 0.0, height / 6.0), base_half),
          boxDistance (p - Eigen::Vector3d (length / 3.0, 0.0, 0.5 * height),
                       upright_half));
    }
    case DepthObjectKind::CAPSULE: {
      const double radius = 0.5 * size.z();
      const double half_length = 0.5 * size.x() - radius;
      const Eigen::Vector3d axis_point (
          std::clamp (p.x(), -half_length, half_length), 0.0, radius);
      return (p - axis_point).norm() - radius;
    }
    }
    return 0.0;
  }

  /** Outward unit normal at a surface point p (world frame). */
  Eigen::Vector3d
  normal (const Eigen::Vector3d& p) const
  {
    return distanceNormal ([this] (const Eigen::Vector3d& q) { return distance (q); },
                           p);
  }

  /** Centre and radius of a sphere holding the object. */
  Eigen::Vector3d
  boundCentre () const
  {
    return position + Eigen::Vector3d (0.0, 0.0, 0.5 * size.z());
  }

  double
  boundRadius () const
  {
    return 0.5 * size.norm();
  }

  Footprint
  footprint () const
  {
    const double c = std::cos (yaw), s = std::sin (yaw);
    const auto place = [&] (double x, double y) {
      return Eigen::Vector2d (position.x() + c * x - s * y,
                              position.y() + s * x + c * y);
    };
    Footprint result;
    switch (kind) {
    case DepthObjectKind::BOWL:
    case DepthObjectKind::CONE:
    case DepthObjectKind::RING:
      result.core = {place (0.0, 0.0)};
      result.radius = 0.5 * size.x();
      break;
    case DepthObjectKind::L_BLOCK: {
      const double x = 0.5 * size.x(), y = 0.5 * size.y();
      result.core = {place (-x, -y), place (x, -y), place (x, y), place (-x, y)};
      break;
    }
    case DepthObjectKind::CAPSULE:
      result.radius = 0.5 * size.z();
      result.core = {place (-0.5 * size.x() + result.radius, 0.0),
                     place (0.5 * size.x() - result.radius, 0.0)};
      break;
    }
    return result;
  }
};

/** Draws the kind, size and yaw of an object (position left at the origin). */
Solid
drawSolid (PortableRandom& random)
{
  Solid solid;
  solid.kind = static_cast<DepthObjectKind> (random.index (NUM_KINDS));
  switch (solid.kind) {
  case DepthObjectKind::BOWL: {
    const double radius = random.uniform (BOWL_MIN_RADIUS, BOWL_MAX_RADIUS);
    solid.size = Eigen::Vector3d (2.0 * radius, 2.0 * radius, radius);
    break;
  }
  case DepthObjectKind::CONE: {
    const double radius = random.uniform (CONE_MIN_RADIUS, CONE_MAX_RADIUS);
    solid.top_radius = radius * random.uniform (CONE_MIN_TOP_RATIO, CONE_MAX_TOP_RATIO);
    solid.size = Eigen::Vector3d (
        2.0 * radius, 2.0 * radius, random.uniform (CONE_MIN_HEIGHT, CONE_MAX_HEIGHT));
    break;
  }
  case DepthObjectKind::RING: {
    const double radius = random.uniform (RING_MIN_RADIUS, RING_MAX_RADIUS);
    const double tube = random.uniform (RING_MIN_TUBE, RING_MAX_TUBE);
    solid.size =
        Eigen::Vector3d (2.0 * (radius + tube), 2.0 * (radius + tube), 2.0 * tube);
    break;
  }
  case DepthObjectKind::L_BLOCK:
    solid.size = Eigen::Vector3d (random.uniform (BLOCK_MIN_LENGTH, BLOCK_MAX_LENGTH),
                                  random.uniform (BLOCK_MIN_WIDTH, BLOCK_MAX_WIDTH),
                                  random.uniform (BLOCK_MIN_HEIGHT, BLOCK_MAX_HEIGHT));
    break;
  case DepthObjectKind::CAPSULE: {
    const double radius = random.uniform (CAPSULE_MIN_RADIUS, CAPSULE_MAX_RADIUS);
    const double length = random.uniform (CAPSULE_MIN_LENGTH, CAPSULE_MAX_LENGTH);
    solid.size = Eigen::Vector3d (length + 2.0 * radius, 2.0 * radius, 2.0 * radius);
    break;
  }
  }
  solid.yaw = random.uniform (0.0, 2.0 * M_PI);
  return solid;
}

/** Largest distance from the centre of a footprint to its outline. */
double
reach (const Footprint& footprint, const Eigen::Vector3d& position)
{
  double core = 0.0;
  for (const Eigen::Vector2d& v : footprint.core)
    core = std::max (core, (v - position.head<2>()).norm());
  return core + footprint.radius;
}

/** Whether the footprint lies inside the disc of radius \a radius about the
 * origin. */
bool
insideDisc (const Footprint& footprint, double radius)
{
  return std::all_of (
      footprint.core.begin(), footprint.core.end(), [&] (const Eigen::Vector2d& v) {
        return v.norm() + footprint.radius <= radius;
      });
}

/** Moves \a solid along the unit direction \a u from \a anchor's position to where
 * the gap between their footprints is \a gap (within 1e-12 m, not less). */
void
placeAtGap (const Solid& anchor, const Eigen::Vector3d& u, double gap, Solid& solid)
{
  const Footprint fixed = anchor.footprint();
  solid.position = anchor.position;
  double low = 0.0;
  double high =
      reach (fixed, anchor.position) + reach (solid.footprint(), solid.position) + gap;
  for (int step = 0; step < GAP_BISECTION_STEPS; ++step) {
    const double middle = 0.5 * (low + high);
    solid.position = anchor.position + middle * u;
    if (footprintGap (fixed, solid.footprint()) < gap)
      low = middle;
    else
      high = middle;
  }
  solid.position = anchor.position + high * u;
}

/** Lays out the objects in the layout disc, as documented; false when the random
 * draws do not fit. */
bool
layOut (std::size_t count,
        const DepthCameraParameters& parameters,
        PortableRandom& random,
        std::vector<Solid>& solids)
{
  solids.clear();
  for (std::size_t k = 0; k < count; ++k) {
    bool placed = false;
    for (int attempt = 0; attempt < MAX_PLACEMENT_ATTEMPTS && !placed; ++attempt) {
      Solid solid = drawSolid (random);
      const bool close = k > 0 && random.uniform() < parameters.close_probability;
      if (close) {
        const Solid& anchor = solids[random.index (k)];
        const double gap =
            random.uniform (parameters.min_close_gap, parameters.max_close_gap);
        const double angle = random.uniform (0.0, 2.0 * M_PI);
        placeAtGap (anchor,
                    Eigen::Vector3d (std::cos (angle), std::sin (angle), 0.0),
                    gap,
                    solid);
      }
      else {
        const double radius = parameters.layout_radius * std::sqrt (random.uniform());
        const double angle = random.uniform (0.0, 2.0 * M_PI);
        solid.position =
            Eigen::Vector3d (radius * std::cos (angle), radius * std::sin (angle), 0.0);
      }
      const Footprint footprint = solid.footprint();
      const double min_gap = close ? parameters.min_close_gap : parameters.min_far_gap;
      placed = insideDisc (footprint, parameters.layout_radius) &&
               std::all_of (solids.begin(), solids.end(), [&] (const Solid& other) {
                 return footprintGap (footprint, other.footprint()) >= min_gap;
               });
      if (placed)
        solids.push_back (solid);
    }
    if (!placed)
      return false;
  }
  return true;
}

/** First hit of the ray origin + t * direction (unit direction), 0 <= t < t_hit, on
 * the objects, by sphere tracing inside each one's bounding sphere: the index of the
 * object hit (t_hit set to the hit) or -1 (t_hit unchanged). */
int
traceObjects (const std::vector<Solid>& solids,
              const Eigen::Vector3d& origin,
              const Eigen::Vector3d& direction,
              double& t_hit)
{
  int hit = -1;
  for (std::size_t k = 0; k < solids.size(); ++k) {
    const Solid& solid = solids[k];
    if (sphereTrace ([&solid] (const Eigen::Vector3d& p) { return solid.distance (p); },
                     solid.boundCentre(),
                     solid.boundRadius(),
                     origin,
                     direction,
                     t_hit))
      hit = static_cast<int> (k);
  }
  return hit;
}

/** Throws pcl::BadArgumentException "generateDepthCameraScene: <message>" unless
 * \a valid. */
template <typename... Parts>
void
require (bool valid, const Parts&... message)
{
  checkParameter (valid, "generateDepthCameraScene", message...);
}

void
checkDepthCameraParameters (const DepthCameraParameters& p)
{
  const char* name = "generateDepthCameraScene";
  require (p.min_objects >= 1 && p.min_objects <= p.max_objects &&
               p.max_objects <= MAX_DEPTH_CAMERA_OBJECTS,
           "the object counts must satisfy 1 <= min <= max <= ",
           MAX_DEPTH_CAMERA_OBJECTS,
           ", not min ",
           p.min_objects,
           " and max ",
           p.max_objects);
  require (p.width >= 1 && p.width <= MAX_IMAGE_SIDE && p.height >= 1 &&
               p.height <= MAX_IMAGE_SIDE,
           "the image sides must be 1 to ",
           MAX_IMAGE_SIDE,
           " pixels, not ",
           p.width,
           " x ",
           p.height);
  checkLength (p.fx, name, "fx");
  checkLength (p.fy, name, "fy");
  require (std::isfinite (p.cx) && std::isfinite (p.cy),
           "the principal point must be finite, not (",
           p.cx,
           ", ",
           p.cy,
           ")");
  checkLength (p.min_distance, name, "minimum distance");
  require (std::isfinite (p.max_distance) && p.max_distance >= p.min_distance,
           "the maximum distance must be finite and at least the minimum, not ",
           p.max_distance);
  require (p.min_elevation_deg > 0.0f && p.min_elevation_deg <= p.max_elevation_deg &&
               p.max_elevation_deg < 90.0f,
           "the elevations must satisfy 0 < min <= max < 90 degrees, not min ",
           p.min_elevation_deg,
           " and max ",
           p.max_elevation_deg);
  const double lowest = p.min_distance * std::sin (p.min_elevation_deg * M_PI / 180.0);
  require (lowest > MAX_OBJECT_HEIGHT,
           "the camera must be above the objects (min distance x sin(min elevation) > ",
           MAX_OBJECT_HEIGHT,
           " m), not at ",
           lowest,
           " m");
  checkLength (p.table_width, name, "table width");
  checkLength (p.table_depth, name, "table depth");
  checkLength (p.layout_radius, name, "layout radius");
  require (2.0f * p.layout_radius <= std::min (p.table_width, p.table_depth),
           "the layout radius must be at most half the table's smaller side, not ",
           p.layout_radius);
  require (p.close_probability >= 0.0f && p.close_probability <= 1.0f,
           "the close probability must be in [0, 1], not ",
           p.close_probability);
  checkLength (p.min_close_gap, name, "minimum close gap");
  require (std::isfinite (p.max_close_gap) && p.max_close_gap >= p.min_close_gap,
           "the maximum close gap must be finite and at least the minimum, not ",
           p.max_close_gap);
  checkLength (p.min_far_gap, name, "minimum far gap");
  checkNonNegative (p.noise_coefficient, name, "noise coefficient");
  checkLength (p.baseline, name, "baseline");
  checkNonNegative (p.disparity_step, name, "disparity step");
  checkNonNegative (p.colour_noise, name, "colour noise");
  require (p.grazing_start_deg >= 0.0f && p.grazing_start_deg <= p.grazing_full_deg &&
               p.grazing_full_deg <= 90.0f,
           "the grazing angles must satisfy 0 <= start <= full <= 90 degrees, not "
           "start ",
           p.grazing_start_deg,
           " and full ",
           p.grazing_full_deg);
}

/** The colour in CIELAB, by PCL's conversion. */
Eigen::Vector3d
toLab (const Colour& colour)
{
  pcl::PointXYZRGB rgb;
  rgb.r = colour[0];
  rgb.g = colour[1];
  rgb.b = colour[2];
  pcl::PointXYZLAB lab;
  pcl::PointXYZRGBtoXYZLAB (rgb, lab);
  return {lab.L, lab.a, lab.b};
}

/** The two tones of an object and where they meet. */
struct Tones {
  /** Number of parts (regions): 1 unpainted, 2, or 3 for a capsule. */
  std::size_t parts = 1;
  bool subtle = false;
  /** Height of the boundary of a cone's regions, in metres. */
  double split = 0.0;
  Colour first = {0, 0, 0}, second = {0, 0, 0};

  /** The colour of a part, as DepthColourRegion::part. */
  const Colour&
  colour (const Solid& solid, std::size_t part) const
  {
    if (solid.kind == DepthObjectKind::CAPSULE)
      return part == 1 || parts == 1 ? first : second;
    return part == 0 ? first : second;
  }

  /** The adjacent parts, (a, b) with a < b. */
  std::vector<std::pair<std::size_t, std::size_t>>
  adjacent () const
  {
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t part = 0; part + 1 < parts; ++part)
      pairs.emplace_back (part, part + 1);
    return pairs;
  }

  /** The part of the surface point p (world frame) with outward normal n. */
  std::size_t
  partOf (const Solid& solid, const Eigen::Vector3d& p, const Eigen::Vector3d& n) const
  {
    if (parts == 1)
      return 0;
    const Eigen::Vector3d local = solid.toLocal (p);
    switch (solid.kind) {
    case DepthObjectKind::BOWL: {
      const double radius = solid.size.z();
      const Eigen::Vector3d q = local - Eigen::Vector3d (0.0, 0.0, radius);
      const bool rim = n.z() > 0.7 && q.z() > -BOWL_WALL;
      return !rim && q.norm() < radius - 0.5 * BOWL_WALL ? 1 : 0;
    }
    case DepthObjectKind::CONE:
      return local.z() >= split ? 1 : 0;
    case DepthObjectKind::RING:
      return local.y() >= 0.0 ? 1 : 0;
    case DepthObjectKind::L_BLOCK:
      return local.x() > solid.size.x() / 6.0 - PART_TOLERANCE ? 1 : 0;
    case DepthObjectKind::CAPSULE: {
      const double half_length = 0.5 * (solid.size.x() - solid.size.z());
      return local.x() < -half_length ? 0 : local.x() > half_length ? 2 : 1;
    }
    }
    return 0;
  }
};

/** Paints the objects in two tones, as DepthCameraParameters::colour_regions
 * documents; \a colours holds each object's first tone. */
std::vector<Tones>
paintObjects (const std::vector<Solid>& solids,
              const std::vector<Colour>& colours,
              std::uint64_t seed)
{
  PortableRandom random (seed + PAINT_SEED_OFFSET);
  const Eigen::Vector3d table = toLab (TABLE_COLOUR);
  std::vector<Eigen::Vector3d> painted;
  for (const Colour& colour : colours)
    painted.push_back (toLab (colour));
  std::vector<Tones> tones (solids.size());
  for (std::size_t k = 0; k < solids.size(); ++k) {
    Tones& object = tones[k];
    object.parts = solids[k].kind == DepthObjectKind::CAPSULE ? 3 : 2;
    object.first = colours[k];
    object.subtle = random.uniform() < SUBTLE_PROBABILITY;
    if (solids[k].kind == DepthObjectKind::CONE)
      object.split =
          solids[k].size.z() * random.uniform (CONE_MIN_SPLIT, CONE_MAX_SPLIT);
    const Eigen::Vector3d first = painted[k];
    bool found = false;
    for (int draw = 0; draw < MAX_TONE_DRAWS && !found; ++draw) {
      for (std::size_t c = 0; c < 3; ++c) {
        const long level =
            object.subtle ? object.first[c] +
                                static_cast<long> (random.index (2 * SUBTLE_STEP + 1)) -
                                SUBTLE_STEP
                          : static_cast<long> (random.index (256));
        object.second[c] = static_cast<std::uint8_t> (std::clamp (level, 0L, 255L));
      }
      const Eigen::Vector3d lab = toLab (object.second);
      const double difference = (lab - first).norm();
      found = (object.subtle ? difference >= SUBTLE_LOW && difference <= SUBTLE_HIGH
                             : difference >= CONTRAST_LOW) &&
              (lab - table).norm() >= TABLE_CONTRAST;
      for (std::size_t j = 0; j < painted.size() && found; ++j)
        found = j == k || (lab - painted[j]).norm() >= OBJECTS_CONTRAST;
      if (found)
        painted.push_back (lab);
    }
    if (!found)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "generateDepthCameraScene: cannot paint object "
                               << k << " in two tones");
  }
  return tones;
}

} // namespace

DepthCameraScene
generateDepthCameraScene (const DepthCameraParameters& parameters)
{
  checkDepthCameraParameters (parameters);
  PortableRandom random (parameters.seed);
  DepthCameraScene scene;

  // Camera: looks at the table centre, no roll; optical frame x right, y down.
  const DepthSensorModel sensor = depthSensorModel (parameters);
  const CameraPose pose = drawCameraPose (random,
                                          parameters.min_distance,
                                          parameters.max_distance,
                                          parameters.min_elevation_deg,
                                          parameters.max_elevation_deg);
  const Eigen::Vector3d& camera = pose.position;
  const Eigen::Vector3d projector = projectorPosition (sensor, pose);
  scene.camera_pose.linear() = pose.rotation.cast<float>();
  scene.camera_pose.translation() = camera.cast<float>();
  scene.distance = static_cast<float> (pose.distance);
  scene.elevation_deg = static_cast<float> (pose.elevation * 180.0 / M_PI);
  const Eigen::Vector3d plane_normal =
      pose.rotation.transpose() * Eigen::Vector3d::UnitZ();
  scene.table_plane << plane_normal.cast<float>(), static_cast<float> (camera.z());

  std::array<Colour, MAX_DEPTH_CAMERA_OBJECTS> palette = OBJECT_PALETTE;
  for (std::size_t i = palette.size() - 1; i > 0; --i)
    std::swap (palette[i], palette[random.index (i + 1)]);

  const std::size_t count =
      parameters.min_objects +
      random.index (parameters.max_objects - parameters.min_objects + 1);
  std::vector<Solid> solids;
  bool laid_out = false;
  for (int layout = 0; layout < MAX_LAYOUT_ATTEMPTS && !laid_out; ++layout)
    laid_out = layOut (count, parameters, random, solids);
  if (!laid_out)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "generateDepthCameraScene: cannot lay out "
                             << count << " objects in a disc of radius "
                             << parameters.layout_radius << " m with gaps of at least "
                             << parameters.min_close_gap << " m (close) and "
                             << parameters.min_far_gap
                             << " m (far); use fewer objects, a larger layout "
                                "radius or smaller gaps");

  for (std::size_t k = 0; k < solids.size(); ++k) {
    DepthCameraObject truth;
    truth.kind = solids[k].kind;
    truth.label = DEPTH_FIRST_OBJECT_LABEL + static_cast<std::uint32_t> (k);
    truth.position = solids[k].position.cast<float>();
    truth.yaw = static_cast<float> (solids[k].yaw);
    truth.dimensions = solids[k].size.cast<float>();
    truth.top_radius = static_cast<float> (solids[k].top_radius);
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < solids.size(); ++j)
      if (j != k)
        gap =
            std::min (gap, footprintGap (solids[k].footprint(), solids[j].footprint()));
    truth.gap = static_cast<float> (gap);
    truth.r = palette[k][0];
    truth.g = palette[k][1];
    truth.b = palette[k][2];
    scene.objects.push_back (truth);
  }

  // Colour regions: one part per object unless painted. A slot is the table or a
  // part of an object, numbered through the scene; the regions are the slots with
  // points.
  std::vector<Tones> tones (solids.size());
  if (parameters.colour_regions)
    tones =
        paintObjects (solids,
                      std::vector<Colour> (palette.begin(), palette.begin() + count),
                      parameters.seed);
  else
    for (std::size_t k = 0; k < solids.size(); ++k)
      tones[k].first = palette[k];
  std::vector<DepthColourRegion> slots (1);
  slots[0].r = TABLE_COLOUR[0];
  slots[0].g = TABLE_COLOUR[1];
  slots[0].b = TABLE_COLOUR[2];
  std::vector<std::size_t> first_slot (solids.size());
  for (std::size_t k = 0; k < solids.size(); ++k) {
    first_slot[k] = slots.size();
    for (std::size_t part = 0; part < tones[k].parts; ++part) {
      DepthColourRegion slot;
      slot.object_label = DEPTH_FIRST_OBJECT_LABEL + static_cast<std::uint32_t> (k);
      slot.part = static_cast<std::uint32_t> (part);
      const Colour& colour = tones[k].colour (solids[k], part);
      slot.r = colour[0];
      slot.g = colour[1];
      slot.b = colour[2];
      slots.push_back (slot);
    }
  }
  constexpr std::size_t NO_SLOT = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> pixel_slots (parameters.width * parameters.height, NO_SLOT);
  PortableRandom colour_random (parameters.seed + COLOUR_NOISE_SEED_OFFSET);

  // One ray per pixel.
  pcl::PointXYZRGBL lost;
  lost.x = lost.y = lost.z = std::numeric_limits<float>::quiet_NaN();
  lost.rgba = 0;
  lost.label = DEPTH_BACKGROUND_LABEL;
  scene.cloud.reset (new pcl::PointCloud<pcl::PointXYZRGBL> (
      static_cast<std::uint32_t> (parameters.width),
      static_cast<std::uint32_t> (parameters.height),
      lost));
  scene.cloud->is_dense = false;
  const double half_width = 0.5 * parameters.table_width;
  const double half_depth = 0.5 * parameters.table_depth;
  const auto intersect = [&] (const Eigen::Vector3d& direction, RayHit& hit) {
    double t = std::numeric_limits<double>::infinity();
    if (direction.z() < 0.0) {
      const double t_table = -camera.z() / direction.z();
      const Eigen::Vector3d p = camera + t_table * direction;
      if (std::abs (p.x()) <= half_width && std::abs (p.y()) <= half_depth)
        t = t_table;
    }
    hit.solid = traceObjects (solids, camera, direction, t);
    if (!std::isfinite (t))
      return false;
    hit.point = camera + t * direction;
    hit.normal = hit.solid < 0 ? Eigen::Vector3d (Eigen::Vector3d::UnitZ())
                               : solids[hit.solid].normal (hit.point);
    if (!parameters.projector_shadows)
      return true;
    const ShadowRay shadow = shadowRay (hit, projector);
    double t_shadow = shadow.length;
    return traceObjects (solids, shadow.origin, shadow.direction, t_shadow) < 0;
  };
  const auto measure = [&] (const DepthPixel& pixel) {
    const int object = pixel.hit.solid;
    if (object < 0) {
      ++scene.num_table_points;
      if (parameters.remove_table)
        return;
    }
    pcl::PointXYZRGBL& point = (*scene.cloud) (pixel.u, pixel.v);
    point.getVector3fMap() = pixel.measured.cast<float>();
    const std::size_t slot =
        object < 0 ? 0
                   : first_slot[object] + tones[object].partOf (solids[object],
                                                                pixel.hit.point,
                                                                pixel.hit.normal);
    pixel_slots[pixel.v * parameters.width + pixel.u] = slot;
    point.r = shade (slots[slot].r, pixel.cos_incidence);
    point.g = shade (slots[slot].g, pixel.cos_incidence);
    point.b = shade (slots[slot].b, pixel.cos_incidence);
    if (parameters.colour_noise > 0.0f)
      addColourNoise (point, parameters.colour_noise, colour_random);
    point.a = 255;
    if (object >= 0) {
      point.label = DEPTH_FIRST_OBJECT_LABEL + static_cast<std::uint32_t> (object);
      ++scene.objects[object].num_points;
    }
  };
  castDepthRays (sensor, pose, fullFrame (sensor), random, intersect, measure);

  // Regions: the slots with points, labelled in slot order.
  for (const std::size_t slot : pixel_slots)
    if (slot != NO_SLOT)
      ++slots[slot].num_points;
  std::vector<std::uint32_t> slot_labels (slots.size(), 0);
  for (std::size_t slot = 0; slot < slots.size(); ++slot)
    if (slots[slot].num_points > 0) {
      slot_labels[slot] = static_cast<std::uint32_t> (scene.regions.size()) + 1;
      scene.regions.push_back (slots[slot]);
      scene.regions.back().label = slot_labels[slot];
    }
  scene.region_labels.reserve (pixel_slots.size());
  for (const std::size_t slot : pixel_slots)
    scene.region_labels.push_back (slot == NO_SLOT ? 0 : slot_labels[slot]);
  for (std::size_t k = 0; k < solids.size(); ++k)
    if (tones[k].subtle)
      for (const auto& [a, b] : tones[k].adjacent()) {
        const std::uint32_t label_a = slot_labels[first_slot[k] + a];
        const std::uint32_t label_b = slot_labels[first_slot[k] + b];
        if (label_a != 0 && label_b != 0)
          scene.similar_regions.emplace_back (std::min (label_a, label_b),
                                              std::max (label_a, label_b));
      }
  std::sort (scene.similar_regions.begin(), scene.similar_regions.end());
  return scene;
}

pcl::PointCloud<pcl::PointXYZRGBL>::Ptr
regionLabelledCloud (const DepthCameraScene& scene)
{
  pcl::PointCloud<pcl::PointXYZRGBL>::Ptr cloud (
      new pcl::PointCloud<pcl::PointXYZRGBL> (*scene.cloud));
  for (std::size_t i = 0; i < cloud->size() && i < scene.region_labels.size(); ++i)
    (*cloud)[i].label = scene.region_labels[i];
  return cloud;
}

} // namespace tda
} // namespace pcl
