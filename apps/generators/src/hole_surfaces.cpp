#include <pcl/tda/generators/hole_surfaces.h>
#include <pcl/tda/generators/parameter_checks.h>
#include <pcl/tda/generators/random_sampling.h>
#include <pcl/exceptions.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>
#include <utility>

namespace pcl {
namespace tda {
namespace {

const char* const NAME = "generateHoleSurface";

/** Fresh starts of the hole placement, and random centres tried per hole in each:
 * when all fail, the holes do not fit. */
constexpr int PLACEMENT_ROUNDS = 50;
constexpr int TRIES_PER_HOLE = 200;

/** Columns of the table of the area density along a row of a height field, and
 * cells per side of the grid that integrates its area. */
constexpr std::size_t DENSITY_COLUMNS = 1024;
constexpr std::size_t AREA_CELLS = 512;

constexpr double INFINITE_DISTANCE = std::numeric_limits<double>::infinity();

/** A hole being placed: centre and normal on the surface, radius along the surface
 * and, on a height field, the radius of its disk in the xy plane. */
struct PlacedHole {
  Eigen::Vector3d centre;
  Eigen::Vector3d normal;
  double radius = 0.0;
  double xy_radius = 0.0;
};

/** A surface of HoleSurfaceKind: its sampling and its distances. By default the
 * holes are balls of the surface's metric distance(). */
class Surface {
public:
  virtual ~Surface() = default;

  /** Area of the surface. */
  virtual double
  area () const = 0;

  /** Exactly \a count points, area-uniform on a jittered grid, with normals. */
  virtual std::vector<SurfaceSample>
  sample (std::size_t count, PortableRandom& random) const = 0;

  /** A hole of radius \a radius centred at a random point of the surface. */
  virtual PlacedHole
  randomHole (double radius, PortableRandom& random) const = 0;

  /** Distance from \a p (on the surface) to the edge of \a hole, negative inside. */
  virtual double
  edgeDistance (const PlacedHole& hole, const Eigen::Vector3d& p) const
  {
    return distance (hole.centre, p) - hole.radius;
  }

  /** Least distance between the edges of holes \a a and \a b (a lower bound). */
  virtual double
  separation (const PlacedHole& a, const PlacedHole& b) const
  {
    return distance (a.centre, b.centre) - a.radius - b.radius;
  }

  /** Least distance from the edge of \a hole to the outer border or to the limits
   * of where holes may lie (a lower bound); for a closed surface, half the distance
   * from the edge to itself the other way round. */
  virtual double
  clearance (const PlacedHole& hole) const = 0;

  /** Distance from \a p (on the surface) to the outer border; infinite on closed
   * surfaces. */
  virtual double
  borderDistance (const Eigen::Vector3d&) const
  {
    return INFINITE_DISTANCE;
  }

protected:
  /** Distance between two points of the surface in its metric. */
  virtual double
  distance (const Eigen::Vector3d& a, const Eigen::Vector3d& b) const = 0;
};

/** z = a sin(k x) sin(k y) over the square |x|, |y| <= side / 2 (a plane for a = 0).
 * See HoleSurfaceKind::HEIGHT_FIELD for the holes and distances. */
class HeightField : public Surface {
public:
  HeightField (double side, double amplitude, double wavelength)
  : half_ (side / 2.0), amplitude_ (amplitude), wave_number_ (2.0 * M_PI / wavelength)
  {
    area_ = side * side;
    if (amplitude_ == 0.0)
      return;
    // Midpoint rule: spectrally accurate over whole periods of a smooth function.
    const double cell = side / AREA_CELLS;
    double sum = 0.0;
    for (std::size_t i = 0; i < AREA_CELLS; ++i)
      for (std::size_t j = 0; j < AREA_CELLS; ++j)
        sum += areaFactor (-half_ + (i + 0.5) * cell, -half_ + (j + 0.5) * cell);
    area_ = sum * cell * cell;
  }

  double
  area () const override
  {
    return area_;
  }

