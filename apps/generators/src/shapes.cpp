#include <pcl/tda/generators/parameter_checks.h>
#include <pcl/tda/generators/random_sampling.h>
#include <pcl/tda/generators/shapes.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace pcl {
namespace tda {
namespace {

/** suggested_radius = RADIUS_PER_SPACING * h + RADIUS_PER_SIGMA * sigma, where h is
 * the sampling cell size (arc length per point on the circle, square root of the
 * area per point on surfaces). Calibrated with Ripser (see the tests). */
constexpr double RADIUS_PER_SPACING = 4.0;
constexpr double RADIUS_PER_SIGMA = 7.0;

using Colour = std::array<std::uint8_t, 3>;
const Colour CIRCLE_COLOUR = {40, 80, 210};
const Colour TORUS_COLOUR = {250, 140, 20};
const Colour SPHERE_COLOUR = {40, 170, 60};

void
checkShapeArguments (std::size_t num_points, float noise_sigma, const char* name)
{
  if (num_points == 0)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         name << ": the number of points must be positive");
  checkNonNegative (noise_sigma, name, "noise sigma");
}

/** The suggested Vietoris-Rips radius for cell size h and noise sigma; throws when
 * it exceeds the largest radius at which the shape's holes certainly survive. */
float
suggestedRadius (double h, double sigma, double limit, const char* name)
{
  const double radius = RADIUS_PER_SPACING * h + RADIUS_PER_SIGMA * sigma;
  if (radius > limit)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         name << ": too few points or too much noise for the shape "
                                 "(the Vietoris-Rips radius needed, "
                              << radius << ", exceeds " << limit
                              << "); add points or lower the noise");
  return static_cast<float> (radius);
}

/** Moves the samples by truncated Gaussian noise and stores them as one shape. */
SyntheticShape
makeShape (const std::vector<Eigen::Vector3d>& points,
           double sigma,
           PortableRandom& random,
           const Colour& colour,
           int beta0,
           int beta1,
           float suggested_radius)
{
  SyntheticShape shape;
  shape.cloud.reset (new pcl::PointCloud<pcl::PointXYZRGBL>);
  shape.cloud->reserve (points.size());
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3d q = p + random.truncatedNormal3 (sigma);
    pcl::PointXYZRGBL point;
    point.x = static_cast<float> (q.x());
    point.y = static_cast<float> (q.y());
    point.z = static_cast<float> (q.z());
    point.r = colour[0];
    point.g = colour[1];
    point.b = colour[2];
    point.label = SHAPE_LABEL;
    shape.cloud->push_back (point);
  }
  shape.beta0 = beta0;
  shape.beta1 = beta1;
  shape.suggested_radius = suggested_radius;
  return shape;
}

} // namespace

SyntheticShape
generateCircle (const CircleParameters& parameters)
{
  const char* name = "generateCircle";
  checkShapeArguments (parameters.num_points, parameters.noise_sigma, name);
  checkLength (parameters.radius, name, "radius");
  const double radius = parameters.radius;
  const std::size_t n = parameters.num_points;
  const float suggested = suggestedRadius (
      2.0 * M_PI * radius / n, parameters.noise_sigma, radius / 2.0, name);

  PortableRandom random (parameters.seed);
  std::vector<Eigen::Vector3d> points (n);
  for (std::size_t i = 0; i < n; ++i) {
    const double theta = 2.0 * M_PI * (i + random.uniform()) / n;
    points[i] =
        Eigen::Vector3d (radius * std::cos (theta), radius * std::sin (theta), 0.0);
  }
  return makeShape (
      points, parameters.noise_sigma, random, CIRCLE_COLOUR, 1, 1, suggested);
}

SyntheticShape
generateTorus (const TorusParameters& parameters)
{
  const char* name = "generateTorus";
  checkShapeArguments (parameters.num_points, parameters.noise_sigma, name);
  checkLength (parameters.major_radius, name, "major radius");
  checkLength (parameters.minor_radius, name, "minor radius");
  if (parameters.minor_radius >= parameters.major_radius)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         name << ": the minor radius (" << parameters.minor_radius
                              << ") must be below the major radius ("
                              << parameters.major_radius << ")");
  const double big = parameters.major_radius;
  const double small = parameters.minor_radius;
  const std::size_t n = parameters.num_points;
  const double h = std::sqrt (4.0 * M_PI * M_PI * big * small / n);
  const float suggested =
      suggestedRadius (h, parameters.noise_sigma, std::min (small, big - small), name);

  PortableRandom random (parameters.seed);
  std::vector<Eigen::Vector3d> points;
  points.reserve (n);
  for (const SurfaceSample& sample : sampleTorus (big, small, n, random))
    points.push_back (sample.point);
  return makeShape (
      points, parameters.noise_sigma, random, TORUS_COLOUR, 1, 2, suggested);
}

SyntheticShape
generateSphere (const SphereParameters& parameters)
{
  const char* name = "generateSphere";
  checkShapeArguments (parameters.num_points, parameters.noise_sigma, name);
  checkLength (parameters.radius, name, "radius");
  const double radius = parameters.radius;
  const std::size_t n = parameters.num_points;
  const double h = std::sqrt (4.0 * M_PI * radius * radius / n);
  const float suggested =
      suggestedRadius (h, parameters.noise_sigma, radius / 2.0, name);

  PortableRandom random (parameters.seed);
  std::vector<Eigen::Vector3d> points;
  points.reserve (n);
  for (const SurfaceSample& sample : sampleSphere (radius, n, random))
    points.push_back (sample.point);
  return makeShape (
      points, parameters.noise_sigma, random, SPHERE_COLOUR, 1, 0, suggested);
}

} // namespace tda
} // namespace pcl
