#include <pcl/tda/common/cielab.h>
#include <pcl/tda/generators/parameter_checks.h>
#include <pcl/tda/generators/random_sampling.h>
#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/exceptions.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace pcl {
namespace tda {
namespace {

/** Colour noise is Gaussian, redrawn beyond this many standard deviations. */
constexpr double COLOUR_NOISE_TRUNCATION = 3.0;

/** Tabletop object sizes, in metres. */
constexpr double BOX_MIN_SIDE = 0.06, BOX_MAX_SIDE = 0.16;
constexpr double BOX_MIN_HEIGHT = 0.05, BOX_MAX_HEIGHT = 0.20;
constexpr double CYLINDER_MIN_RADIUS = 0.03, CYLINDER_MAX_RADIUS = 0.06;
constexpr double CYLINDER_MIN_HEIGHT = 0.06, CYLINDER_MAX_HEIGHT = 0.20;
constexpr double SPHERE_MIN_RADIUS = 0.03, SPHERE_MAX_RADIUS = 0.07;
constexpr double MAX_OBJECT_HEIGHT = 0.20;
/** Free border between the objects and the table edge, in metres. */
constexpr double TABLE_MARGIN = 0.02;
/** Upper bound on the number of table samples, to refuse absurd densities. */
constexpr double MAX_TABLE_SAMPLES = 5e7;
constexpr int MAX_PLACEMENT_ATTEMPTS = 1000;
constexpr int MAX_LAYOUT_ATTEMPTS = 100;

using Colour = std::array<std::uint8_t, 3>;
const Colour TABLE_COLOUR = {150, 110, 75};
const std::array<Colour, MAX_TABLETOP_OBJECTS> OBJECT_PALETTE = {{{210, 40, 40},
                                                                  {40, 170, 60},
                                                                  {40, 80, 210},
                                                                  {230, 210, 40},
                                                                  {180, 50, 180},
                                                                  {40, 190, 200},
                                                                  {250, 140, 20},
                                                                  {235, 235, 235}}};

/** Colour regions: the colour differences of TabletopParameters::colour_regions
 * with margins, so that other conversions to CIELAB (in float, with other rounded
 * matrices) agree with the documented bounds. */
constexpr double SIMILAR_LOW = SIMILAR_REGION_MIN_DELTA_E + 0.5;
constexpr double SIMILAR_HIGH = SIMILAR_REGION_MAX_DELTA_E - 0.5;
constexpr double DISTINCT = DISTINCT_REGION_MIN_DELTA_E + 1.0;
constexpr double OTHER_OBJECTS = SIMILAR_REGION_MIN_DELTA_E + 0.5;
/** Painted channels stay in this range, so that colour noise of up to 8 levels,
 * truncated at 3 standard deviations, is never clipped. */
constexpr int MIN_PAINT_LEVEL = 24, MAX_PAINT_LEVEL = 231;
/** Largest change of a channel from a region's colour to its similar partner's. */
constexpr int SIMILAR_STEP = 28;
/** Similar pairs are chosen among regions with at least this many samples each. */
constexpr std::size_t MIN_SIMILAR_SAMPLES = 15;
/** Cylinders at least this tall (metres) may get three bands instead of two. */
constexpr double MIN_THREE_BAND_HEIGHT = 0.09;
constexpr int MAX_COLOUR_DRAWS = 2000;
constexpr int MAX_PAINT_ATTEMPTS = 100;
/** Offset of the seed of the painting's random generator from the scene's seed. */
constexpr std::uint64_t PAINT_SEED_OFFSET = 0x9e3779b97f4a7c15ULL;

/** The sRGB colour in CIELAB (rgbToLab(): D65 white, 2 degree observer). */
Eigen::Vector3d
toLab (const Colour& colour)
{
  const LabColor lab = rgbToLab (colour[0], colour[1], colour[2]);
  return {lab.l, lab.a, lab.b};
}

/** Narrows [t0, t1] to the parameters t at which p + t * d lies strictly inside the
 * slab |x| < half; false when nothing is left. */
bool
clipToSlab (double p, double d, double half, double& t0, double& t1)
{
  if (std::abs (d) < 1e-12)
    return std::abs (p) < half;
  double t_near = (-half - p) / d;
  double t_far = (half - p) / d;
  if (t_near > t_far)
    std::swap (t_near, t_far);
  t0 = std::max (t0, t_near);
  t1 = std::min (t1, t_far);
  return t0 < t1;
}

/** A primitive resting on the table: geometry, sampling and ray tests. */
struct Primitive {
  PrimitiveType type;
  Eigen::Vector3d centre;
  /** Half side lengths of the bounding box in the primitive's own frame. */
  Eigen::Vector3d half;
  double yaw;