  /** Rows of equal width in y, each with points in proportion to its area; along a
   * row, cells of equal area (by a table of the area density over x, averaged over
   * the row's width by 2-point Gauss), one point each: x drawn uniformly by area in
   * its cell, y uniformly in the row. */
  std::vector<SurfaceSample>
  sample (std::size_t count, PortableRandom& random) const override
  {
    const double side = 2.0 * half_;
    const std::size_t rows = cellCount (side, std::sqrt (area_ / count));
    const double dy = side / rows, dx = side / DENSITY_COLUMNS;
    const double gauss = dy / (2.0 * std::sqrt (3.0));
    std::vector<std::vector<double>> cumulative (rows);
    std::vector<double> weights (rows);
    for (std::size_t j = 0; j < rows; ++j) {
      const double y = -half_ + (j + 0.5) * dy;
      std::vector<double>& c = cumulative[j];
      c.assign (DENSITY_COLUMNS + 1, 0.0);
      for (std::size_t i = 0; i < DENSITY_COLUMNS; ++i) {
        const double x = -half_ + (i + 0.5) * dx;
        c[i + 1] = c[i] + 0.5 * (areaFactor (x, y - gauss) + areaFactor (x, y + gauss));
      }
      weights[j] = c.back();
    }
    const std::vector<std::size_t> per_row = apportion (weights, count);
    std::vector<SurfaceSample> samples;
    samples.reserve (count);
    for (std::size_t j = 0; j < rows; ++j) {
      const std::vector<double>& c = cumulative[j];
      std::size_t column = 0;
      for (std::size_t k = 0; k < per_row[j]; ++k) {
        const double target = (k + random.uniform()) / per_row[j] * c.back();
        while (column + 1 < DENSITY_COLUMNS && c[column + 1] <= target)
          ++column;
        const double within = (target - c[column]) / (c[column + 1] - c[column]);
        const double x = -half_ + (column + std::min (1.0, within)) * dx;
        const double y = -half_ + (j + random.uniform()) * dy;
        samples.push_back (at (x, y));
      }
    }
    return samples;
  }

  PlacedHole
  randomHole (double radius, PortableRandom& random) const override
  {
    const double x = random.uniform (-half_, half_);
    const double y = random.uniform (-half_, half_);
    const SurfaceSample centre = at (x, y);
    PlacedHole hole{centre.point, centre.normal, radius, radius};
    hole.xy_radius =
        radius * std::pow (1.0 + gradient (x, y).squaredNorm(), -0.25); // area kept
    return hole;
  }

  double
  edgeDistance (const PlacedHole& hole, const Eigen::Vector3d& p) const override
  {
    const Eigen::Vector2d offset = p.head<2>() - hole.centre.head<2>();
    const double length = offset.norm();
    if (length == 0.0)
      return -hole.radius;
    const double slope = gradient (p.x(), p.y()).dot (offset) / length;
    return (length - hole.xy_radius) * std::sqrt (1.0 + slope * slope);
  }

  double
  separation (const PlacedHole& a, const PlacedHole& b) const override
  {
    // In the xy plane: no longer than along the surface.
    return (a.centre.head<2>() - b.centre.head<2>()).norm() - a.xy_radius - b.xy_radius;
  }

  double
  clearance (const PlacedHole& hole) const override
  {
    return half_ - hole.centre.head<2>().cwiseAbs().maxCoeff() - hole.xy_radius;
  }

  double
  borderDistance (const Eigen::Vector3d& p) const override
  {
    const Eigen::Vector2d g = gradient (p.x(), p.y());
    return std::min ((half_ - std::abs (p.x())) * std::sqrt (1.0 + g.x() * g.x()),
                     (half_ - std::abs (p.y())) * std::sqrt (1.0 + g.y() * g.y()));
  }

protected:
  double
  distance (const Eigen::Vector3d& a, const Eigen::Vector3d& b) const override
  {
    return (a.head<2>() - b.head<2>()).norm(); // unused: the holes are xy disks
  }

private:
  Eigen::Vector2d
  gradient (double x, double y) const
  {
    const double ak = amplitude_ * wave_number_;
    return {ak * std::cos (wave_number_ * x) * std::sin (wave_number_ * y),
            ak * std::sin (wave_number_ * x) * std::cos (wave_number_ * y)};
  }

  double
  areaFactor (double x, double y) const
  {
    return std::sqrt (1.0 + gradient (x, y).squaredNorm());
  }

  /** The point of the surface above (x, y) and its upward unit normal. */
  SurfaceSample
  at (double x, double y) const
  {
    const Eigen::Vector2d g = gradient (x, y);
    const double z =
        amplitude_ * std::sin (wave_number_ * x) * std::sin (wave_number_ * y);
    return {Eigen::Vector3d (x, y, z),
            Eigen::Vector3d (-g.x(), -g.y(), 1.0).normalized()};
  }

  double half_, amplitude_, wave_number_, area_;
};

/** The sphere of radius \a radius; geodesic distance. */
class Sphere : public Surface {
public:
  explicit Sphere (double radius) : radius_ (radius) {}

  double
  area () const override
  {
    return 4.0 * M_PI * radius_ * radius_;
  }

  std::vector<SurfaceSample>
  sample (std::size_t count, PortableRandom& random) const override
  {
    return sampleSphere (radius_, count, random);
  }

  PlacedHole
  randomHole (double radius, PortableRandom& random) const override
  {
    const double z = random.uniform (-1.0, 1.0);
    const double theta = random.uniform (0.0, 2.0 * M_PI);
    const double rho = std::sqrt (std::max (0.0, 1.0 - z * z));
    const Eigen::Vector3d n (rho * std::cos (theta), rho * std::sin (theta), z);
    return {radius_ * n, n, radius, radius};
  }

  double
  clearance (const PlacedHole& hole) const override
  {
    return M_PI * radius_ - hole.radius;
  }

protected:
  double
  distance (const Eigen::Vector3d& a, const Eigen::Vector3d& b) const override
  {
    return radius_ * std::atan2 (a.cross (b).norm(), a.dot (b));
  }

private:
  double radius_;
};

/** The open side of the cylinder of radius \a radius around the z axis,
 * |z| <= height / 2; geodesic distance. */
class Cylinder : public Surface {
public:
  Cylinder (double radius, double height) : radius_ (radius), half_ (height / 2.0) {}

  double
  area () const override
  {
    return 4.0 * M_PI * radius_ * half_;
  }

  /** Rings of equal height, equally many points each (so cells of equal area). */
  std::vector<SurfaceSample>
  sample (std::size_t count, PortableRandom& random) const override
  {
    const std::size_t rows = cellCount (2.0 * half_, std::sqrt (area() / count));
    const std::vector<std::size_t> per_row =
        apportion (std::vector<double> (rows, 1.0), count);
    std::vector<SurfaceSample> samples;
    samples.reserve (count);
    for (std::size_t j = 0; j < rows; ++j)
      for (std::size_t k = 0; k < per_row[j]; ++k) {
        const double z = half_ * (2.0 * (j + random.uniform()) / rows - 1.0);
        const double theta = 2.0 * M_PI * (k + random.uniform()) / per_row[j];
        samples.push_back (at (theta, z));
      }
    return samples;
  }

  PlacedHole
  randomHole (double radius, PortableRandom& random) const override
  {
    const double theta = random.uniform (0.0, 2.0 * M_PI);
    const SurfaceSample centre = at (theta, random.uniform (-half_, half_));
    return {centre.point, centre.normal, radius, radius};
  }

  double
  clearance (const PlacedHole& hole) const override
  {
    return std::min (borderDistance (hole.centre), M_PI * radius_) - hole.radius;
  }