  /** Rotation from the primitive's frame to the world frame. */
  Eigen::Matrix3d
  rotation () const
  {
    return Eigen::AngleAxisd (yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  }

  /** Radius of a disc about the centre that holds the footprint. */
  double
  footprintRadius () const
  {
    return type == PrimitiveType::BOX ? std::hypot (half.x(), half.y()) : half.x();
  }

  /** Whether the table point (x, y, 0) lies under the primitive (spheres touch the
   * table in a single point and cover nothing). */
  bool
  covers (const Eigen::Vector3d& p) const
  {
    const Eigen::Vector3d local = rotation().transpose() * (p - centre);
    switch (type) {
    case PrimitiveType::BOX:
      return std::abs (local.x()) <= half.x() && std::abs (local.y()) <= half.y();
    case PrimitiveType::CYLINDER:
      return local.head<2>().norm() <= half.x();
    case PrimitiveType::SPHERE:
      break;
    }
    return false;
  }

  /** Whether the segment from a to b passes through the interior. */
  bool
  intersects (const Eigen::Vector3d& a, const Eigen::Vector3d& b) const
  {
    const Eigen::Matrix3d to_local = rotation().transpose();
    const Eigen::Vector3d p = to_local * (a - centre);
    const Eigen::Vector3d d = to_local * (b - a);
    switch (type) {
    case PrimitiveType::BOX: {
      double t0 = 0.0, t1 = 1.0;
      for (int k = 0; k < 3; ++k)
        if (!clipToSlab (p[k], d[k], half[k], t0, t1))
          return false;
      return true;
    }
    case PrimitiveType::CYLINDER: {
      double t0 = 0.0, t1 = 1.0;
      if (!clipToSlab (p.z(), d.z(), half.z(), t0, t1))
        return false;
      const double dd = d.head<2>().squaredNorm();
      const double t =
          dd < 1e-24 ? t0 : std::clamp (-p.head<2>().dot (d.head<2>()) / dd, t0, t1);
      return (p.head<2>() + t * d.head<2>()).squaredNorm() < half.x() * half.x();
    }
    case PrimitiveType::SPHERE: {
      const double t = std::clamp (-p.dot (d) / d.squaredNorm(), 0.0, 1.0);
      return (p + t * d).squaredNorm() < half.x() * half.x();
    }
    }
    return false;
  }

  /** One point per cell of about spacing x spacing on every surface except a
   * bottom resting on the table, with outward normals, in world coordinates. */
  std::vector<SurfaceSample>
  sample (double spacing, PortableRandom& random) const
  {
    std::vector<SurfaceSample> local;
    switch (type) {
    case PrimitiveType::BOX: {
      const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                            z = Eigen::Vector3d::UnitZ();
      const Eigen::Vector3d sx = 2.0 * half.x() * x, sy = 2.0 * half.y() * y,
                            sz = 2.0 * half.z() * z;
      const Eigen::Vector3d corner = -half;
      sampleRectangle (corner + sz, sx, sy, z, spacing, random, local);
      sampleRectangle (corner, sx, sz, -y, spacing, random, local);
      sampleRectangle (corner + sy, sx, sz, y, spacing, random, local);
      sampleRectangle (corner, sy, sz, -x, spacing, random, local);
      sampleRectangle (corner + sx, sy, sz, x, spacing, random, local);
      break;
    }
    case PrimitiveType::CYLINDER: {
      const double radius = half.x();
      const std::size_t around =
          std::max<std::size_t> (3, cellCount (2.0 * M_PI * radius, spacing));
      const std::size_t along = cellCount (2.0 * half.z(), spacing);
      for (std::size_t i = 0; i < around; ++i)
        for (std::size_t j = 0; j < along; ++j) {
          const double theta = 2.0 * M_PI * (i + random.uniform()) / around;
          const double z = half.z() * (2.0 * (j + random.uniform()) / along - 1.0);
          const Eigen::Vector3d n (std::cos (theta), std::sin (theta), 0.0);
          local.push_back ({radius * n + z * Eigen::Vector3d::UnitZ(), n});
        }
      for (SurfaceSample& s : sampleDisc (radius, spacing, random)) {
        s.point.z() = half.z();
        local.push_back (s);
      }
      break;
    }
    case PrimitiveType::SPHERE: {
      const double radius = half.x();
      const double area = 4.0 * M_PI * radius * radius;
      local = sampleSphere (radius, cellCount (area, spacing * spacing), random);
      break;
    }
    }
    const Eigen::Matrix3d to_world = rotation();
    for (SurfaceSample& s : local) {
      s.point = to_world * s.point + centre;
      s.normal = to_world * s.normal;
    }
    return local;
  }
};

/** The colour regions of an object: how its surface is split into parts, which
 * parts share a boundary, which of those are painted in similar colours, and the
 * colours. One part without TabletopParameters::colour_regions. */
struct Painting {
  std::size_t parts = 1;
  /** Cylinder: heights (object frame) of the boundaries between its bands,
   * increasing. */
  std::vector<double> band_bounds;
  /** Sphere: unit axis of its parallel splitting planes (object frame) and their
   * offsets along it, increasing. */
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  std::vector<double> plane_offsets;
  /** Pairs (a, b), a < b, of parts that share a boundary. */
  std::vector<std::pair<std::size_t, std::size_t>> adjacent;
  /** Adjacent pairs painted in similar colours, disjoint, increasing. */
  std::vector<std::pair<std::size_t, std::size_t>> similar;
  std::vector<Colour> colours;