  double
  borderDistance (const Eigen::Vector3d& p) const override
  {
    return half_ - std::abs (p.z());
  }

protected:
  double
  distance (const Eigen::Vector3d& a, const Eigen::Vector3d& b) const override
  {
    const double angle =
        std::atan2 (a.x() * b.y() - a.y() * b.x(), a.x() * b.x() + a.y() * b.y());
    return std::hypot (radius_ * angle, a.z() - b.z());
  }

private:
  SurfaceSample
  at (double theta, double z) const
  {
    const Eigen::Vector3d n (std::cos (theta), std::sin (theta), 0.0);
    return {radius_ * n + z * Eigen::Vector3d::UnitZ(), n};
  }

  double radius_, half_;
};

/** The torus of radii \a major and \a minor around the z axis; chord distance;
 * holes on the outer half only. */
class Torus : public Surface {
public:
  Torus (double major, double minor) : major_ (major), minor_ (minor) {}

  double
  area () const override
  {
    return 4.0 * M_PI * M_PI * major_ * minor_;
  }

  std::vector<SurfaceSample>
  sample (std::size_t count, PortableRandom& random) const override
  {
    return sampleTorus (major_, minor_, count, random);
  }

  /** A centre drawn area-uniformly on the outer half. */
  PlacedHole
  randomHole (double radius, PortableRandom& random) const override
  {
    double phi = 0.0;
    do
      phi = random.uniform (-0.5 * M_PI, 0.5 * M_PI);
    while (random.uniform (0.0, major_ + minor_) > major_ + minor_ * std::cos (phi));
    const double theta = random.uniform (0.0, 2.0 * M_PI);
    const Eigen::Vector3d n (std::cos (phi) * std::cos (theta),
                             std::cos (phi) * std::sin (theta),
                             std::sin (phi));
    const Eigen::Vector3d axis (std::cos (theta), std::sin (theta), 0.0);
    return {major_ * axis + minor_ * n, n, radius, radius};
  }

  /** To the circles that bound the outer half (top and bottom of the tube). */
  double
  clearance (const PlacedHole& hole) const override
  {
    const double rho = hole.centre.head<2>().norm();
    const double z = std::abs (hole.centre.z());
    return std::hypot (rho - major_, minor_ - z) - hole.radius;
  }

protected:
  double
  distance (const Eigen::Vector3d& a, const Eigen::Vector3d& b) const override
  {
    return (a - b).norm();
  }

private:
  double major_, minor_;
};

std::unique_ptr<Surface>
makeSurface (HoleSurfaceKind kind)
{
  switch (kind) {
  case HoleSurfaceKind::PLANE:
    return std::make_unique<HeightField> (
        HOLE_PLANE_SIDE, 0.0, HEIGHT_FIELD_WAVELENGTH);
  case HoleSurfaceKind::SPHERE:
    return std::make_unique<Sphere> (HOLE_SPHERE_RADIUS);
  case HoleSurfaceKind::CYLINDER:
    return std::make_unique<Cylinder> (HOLE_CYLINDER_RADIUS, HOLE_CYLINDER_HEIGHT);
  case HoleSurfaceKind::TORUS:
    return std::make_unique<Torus> (HOLE_TORUS_MAJOR_RADIUS, HOLE_TORUS_MINOR_RADIUS);
  case HoleSurfaceKind::HEIGHT_FIELD:
    return std::make_unique<HeightField> (
        HOLE_PLANE_SIDE, HEIGHT_FIELD_AMPLITUDE, HEIGHT_FIELD_WAVELENGTH);
  }
  PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                       NAME << ": unknown surface kind " << static_cast<int> (kind));
}

void
checkHoleSurfaceParameters (const HoleSurfaceParameters& parameters)
{
  if (parameters.num_points < MIN_HOLE_SURFACE_POINTS)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         NAME << ": the number of points must be at least "
                              << MIN_HOLE_SURFACE_POINTS << ", not "
                              << parameters.num_points);
  if (parameters.hole_radii.size() >= OUTER_BORDER_LABEL)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         NAME << ": too many holes (" << parameters.hole_radii.size()
                              << ")");
  for (std::size_t i = 0; i < parameters.hole_radii.size(); ++i) {
    const float radius = parameters.hole_radii[i];
    if (!std::isfinite (radius) || radius < MIN_HOLE_RADIUS)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           NAME << ": hole radius " << i + 1
                                << " must be finite and >= " << MIN_HOLE_RADIUS
                                << " (in units of the spacing), not " << radius);
  }
  checkNonNegative (parameters.noise_sigma, NAME, "noise sigma");
  if (parameters.noise_sigma >= 1.0f)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         NAME << ": noise sigma must be < 1 (in units of the "
                                 "spacing), not "
                              << parameters.noise_sigma);
  checkNonNegative (parameters.removal_fraction, NAME, "removal fraction");
  if (parameters.removal_fraction >= MAX_HOLE_REMOVAL_FRACTION)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         NAME << ": removal fraction must be < "
                              << MAX_HOLE_REMOVAL_FRACTION << ", not "
                              << parameters.removal_fraction);
  checkLength (parameters.band_width, NAME, "band width");
}

/** Places holes of the radii \a radii (absolute) on \a surface at random, each
 * at least \a gap from the others and from the border, the largest first.
 * \throws pcl::BadArgumentException when they do not fit */
std::vector<PlacedHole>
placeHoles (const Surface& surface,
            const std::vector<double>& radii,
            double gap,
            double spacing,
            HoleSurfaceKind kind,
            PortableRandom& random)
{
  std::vector<std::size_t> order (radii.size());
  std::iota (order.begin(), order.end(), 0);
  std::stable_sort (
      order.begin(), order.end(), [&radii] (std::size_t a, std::size_t b) {
        return radii[a] > radii[b];
      });
  std::vector<PlacedHole> holes (radii.size());
  for (int round = 0; round < PLACEMENT_ROUNDS; ++round) {
    std::vector<std::size_t> placed;
    for (const std::size_t i : order) {
      for (int attempt = 0; attempt < TRIES_PER_HOLE; ++attempt) {
        const PlacedHole hole = surface.randomHole (radii[i], random);
        if (surface.clearance (hole) < gap)
          continue;
        if (std::any_of (placed.begin(), placed.end(), [&] (std::size_t j) {
              return surface.separation (hole, holes[j]) < gap;
            }))
          continue;
        holes[i] = hole;
        placed.push_back (i);
        break;
      }
      if (placed.empty() || placed.back() != i)
        break;
    }
    if (placed.size() == radii.size())
      return holes;
  }
  std::ostringstream list;
  for (std::size_t i = 0; i < radii.size(); ++i)
    list << (i == 0 ? "" : ", ") << radii[i] / spacing;
  PCL_THROW_EXCEPTION (
      pcl::BadArgumentException,
      NAME << ": cannot place " << radii.size()
           << (radii.size() == 1 ? " hole of radius " : " holes of radii ")
           << list.str() << " (in units of the spacing h = " << spacing << ") on the "
           << holeSurfaceKindName (kind) << ", " << gap / spacing
           << " h apart and from its border; use fewer or smaller "
              "holes, or more points");
}

} // namespace

const char*
holeSurfaceKindName (HoleSurfaceKind kind)
{
  switch (kind) {
  case HoleSurfaceKind::PLANE:
    return "plane";
  case HoleSurfaceKind::SPHERE:
    return "sphere";
  case HoleSurfaceKind::CYLINDER:
    return "cylinder";
  case HoleSurfaceKind::TORUS:
    return "torus";
  case HoleSurfaceKind::HEIGHT_FIELD:
    return "heightfield";
  }
  return "unknown surface";
}

bool
parseHoleSurfaceKind (const std::string& name, HoleSurfaceKind& kind)
{
  for (const HoleSurfaceKind k : {HoleSurfaceKind::PLANE,
                                  HoleSurfaceKind::SPHERE,
                                  HoleSurfaceKind::CYLINDER,
                                  HoleSurfaceKind::TORUS,
                                  HoleSurfaceKind::HEIGHT_FIELD})
    if (name == holeSurfaceKindName (k)) {
      kind = k;
      return true;
    }
  return false;
}