  /** The part of a surface sample of \a primitive, as TabletopColourRegion::part. */
  std::size_t
  partOf (const Primitive& primitive, const SurfaceSample& sample) const
  {
    if (parts == 1)
      return 0;
    const Eigen::Matrix3d to_local = primitive.rotation().transpose();
    const Eigen::Vector3d normal = to_local * sample.normal;
    const Eigen::Vector3d local = to_local * (sample.point - primitive.centre);
    switch (primitive.type) {
    case PrimitiveType::BOX:
      if (normal.z() > 0.5)
        return 0;
      if (std::abs (normal.y()) > 0.5)
        return normal.y() < 0.0 ? 1 : 2;
      return normal.x() < 0.0 ? 3 : 4;
    case PrimitiveType::CYLINDER:
      if (normal.z() > 0.5)
        return parts - 1;
      return static_cast<std::size_t> (
          std::upper_bound (band_bounds.begin(), band_bounds.end(), local.z()) -
          band_bounds.begin());
    case PrimitiveType::SPHERE:
      return static_cast<std::size_t> (std::upper_bound (plane_offsets.begin(),
                                                         plane_offsets.end(),
                                                         axis.dot (local)) -
                                       plane_offsets.begin());
    }
    return 0;
  }
};

/** Draws how the primitive is split into colour regions (colours left empty). */
Painting
drawPainting (const Primitive& primitive, PortableRandom& random)
{
  Painting painting;
  switch (primitive.type) {
  case PrimitiveType::BOX:
    // Top, sides -y, +y, -x, +x.
    painting.parts = 5;
    painting.adjacent = {
        {0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 3}, {1, 4}, {2, 3}, {2, 4}};
    break;
  case PrimitiveType::CYLINDER: {
    const double height = 2.0 * primitive.half.z();
    const std::size_t bands =
        height >= MIN_THREE_BAND_HEIGHT && random.uniform() < 0.5 ? 3 : 2;
    for (std::size_t i = 1; i < bands; ++i)
      painting.band_bounds.push_back (
          height * ((i + random.uniform (-0.25, 0.25)) / bands - 0.5));
    painting.parts = bands + 1;
    for (std::size_t i = 0; i < bands; ++i)
      painting.adjacent.emplace_back (i, i + 1);
    break;
  }
  case PrimitiveType::SPHERE: {
    const double radius = primitive.half.x();
    const bool halves = random.uniform() < 0.5;
    // Halves: a tilted plane through the centre; else a band about a steep axis.
    const double polar = halves ? random.uniform (M_PI / 6.0, M_PI / 2.0)
                                : random.uniform (0.0, M_PI / 4.0);
    const double azimuth = random.uniform (0.0, 2.0 * M_PI);
    painting.axis = Eigen::Vector3d (std::sin (polar) * std::cos (azimuth),
                                     std::sin (polar) * std::sin (azimuth),
                                     std::cos (polar));
    if (halves)
      painting.plane_offsets = {0.0};
    else
      painting.plane_offsets = {radius * random.uniform (-0.45, -0.1),
                                radius * random.uniform (0.1, 0.45)};
    painting.parts = painting.plane_offsets.size() + 1;
    for (std::size_t i = 0; i + 1 < painting.parts; ++i)
      painting.adjacent.emplace_back (i, i + 1);
    break;
  }
  }
  return painting;
}

/** Chooses the similar pairs of the painting among the adjacent parts that have at
 * least MIN_SIMILAR_SAMPLES samples each (\a counts): one, or for a box one or
 * two, no part in two pairs. */
void
chooseSimilarPairs (const std::vector<std::size_t>& counts,
                    PortableRandom& random,
                    Painting& painting)
{
  std::vector<std::pair<std::size_t, std::size_t>> candidates;
  for (const auto& pair : painting.adjacent)
    if (counts[pair.first] >= MIN_SIMILAR_SAMPLES &&
        counts[pair.second] >= MIN_SIMILAR_SAMPLES)
      candidates.push_back (pair);
  for (std::size_t i = candidates.size(); i > 1; --i)
    std::swap (candidates[i - 1], candidates[random.index (i)]);
  const std::size_t wanted = painting.parts == 5 ? 1 + random.index (2) : 1;
  std::vector<bool> taken (painting.parts, false);
  for (const auto& pair : candidates) {
    if (painting.similar.size() == wanted)
      break;
    if (taken[pair.first] || taken[pair.second])
      continue;
    taken[pair.first] = taken[pair.second] = true;
    painting.similar.push_back (pair);
  }
  std::sort (painting.similar.begin(), painting.similar.end());
}

/** Draws the colours of the painting's parts as TabletopParameters::colour_regions
 * documents, given the table's colour and the colours of the objects painted
 * before, in CIELAB; false when the draws do not succeed. */
bool
drawColours (const Eigen::Vector3d& table,
             const std::vector<Eigen::Vector3d>& others,
             PortableRandom& random,
             Painting& painting)
{
  std::vector<std::size_t> partner (painting.parts, painting.parts);
  for (const auto& pair : painting.similar)
    partner[pair.second] = pair.first;
  std::vector<Eigen::Vector3d> labs;
  for (int attempt = 0; attempt < MAX_PAINT_ATTEMPTS; ++attempt) {
    painting.colours.clear();
    labs.clear();
    for (std::size_t part = 0; part < painting.parts; ++part) {
      const std::size_t similar = partner[part];
      bool found = false;
      for (int draw = 0; draw < MAX_COLOUR_DRAWS && !found; ++draw) {
        Colour colour;
        for (std::size_t c = 0; c < 3; ++c) {
          const long level =
              similar < part
                  ? painting.colours[similar][c] +
                        static_cast<long> (random.index (2 * SIMILAR_STEP + 1)) -
                        SIMILAR_STEP
                  : MIN_PAINT_LEVEL + static_cast<long> (random.index (
                                          MAX_PAINT_LEVEL - MIN_PAINT_LEVEL + 1));
          colour[c] = static_cast<std::uint8_t> (
              std::clamp<long> (level, MIN_PAINT_LEVEL, MAX_PAINT_LEVEL));
        }
        const Eigen::Vector3d lab = toLab (colour);
        found = (lab - table).norm() >= DISTINCT;
        for (std::size_t k = 0; k < part && found; ++k) {
          const double difference = (lab - labs[k]).norm();
          found = k == similar ? difference >= SIMILAR_LOW && difference <= SIMILAR_HIGH
                               : difference >= DISTINCT;
        }
        for (std::size_t k = 0; k < others.size() && found; ++k)
          found = (lab - others[k]).norm() >= OTHER_OBJECTS;
        if (found) {
          painting.colours.push_back (colour);
          labs.push_back (lab);
        }
      }
      if (!found)
        break;
    }
    if (painting.colours.size() == painting.parts)
      return true;
  }
  return false;
}

/** Paints the objects in colour regions from a random generator of their own:
 * samples[0] is the table, samples[k + 1] object k; sets parts[k + 1] to the part
 * of each sample of object k. */
void
paintObjects (const std::vector<Primitive>& objects,
              const std::vector<std::vector<SurfaceSample>>& samples,
              std::uint64_t seed,
              std::vector<Painting>& paintings,
              std::vector<std::vector<std::size_t>>& parts)
{
  PortableRandom random (seed + PAINT_SEED_OFFSET);
  const Eigen::Vector3d table = toLab (TABLE_COLOUR);
  std::vector<Eigen::Vector3d> painted;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    Painting& painting = paintings[k];
    painting = drawPainting (objects[k], random);
    std::vector<std::size_t> counts (painting.parts, 0);
    for (const SurfaceSample& sample : samples[k + 1]) {
      parts[k + 1].push_back (painting.partOf (objects[k], sample));
      ++counts[parts[k + 1].back()];
    }
    chooseSimilarPairs (counts, random, painting);
    if (!drawColours (table, painted, random, painting))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "generateTabletopScene: cannot paint object "
                               << k << " in colour regions");
    for (const Colour& colour : painting.colours)
      painted.push_back (toLab (colour));
  }
}

/** Draws the type, size and yaw of an object (position left at the origin). */
Primitive
drawPrimitive (PortableRandom& random)
{
  Primitive primitive;
  primitive.type = static_cast<PrimitiveType> (random.index (3));
  primitive.yaw = 0.0;
  switch (primitive.type) {
  case PrimitiveType::BOX:
    primitive.half =
        0.5 * Eigen::Vector3d (random.uniform (BOX_MIN_SIDE, BOX_MAX_SIDE),
                               random.uniform (BOX_MIN_SIDE, BOX_MAX_SIDE),
                               random.uniform (BOX_MIN_HEIGHT, BOX_MAX_HEIGHT));
    primitive.yaw = random.uniform (0.0, M_PI);
    break;
  case PrimitiveType::CYLINDER: {
    const double radius = random.uniform (CYLINDER_MIN_RADIUS, CYLINDER_MAX_RADIUS);
    const double height = random.uniform (CYLINDER_MIN_HEIGHT, CYLINDER_MAX_HEIGHT);
    primitive.half = Eigen::Vector3d (radius, radius, 0.5 * height);
    break;
  }
  case PrimitiveType::SPHERE: {
    const double radius = random.uniform (SPHERE_MIN_RADIUS, SPHERE_MAX_RADIUS);
    primitive.half = Eigen::Vector3d::Constant (radius);
    break;
  }
  }
  primitive.centre = Eigen::Vector3d::Zero();
  return primitive;
}

/** Places count objects inside the table, their footprint discs at least
 * separation apart; false when the random draws do not fit. */
bool
placeObjects (std::size_t count,
              double half_width,
              double half_depth,
              double separation,
              PortableRandom& random,
              std::vector<Primitive>& objects)
{
  objects.clear();
  for (std::size_t k = 0; k < count; ++k) {
    bool placed = false;
    for (int attempt = 0; attempt < MAX_PLACEMENT_ATTEMPTS && !placed; ++attempt) {
      Primitive candidate = drawPrimitive (random);
      const double reach = candidate.footprintRadius() + TABLE_MARGIN;
      if (reach >= half_width || reach >= half_depth)
        continue;
      candidate.centre =
          Eigen::Vector3d (random.uniform (-half_width + reach, half_width - reach),
                           random.uniform (-half_depth + reach, half_depth - reach),
                           candidate.half.z());
      placed =
          std::all_of (objects.begin(), objects.end(), [&] (const Primitive& other) {
            const double distance = (candidate.centre - other.centre).head<2>().norm();
            return distance >=
                   candidate.footprintRadius() + other.footprintRadius() + separation;
          });
      if (placed)
        objects.push_back (candidate);
    }
    if (!placed)
      return false;
  }
  return true;
}

/** Keeps the samples a camera sees: those facing it and not behind another object.
 * samples[0] is the table, samples[k + 1] object k. Returns false when some object
 * hides part of another (objects may hide only the table). */
bool
keepVisible (const Eigen::Vector3d& camera,
             const std::vector<Primitive>& objects,
             std::vector<std::vector<SurfaceSample>>& samples)
{
  for (std::size_t part = 0; part < samples.size(); ++part) {
    const std::size_t self = part == 0 ? objects.size() : part - 1;
    std::vector<SurfaceSample> visible;
    for (const SurfaceSample& s : samples[part]) {
      if (s.normal.dot (camera - s.point) <= 0.0)
        continue;
      bool hidden = false;
      for (std::size_t j = 0; j < objects.size() && !hidden; ++j)
        hidden = j != self && objects[j].intersects (s.point, camera);
      if (!hidden)
        visible.push_back (s);
      else if (part > 0)
        return false;
    }
    samples[part].swap (visible);
  }
  return true;
}

void
checkTabletopParameters (const TabletopParameters& parameters)
{
  const char* name = "generateTabletopScene";
  if (parameters.num_objects > MAX_TABLETOP_OBJECTS)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         name << ": at most " << MAX_TABLETOP_OBJECTS
                              << " objects, not " << parameters.num_objects);
  checkLength (parameters.table_width, name, "table width");
  checkLength (parameters.table_depth, name, "table depth");
  checkLength (parameters.point_spacing, name, "point spacing");
  checkLength (parameters.min_gap, name, "minimum gap");
  if (parameters.point_spacing > TABLETOP_MAX_POINT_SPACING)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         name << ": point spacing must be at most "
                              << TABLETOP_MAX_POINT_SPACING << " m, not "
                              << parameters.point_spacing);
  const double table_samples =
      static_cast<double> (parameters.table_width) * parameters.table_depth /
      (static_cast<double> (parameters.point_spacing) * parameters.point_spacing);
  if (table_samples > MAX_TABLE_SAMPLES)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         name << ": point spacing " << parameters.point_spacing
                              << " m gives " << table_samples
                              << " table points, more than " << MAX_TABLE_SAMPLES);
  checkNonNegative (parameters.noise_sigma, name, "noise sigma");
  checkNonNegative (parameters.colour_noise, name, "colour noise");
  if (!(parameters.dropout >= 0.0f && parameters.dropout < 1.0f))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         name << ": dropout must be in [0, 1), not "
                              << parameters.dropout);
  if (!parameters.camera_position.allFinite() ||
      parameters.camera_position.z() <= MAX_OBJECT_HEIGHT)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         name << ": the camera must be above the objects (z > "
                              << MAX_OBJECT_HEIGHT
                              << " m), not at z = " << parameters.camera_position.z());
}

std::uint8_t
noisyChannel (std::uint8_t value, double sigma, PortableRandom& random)
{
  const double noisy = value + random.truncatedNormal (sigma, COLOUR_NOISE_TRUNCATION);
  return static_cast<std::uint8_t> (std::clamp (std::lround (noisy), 0L, 255L));
}

} // namespace

TabletopScene
generateTabletopScene (const TabletopParameters& parameters)
{
  checkTabletopParameters (parameters);
  PortableRandom random (parameters.seed);
  const double half_width = 0.5 * parameters.table_width;
  const double half_depth = 0.5 * parameters.table_depth;
  const double spacing = parameters.point_spacing;
  const Eigen::Vector3d camera = parameters.camera_position.cast<double>();

  // Bound on the depth noise: the farthest point of the scene from the camera.
  double farthest = 0.0;
  for (const double x : {-half_width, half_width})
    for (const double y : {-half_depth, half_depth})
      for (const double z : {0.0, MAX_OBJECT_HEIGHT})
        farthest = std::max (farthest, (Eigen::Vector3d (x, y, z) - camera).norm());
  const double max_displacement =
      NOISE_TRUNCATION * parameters.noise_sigma * farthest * farthest;
  const double separation = parameters.min_gap + 2.0 * max_displacement;

  std::array<Colour, MAX_TABLETOP_OBJECTS> palette = OBJECT_PALETTE;
  for (std::size_t i = palette.size() - 1; i > 0; --i)
    std::swap (palette[i], palette[random.index (i + 1)]);

  // Lay out the objects until none hides any part of another.
  std::vector<Primitive> objects;
  std::vector<std::vector<SurfaceSample>> samples; // [0] table, [k + 1] object k
  bool accepted = false;
  for (int layout = 0; layout < MAX_LAYOUT_ATTEMPTS && !accepted; ++layout) {
    if (!placeObjects (parameters.num_objects,
                       half_width,
                       half_depth,
                       separation,
                       random,
                       objects))
      continue;
    samples.assign (1, {});
    sampleRectangle (Eigen::Vector3d (-half_width, -half_depth, 0.0),
                     Eigen::Vector3d (parameters.table_width, 0.0, 0.0),
                     Eigen::Vector3d (0.0, parameters.table_depth, 0.0),
                     Eigen::Vector3d::UnitZ(),
                     spacing,
                     random,
                     samples[0]);
    samples[0].erase (std::remove_if (samples[0].begin(),
                                      samples[0].end(),
                                      [&] (const SurfaceSample& s) {
                                        return std::any_of (objects.begin(),
                                                            objects.end(),
                                                            [&] (const Primitive& o) {
                                                              return o.covers (s.point);
                                                            });
                                      }),
                      samples[0].end());
    for (const Primitive& object : objects)
      samples.push_back (object.sample (spacing, random));
    accepted = !parameters.visible_only || keepVisible (camera, objects, samples);
  }
  if (!accepted)
    PCL_THROW_EXCEPTION (
        pcl::BadArgumentException,
        "generateTabletopScene: cannot lay out "
            << parameters.num_objects << " objects on a " << parameters.table_width
            << " x " << parameters.table_depth << " m table with gaps of " << separation
            << " m (min gap plus noise) and none hiding another; use fewer objects, a "
               "larger table or less noise");

  // Colour regions: one part per object unless painted. A slot is a part of the
  // table or of an object, numbered through the scene; the regions are the slots
  // with points.
  std::vector<Painting> paintings (objects.size());
  std::vector<std::vector<std::size_t>> parts (samples.size());
  if (parameters.colour_regions)
    paintObjects (objects, samples, parameters.seed, paintings, parts);
  else
    for (std::size_t k = 0; k < objects.size(); ++k) {
      paintings[k].colours = {palette[k]};
      parts[k + 1].assign (samples[k + 1].size(), 0);
    }
  parts[0].assign (samples[0].size(), 0);
  std::vector<TabletopColourRegion> slots (1);
  slots[0].r = TABLE_COLOUR[0];
  slots[0].g = TABLE_COLOUR[1];
  slots[0].b = TABLE_COLOUR[2];
  std::vector<std::size_t> first_slot (samples.size(), 0);
  for (std::size_t k = 0; k < objects.size(); ++k) {
    first_slot[k + 1] = slots.size();
    for (std::size_t part = 0; part < paintings[k].parts; ++part) {
      TabletopColourRegion slot;
      slot.object_label = FIRST_OBJECT_LABEL + static_cast<std::uint32_t> (k);
      slot.part = static_cast<std::uint32_t> (part);
      slot.r = paintings[k].colours[part][0];
      slot.g = paintings[k].colours[part][1];
      slot.b = paintings[k].colours[part][2];
      slots.push_back (slot);
    }
  }
  std::vector<std::size_t> point_slots;

  TabletopScene scene;
  scene.cloud.reset (new pcl::PointCloud<pcl::PointXYZRGBL>);
  scene.cloud->sensor_origin_ = Eigen::Vector4f (parameters.camera_position.x(),
                                                 parameters.camera_position.y(),
                                                 parameters.camera_position.z(),
                                                 0.0f);
  scene.table_r = TABLE_COLOUR[0];
  scene.table_g = TABLE_COLOUR[1];
  scene.table_b = TABLE_COLOUR[2];
  scene.max_noise_displacement = static_cast<float> (max_displacement);
  for (std::size_t part = 0; part < samples.size(); ++part) {
    const std::uint32_t label =
        part == 0 ? TABLE_LABEL
                  : FIRST_OBJECT_LABEL + static_cast<std::uint32_t> (part - 1);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < samples[part].size(); ++i) {
      const SurfaceSample& s = samples[part][i];
      if (random.uniform() < parameters.dropout)
        continue;
      const std::size_t slot = first_slot[part] + parts[part][i];
      const Colour colour = {slots[slot].r, slots[slot].g, slots[slot].b};
      const Eigen::Vector3d ray = s.point - camera;
      const double distance = ray.norm();
      const double sigma = parameters.noise_sigma * distance * distance;
      const Eigen::Vector3d q =
          s.point + random.truncatedNormal (sigma, NOISE_TRUNCATION) * ray / distance;
      pcl::PointXYZRGBL point;
      point.x = static_cast<float> (q.x());
      point.y = static_cast<float> (q.y());
      point.z = static_cast<float> (q.z());
      point.r = noisyChannel (colour[0], parameters.colour_noise, random);
      point.g = noisyChannel (colour[1], parameters.colour_noise, random);
      point.b = noisyChannel (colour[2], parameters.colour_noise, random);
      point.label = label;
      scene.cloud->push_back (point);
      point_slots.push_back (slot);
      ++kept;
    }
    if (part == 0) {
      scene.num_table_points = kept;
      continue;
    }
    const Primitive& object = objects[part - 1];
    TabletopObject truth;
    truth.type = object.type;
    truth.label = label;
    truth.centre = object.centre.cast<float>();
    truth.dimensions = (2.0 * object.half).cast<float>();
    truth.yaw = static_cast<float> (object.yaw);
    truth.r = paintings[part - 1].colours[0][0];
    truth.g = paintings[part - 1].colours[0][1];
    truth.b = paintings[part - 1].colours[0][2];
    truth.num_points = kept;
    scene.objects.push_back (truth);
  }

  // Regions: the table, then the slots with points, labelled in slot order.
  for (const std::size_t slot : point_slots)
    ++slots[slot].num_points;
  std::vector<std::uint32_t> slot_labels (slots.size(), 0);
  for (std::size_t slot = 0; slot < slots.size(); ++slot)
    if (slot == 0 || slots[slot].num_points > 0) {
      slot_labels[slot] = static_cast<std::uint32_t> (scene.regions.size()) + 1;
      scene.regions.push_back (slots[slot]);
      scene.regions.back().label = slot_labels[slot];
    }
  scene.region_labels.reserve (point_slots.size());
  for (const std::size_t slot : point_slots)
    scene.region_labels.push_back (slot_labels[slot]);
  for (std::size_t k = 0; k < objects.size(); ++k)
    for (const auto& [a, b] : paintings[k].similar) {
      const std::uint32_t label_a = slot_labels[first_slot[k + 1] + a];
      const std::uint32_t label_b = slot_labels[first_slot[k + 1] + b];
      if (label_a != 0 && label_b != 0)
        scene.similar_regions.emplace_back (std::min (label_a, label_b),
                                            std::max (label_a, label_b));
    }
  std::sort (scene.similar_regions.begin(), scene.similar_regions.end());
  return scene;
}

pcl::PointCloud<pcl::PointXYZRGBL>::Ptr
regionLabelledCloud (const TabletopScene& scene)
{
  pcl::PointCloud<pcl::PointXYZRGBL>::Ptr cloud (
      new pcl::PointCloud<pcl::PointXYZRGBL> (*scene.cloud));
  for (std::size_t i = 0; i < cloud->size() && i < scene.region_labels.size(); ++i)
    (*cloud)[i].label = scene.region_labels[i];
  return cloud;
}

} // namespace tda
} // namespace pcl