HoleSurface
generateHoleSurface (const HoleSurfaceParameters& parameters)
{
  checkHoleSurfaceParameters (parameters);
  const std::unique_ptr<Surface> surface = makeSurface (parameters.kind);
  const std::size_t n = parameters.num_points;
  const double h = std::sqrt (surface->area() / n);
  const double band = parameters.band_width * h;
  const double gap = std::max<double> (HOLE_GAP, 2.0 * parameters.band_width + 1.0) * h;
  std::vector<double> radii;
  for (const float radius : parameters.hole_radii)
    radii.push_back (radius * h);

  PortableRandom random (parameters.seed);
  const std::vector<SurfaceSample> samples = surface->sample (n, random);
  const std::vector<PlacedHole> holes =
      placeHoles (*surface, radii, gap, h, parameters.kind, random);

  // Cut and label on the noise-free surface, then add the noise.
  HoleSurface result;
  result.spacing = static_cast<float> (h);
  result.closed = parameters.kind == HoleSurfaceKind::SPHERE ||
                  parameters.kind == HoleSurfaceKind::TORUS;
  for (const PlacedHole& hole : holes)
    result.holes.push_back ({hole.centre.cast<float>(),
                             hole.normal.cast<float>(),
                             static_cast<float> (hole.radius)});
  result.cloud.reset (new pcl::PointCloud<pcl::PointXYZL>);
  result.removed.reset (new pcl::PointCloud<pcl::PointXYZ>);
  result.cut.reset (new pcl::PointCloud<pcl::PointXYZL>);
  pcl::PointCloud<pcl::PointXYZL>& cloud = *result.cloud;
  cloud.reserve (samples.size());
  const double sigma = parameters.noise_sigma * h;
  for (const SurfaceSample& sample : samples) {
    std::uint32_t label = SURFACE_LABEL;
    std::size_t cut_by = holes.size();
    for (std::size_t i = 0; i < holes.size() && cut_by == holes.size(); ++i) {
      const double edge = surface->edgeDistance (holes[i], sample.point);
      if (edge <= 0.0)
        cut_by = i;
      else if (edge <= band && label == SURFACE_LABEL)
        label = static_cast<std::uint32_t> (i + 1);
    }
    if (cut_by < holes.size()) {
      pcl::PointXYZL point;
      point.getVector3fMap() = sample.point.cast<float>();
      point.label = static_cast<std::uint32_t> (cut_by + 1);
      result.cut->push_back (point);
      continue;
    }
    if (label == SURFACE_LABEL && surface->borderDistance (sample.point) <= band)
      label = OUTER_BORDER_LABEL;
    const Eigen::Vector3d q = sample.point + random.truncatedNormal3 (sigma);
    pcl::PointXYZL point;
    point.x = static_cast<float> (q.x());
    point.y = static_cast<float> (q.y());
    point.z = static_cast<float> (q.z());
    point.label = label;
    cloud.push_back (point);
  }

  // Random removal: exactly round(fraction * kept) points, order kept otherwise.
  const std::size_t kept = cloud.size();
  const auto removals = static_cast<std::size_t> (
      std::lround (static_cast<double> (parameters.removal_fraction) * kept));
  if (removals == 0)
    return result;
  std::vector<std::size_t> indices (kept);
  std::iota (indices.begin(), indices.end(), 0);
  std::vector<bool> remove (kept, false);
  for (std::size_t i = 0; i < removals; ++i) {
    std::swap (indices[i], indices[i + random.index (kept - i)]);
    remove[indices[i]] = true;
  }
  pcl::PointCloud<pcl::PointXYZL> remaining;
  remaining.reserve (kept - removals);
  result.removed->reserve (removals);
  for (std::size_t i = 0; i < kept; ++i)
    if (remove[i])
      result.removed->push_back (pcl::PointXYZ (cloud[i].x, cloud[i].y, cloud[i].z));
    else
      remaining.push_back (cloud[i]);
  cloud = std::move (remaining);
  return result;
}

} // namespace tda
} // namespace pcl
