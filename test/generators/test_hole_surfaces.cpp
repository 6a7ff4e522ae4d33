// Tests of the surfaces with round holes: determinism, no point left inside a hole,
// rim and border labels against distances computed here from the surfaces'
// definitions, rim sizes against the band areas, spacing, noise, random removal and
// refused parameters.

#include <pcl/tda/generators/hole_surfaces.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include "generators/generator_test_utils.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <vector>

using pcl::tda::HoleSurface;
using pcl::tda::HoleSurfaceKind;
using pcl::tda::HoleSurfaceParameters;
using pcl::tda::OUTER_BORDER_LABEL;
using pcl::tda::SURFACE_LABEL;
using pcl::tda::test::identical;
using Hole = pcl::tda::HoleSurface::Hole;

namespace {

const std::vector<HoleSurfaceKind> KINDS = {HoleSurfaceKind::PLANE,
                                            HoleSurfaceKind::SPHERE,
                                            HoleSurfaceKind::CYLINDER,
                                            HoleSurfaceKind::TORUS,
                                            HoleSurfaceKind::HEIGHT_FIELD};

const std::vector<std::uint64_t> SEEDS = {0, 1, 2, 7, 12345};

constexpr double INF = std::numeric_limits<double>::infinity();

bool
isOpen (HoleSurfaceKind kind)
{
  return kind == HoleSurfaceKind::PLANE || kind == HoleSurfaceKind::CYLINDER ||
         kind == HoleSurfaceKind::HEIGHT_FIELD;
}

/** The height field's z and gradient, from its definition. */
double
fieldHeight (double x, double y)
{
  const double k = 2.0 * M_PI / pcl::tda::HEIGHT_FIELD_WAVELENGTH;
  return pcl::tda::HEIGHT_FIELD_AMPLITUDE * std::sin (k * x) * std::sin (k * y);
}

Eigen::Vector2d
fieldGradient (double x, double y)
{
  const double k = 2.0 * M_PI / pcl::tda::HEIGHT_FIELD_WAVELENGTH;
  const double ak = pcl::tda::HEIGHT_FIELD_AMPLITUDE * k;
  return {ak * std::cos (k * x) * std::sin (k * y),
          ak * std::sin (k * x) * std::cos (k * y)};
}

/** Radius of the xy disk of a height field hole. */
double
fieldDiskRadius (const Hole& hole)
{
  return hole.radius *
         std::pow (1.0 + fieldGradient (hole.center.x(), hole.center.y()).squaredNorm(),
                   -0.25);
}

/** The distance of the (noise-free) point \a p to the edge of \a hole, measured as
 * documented for each surface; negative inside. */
double
edgeDistance (HoleSurfaceKind kind, const Hole& hole, const Eigen::Vector3d& p)
{
  const Eigen::Vector3d c = hole.center.cast<double>();
  switch (kind) {
  case HoleSurfaceKind::PLANE:
  case HoleSurfaceKind::TORUS:
    return (p - c).norm() - hole.radius;
  case HoleSurfaceKind::SPHERE: {
    const double angle = std::atan2 (p.cross (c).norm(), p.dot (c));
    return pcl::tda::HOLE_SPHERE_RADIUS * angle - hole.radius;
  }
  case HoleSurfaceKind::CYLINDER: {
    double angle = std::abs (std::atan2 (p.y(), p.x()) - std::atan2 (c.y(), c.x()));
    angle = std::min (angle, 2.0 * M_PI - angle);
    return std::hypot (pcl::tda::HOLE_CYLINDER_RADIUS * angle, p.z() - c.z()) -
           hole.radius;
  }
  case HoleSurfaceKind::HEIGHT_FIELD: {
    const Eigen::Vector2d offset = p.head<2>() - c.head<2>();
    const double slope = fieldGradient (p.x(), p.y()).dot (offset.normalized());
    return (offset.norm() - fieldDiskRadius (hole)) * std::sqrt (1.0 + slope * slope);
  }
  }
  return 0.0;
}

/** The distance of the point \a p to the outer border; infinite on closed
 * surfaces. */
double
borderDistance (HoleSurfaceKind kind, const Eigen::Vector3d& p)
{
  const double half = pcl::tda::HOLE_PLANE_SIDE / 2.0;
  switch (kind) {
  case HoleSurfaceKind::PLANE:
    return half - std::max (std::abs (p.x()), std::abs (p.y()));
  case HoleSurfaceKind::CYLINDER:
    return pcl::tda::HOLE_CYLINDER_HEIGHT / 2.0 - std::abs (p.z());
  case HoleSurfaceKind::HEIGHT_FIELD: {
    const Eigen::Vector2d g = fieldGradient (p.x(), p.y());
    return std::min ((half - std::abs (p.x())) * std::hypot (1.0, g.x()),
                     (half - std::abs (p.y())) * std::hypot (1.0, g.y()));
  }
  default:
    return INF;
  }
}

/** Distance of \a p from the surface (0 for a point on it). */
double
offSurface (HoleSurfaceKind kind, const Eigen::Vector3d& p)
{
  switch (kind) {
  case HoleSurfaceKind::PLANE:
    return std::abs (p.z());
  case HoleSurfaceKind::SPHERE:
    return std::abs (p.norm() - pcl::tda::HOLE_SPHERE_RADIUS);
  case HoleSurfaceKind::CYLINDER:
    return std::abs (p.head<2>().norm() - pcl::tda::HOLE_CYLINDER_RADIUS);
  case HoleSurfaceKind::TORUS:
    return std::abs (
        std::hypot (p.head<2>().norm() - pcl::tda::HOLE_TORUS_MAJOR_RADIUS, p.z()) -
        pcl::tda::HOLE_TORUS_MINOR_RADIUS);
  case HoleSurfaceKind::HEIGHT_FIELD:
    return std::abs (p.z() - fieldHeight (p.x(), p.y()));
  }
  return INF;
}

/** The unit normal of the surface at \a p (outward, or up). */
Eigen::Vector3d
surfaceNormal (HoleSurfaceKind kind, const Eigen::Vector3d& p)
{
  switch (kind) {
  case HoleSurfaceKind::PLANE:
    return Eigen::Vector3d::UnitZ();
  case HoleSurfaceKind::SPHERE:
    return p.normalized();
  case HoleSurfaceKind::CYLINDER:
    return Eigen::Vector3d (p.x(), p.y(), 0.0).normalized();
  case HoleSurfaceKind::TORUS:
    return (p - pcl::tda::HOLE_TORUS_MAJOR_RADIUS *
                    Eigen::Vector3d (p.x(), p.y(), 0.0).normalized())
        .normalized();
  case HoleSurfaceKind::HEIGHT_FIELD: {
    const Eigen::Vector2d g = fieldGradient (p.x(), p.y());
    return Eigen::Vector3d (-g.x(), -g.y(), 1.0).normalized();
  }
  }
  return Eigen::Vector3d::Zero();
}

/** Area of the surface: exact, or by a fine midpoint rule for the height field. */
double
surfaceArea (HoleSurfaceKind kind)
{
  switch (kind) {
  case HoleSurfaceKind::PLANE:
    return 1.0;
  case HoleSurfaceKind::SPHERE:
    return M_PI;
  case HoleSurfaceKind::CYLINDER:
    return 2.0 * M_PI * 0.3;
  case HoleSurfaceKind::TORUS:
    return 4.0 * M_PI * M_PI * 0.5 * 0.2;
  case HoleSurfaceKind::HEIGHT_FIELD: {
    const int cells = 700;
    double sum = 0.0;
    for (int i = 0; i < cells; ++i)
      for (int j = 0; j < cells; ++j)
        sum += std::sqrt (
            1.0 + fieldGradient ((i + 0.5) / cells - 0.5, (j + 0.5) / cells - 0.5)
                      .squaredNorm());
    return sum / (cells * cells);
  }
  }
  return 0.0;
}

HoleSurface
generate (HoleSurfaceKind kind,
          std::uint64_t seed,
          float noise = 0.0f,
          float removal = 0.0f,
          std::vector<float> radii = HoleSurfaceParameters().hole_radii)
{
  HoleSurfaceParameters parameters;
  parameters.kind = kind;
  parameters.seed = seed;
  parameters.noise_sigma = noise;
  parameters.removal_fraction = removal;
  parameters.hole_radii = std::move (radii);
  return pcl::tda::generateHoleSurface (parameters);
}

std::string
traceName (HoleSurfaceKind kind, std::uint64_t seed)
{
  return std::string (pcl::tda::holeSurfaceKindName (kind)) + ", seed " +
         std::to_string (seed);
}

} // namespace

TEST (HoleSurfaces, SameSeedGivesIdenticalSurfacesAndOtherSeedsDiffer)
{
  for (const HoleSurfaceKind kind : KINDS)
    for (const std::uint64_t seed : {0u, 3u}) {
      SCOPED_TRACE (traceName (kind, seed));
      const HoleSurface a = generate (kind, seed, 0.1f, 0.2f);
      const HoleSurface b = generate (kind, seed, 0.1f, 0.2f);
      const HoleSurface c = generate (kind, seed + 1, 0.1f, 0.2f);
      EXPECT_TRUE (identical (*a.cloud, *b.cloud));
      EXPECT_FALSE (a.removed->empty());
      EXPECT_TRUE (identical (*a.removed, *b.removed));
      ASSERT_EQ (a.holes.size(), b.holes.size());
      for (std::size_t i = 0; i < a.holes.size(); ++i)
        EXPECT_EQ (a.holes[i].center, b.holes[i].center);
      EXPECT_EQ (a.spacing, b.spacing);
      EXPECT_FALSE (identical (*a.cloud, *c.cloud));
    }
}

TEST (HoleSurfaces, LabelsMatchTheDistancesToHolesAndBorder)
{
  const HoleSurfaceParameters defaults;
  for (const HoleSurfaceKind kind : KINDS)
    for (const std::uint64_t seed : SEEDS) {
      SCOPED_TRACE (traceName (kind, seed));
      const HoleSurface s = generate (kind, seed);
      const double h = s.spacing;
      const double band = defaults.band_width * h;
      const double eps = 1e-3 * h; // float coordinates
      ASSERT_EQ (defaults.hole_radii.size(), s.holes.size());
      EXPECT_EQ (!isOpen (kind), s.closed);
      EXPECT_TRUE (s.removed->empty());
      EXPECT_EQ (s.cloud->size(), std::size_t (s.cloud->width) * s.cloud->height);
      std::map<std::uint32_t, std::size_t> counts;
      for (const pcl::PointXYZL& point : *s.cloud) {
        const Eigen::Vector3d p = point.getVector3fMap().cast<double>();
        ASSERT_LT (offSurface (kind, p), 1e-5);
        ++counts[point.label];
        for (std::size_t i = 0; i < s.holes.size(); ++i) {
          const double edge = edgeDistance (kind, s.holes[i], p);
          ASSERT_GT (edge, -eps) << "a point inside hole " << i + 1;
          if (point.label == i + 1)
            ASSERT_LE (edge, band + eps) << "hole " << i + 1;
          else
            ASSERT_GT (edge, band - eps) << "label " << point.label;
        }
        const double border = borderDistance (kind, p);
        if (point.label == OUTER_BORDER_LABEL)
          ASSERT_LE (border, band + eps);
        else if (point.label == SURFACE_LABEL)
          ASSERT_GT (border, band - eps);
        else
          ASSERT_LE (point.label, s.holes.size());
      }
      for (std::uint32_t label = 1; label <= s.holes.size(); ++label)
        EXPECT_GT (counts[label], 0u) << "the rim of hole " << label;
      EXPECT_EQ (isOpen (kind), counts.count (OUTER_BORDER_LABEL) == 1);
    }
}

TEST (HoleSurfaces, CutSamplesLieInTheirHolesOnTheSurface)
{
  const HoleSurfaceParameters defaults;
  for (const HoleSurfaceKind kind : KINDS)
    for (const std::uint64_t seed : SEEDS) {
      SCOPED_TRACE (traceName (kind, seed));
      const HoleSurface s = generate (kind, seed, 0.1f);
      const double eps = 1e-3 * s.spacing;
      // Every sample is kept or cut (no removal here).
      EXPECT_EQ (s.cloud->size() + s.cut->size(), defaults.num_points);
      std::vector<std::size_t> per_hole (s.holes.size(), 0);
      for (const pcl::PointXYZL& point : *s.cut) {
        const Eigen::Vector3d p = point.getVector3fMap().cast<double>();
        ASSERT_LT (offSurface (kind, p), 1e-5); // noise-free
        ASSERT_GE (point.label, 1u);
        ASSERT_LE (point.label, s.holes.size());
        ASSERT_LE (edgeDistance (kind, s.holes[point.label - 1], p), eps);
        ++per_hole[point.label - 1];
      }
      for (const std::size_t count : per_hole)
        EXPECT_GT (count, 0u);
    }
}

TEST (HoleSurfaces, HolesLieOnTheSurfaceApartAndAwayFromTheBorder)
{
  const HoleSurfaceParameters defaults;
  for (const HoleSurfaceKind kind : KINDS)
    for (const std::uint64_t seed : SEEDS) {
      SCOPED_TRACE (traceName (kind, seed));
      const HoleSurface s = generate (kind, seed);
      const double h = s.spacing, gap = pcl::tda::HOLE_GAP * h, eps = 1e-4 * h;
      for (std::size_t i = 0; i < s.holes.size(); ++i) {
        const Hole& hole = s.holes[i];
        const Eigen::Vector3d c = hole.center.cast<double>();
        EXPECT_LT (offSurface (kind, c), 1e-6);
        EXPECT_NEAR (1.0, hole.normal.norm(), 1e-6);
        EXPECT_NEAR (
            1.0, hole.normal.cast<double>().dot (surfaceNormal (kind, c)), 1e-6);
        EXPECT_FLOAT_EQ (defaults.hole_radii[i] * s.spacing, hole.radius);
        const bool field = kind == HoleSurfaceKind::HEIGHT_FIELD;
        const double radius = field ? fieldDiskRadius (hole) : hole.radius;
        if (isOpen (kind)) {
          // xy distances on the height field are shorter than along the surface.
          const double border = field ? 0.5 - c.head<2>().cwiseAbs().maxCoeff()
                                      : borderDistance (kind, c);
          EXPECT_GE (border - radius, gap - eps);
        }
        if (kind == HoleSurfaceKind::TORUS) {
          const double rho = c.head<2>().norm();
          EXPECT_GT (rho, pcl::tda::HOLE_TORUS_MAJOR_RADIUS); // the outer half
          EXPECT_GE (std::hypot (rho - pcl::tda::HOLE_TORUS_MAJOR_RADIUS,
                                 pcl::tda::HOLE_TORUS_MINOR_RADIUS - std::abs (c.z())) -
                         hole.radius,
                     gap - eps);
        }
        for (std::size_t j = 0; j < i; ++j) {
          const Hole& other = s.holes[j];
          const double apart =
              field ? (c.head<2>() - other.center.cast<double>().head<2>()).norm() -
                          radius - fieldDiskRadius (other)
                    : edgeDistance (kind, hole, other.center.cast<double>()) -
                          other.radius;
          EXPECT_GE (apart, gap - eps) << "holes " << j + 1 << " and " << i + 1;
        }
      }
    }
}

TEST (HoleSurfaces, RimsAndHolesHaveTheSizesOfTheirAreas)
{
  const HoleSurfaceParameters defaults;
  const std::vector<float> radii = {4.0f, 7.0f, 10.0f};
  for (const HoleSurfaceKind kind : KINDS)
    for (const std::uint64_t seed : SEEDS) {
      SCOPED_TRACE (traceName (kind, seed));
      const HoleSurface s = generate (kind, seed, 0.0f, 0.0f, radii);
      const double h = s.spacing, band = defaults.band_width * h;
      std::map<std::uint32_t, std::size_t> counts;
      for (const pcl::PointXYZL& point : *s.cloud)
        ++counts[point.label];
      // A rim band is an annulus of width band: a point per h x h of its area (flat
      // formula; the surfaces bend little over a hole). Over 60 seeds a single rim
      // is within 20% of it, all three within 10%, the holes within 6%.
      double hole_area = 0.0, rim_points = 0.0, rim_expected = 0.0;
      for (std::size_t i = 0; i < s.holes.size(); ++i) {
        const double rho = s.holes[i].radius;
        const double expected = M_PI * (2.0 * rho * band + band * band) / (h * h);
        const double points = counts[static_cast<std::uint32_t> (i + 1)];
        EXPECT_GT (points / expected, 0.7) << "hole " << i + 1;
        EXPECT_LT (points / expected, 1.3) << "hole " << i + 1;
        rim_points += points;
        rim_expected += expected;
        hole_area += M_PI * rho * rho;
      }
      EXPECT_NEAR (1.0, rim_points / rim_expected, 0.1);
      const double cut = static_cast<double> (defaults.num_points) -
                         static_cast<double> (s.cloud->size());
      EXPECT_NEAR (1.0, cut / (hole_area / (h * h)), 0.08);
      if (kind == HoleSurfaceKind::PLANE) {
        // The border band: the square's perimeter times the band, corners once.
        const double expected = (4.0 * band - 4.0 * band * band) / (h * h);
        EXPECT_NEAR (1.0, counts[OUTER_BORDER_LABEL] / expected, 0.05);
      }
    }
}

TEST (HoleSurfaces, SpacingIsTheSquareRootOfTheAreaPerPoint)
{
  for (const HoleSurfaceKind kind : KINDS)
    for (const std::size_t n :
         {std::size_t (5000), std::size_t (20000), std::size_t (60000)}) {
      SCOPED_TRACE (traceName (kind, n));
      HoleSurfaceParameters parameters;
      parameters.kind = kind;
      parameters.num_points = n;
      parameters.hole_radii.clear();
      const HoleSurface s = pcl::tda::generateHoleSurface (parameters);
      EXPECT_NEAR (std::sqrt (surfaceArea (kind) / n), s.spacing, 1e-4 * s.spacing);
      EXPECT_EQ (n, s.cloud->size()); // no holes: every point kept
      EXPECT_TRUE (s.holes.empty());
    }
}

TEST (HoleSurfaces, SamplingIsAreaUniformWithoutLargeGaps)
{
  // The height field's points in cells of an xy grid against each cell's area on
  // the surface (which varies by up to 18%).
  HoleSurfaceParameters parameters;
  parameters.kind = HoleSurfaceKind::HEIGHT_FIELD;
  parameters.num_points = 40000;
  parameters.hole_radii.clear();
  const HoleSurface s = pcl::tda::generateHoleSurface (parameters);
  const int cells = 10; // cells of 0.1 x 0.1: about 400 points each
  std::vector<double> counts (cells * cells, 0.0), areas (cells * cells, 0.0);
  for (const pcl::PointXYZL& p : *s.cloud) {
    const int i = std::min (cells - 1, static_cast<int> ((p.x + 0.5) * cells));
    const int j = std::min (cells - 1, static_cast<int> ((p.y + 0.5) * cells));
    counts[i * cells + j] += 1.0;
  }
  const int fine = 50;
  for (int i = 0; i < cells * fine; ++i)
    for (int j = 0; j < cells * fine; ++j) {
      const double x = (i + 0.5) / (cells * fine) - 0.5,
                   y = (j + 0.5) / (cells * fine) - 0.5;
      areas[(i / fine) * cells + j / fine] +=
          std::sqrt (1.0 + fieldGradient (x, y).squaredNorm());
    }
  const double total = surfaceArea (HoleSurfaceKind::HEIGHT_FIELD);
  for (int k = 0; k < cells * cells; ++k) {
    const double expected =
        areas[k] / (fine * fine * cells * cells) / total * parameters.num_points;
    EXPECT_NEAR (1.0, counts[k] / expected, 0.05) << "cell " << k;
  }
  // No large gaps: every point of the plane has a sample within 1.5 h (a jittered
  // grid of cells of about h x h leaves at most one cell diagonal, 1.41 h).
  parameters.kind = HoleSurfaceKind::PLANE;
  parameters.num_points = 5000;
  const HoleSurface plane = pcl::tda::generateHoleSurface (parameters);
  const double h = plane.spacing;
  const int side = static_cast<int> (std::ceil (1.0 / h));
  std::vector<std::vector<Eigen::Vector2d>> buckets (side * side);
  const auto bucket = [side, h] (double v) {
    return std::clamp (static_cast<int> ((v + 0.5) / h), 0, side - 1);
  };
  for (const pcl::PointXYZL& p : *plane.cloud)
    buckets[bucket (p.x) * side + bucket (p.y)].emplace_back (p.x, p.y);
  double largest = 0.0;
  for (double x = -0.5; x <= 0.5; x += 0.2 * h)
    for (double y = -0.5; y <= 0.5; y += 0.2 * h) {
      double nearest = INF;
      for (int i = bucket (x) - 2; i <= bucket (x) + 2; ++i)
        for (int j = bucket (y) - 2; j <= bucket (y) + 2; ++j)
          if (i >= 0 && j >= 0 && i < side && j < side)
            for (const Eigen::Vector2d& q : buckets[i * side + j])
              nearest = std::min (nearest, (q - Eigen::Vector2d (x, y)).norm());
      largest = std::max (largest, nearest);
    }
  EXPECT_LT (largest, 1.5 * h);
}

TEST (HoleSurfaces, NoiseStaysWithinFourSigmaOfTheSurface)
{
  const float noise = 0.2f;
  for (const HoleSurfaceKind kind : KINDS) {
    SCOPED_TRACE (pcl::tda::holeSurfaceKindName (kind));
    const HoleSurface clean = generate (kind, 4);
    const HoleSurface noisy = generate (kind, 4, noise);
    // Labels come before the noise: the same points, the same labels.
    ASSERT_EQ (clean.cloud->size(), noisy.cloud->size());
    double largest = 0.0, moved = 0.0;
    for (std::size_t i = 0; i < clean.cloud->size(); ++i) {
      ASSERT_EQ ((*clean.cloud)[i].label, (*noisy.cloud)[i].label);
      const Eigen::Vector3f d =
          (*noisy.cloud)[i].getVector3fMap() - (*clean.cloud)[i].getVector3fMap();
      largest = std::max (largest, static_cast<double> (d.norm()));
      moved += d.squaredNorm();
    }
    const double sigma = noise * clean.spacing;
    EXPECT_LE (largest, 4.0 * sigma * (1.0 + 1e-4));
    // The mean squared displacement of a 3D normal is 3 sigma^2 (a bit less when
    // truncated).
    EXPECT_NEAR (3.0, moved / clean.cloud->size() / (sigma * sigma), 0.1);
  }
}

TEST (HoleSurfaces, RandomRemovalTakesTheFractionOfTheCutSurface)
{
  for (const HoleSurfaceKind kind : KINDS)
    for (const float fraction : {0.1f, 0.2f, 0.3f}) {
      SCOPED_TRACE (std::string (pcl::tda::holeSurfaceKindName (kind)) + ", fraction " +
                    std::to_string (fraction));
      const HoleSurface full = generate (kind, 5, 0.05f);
      const HoleSurface thinned = generate (kind, 5, 0.05f, fraction);
      const std::size_t kept = thinned.cloud->size(), removed = thinned.removed->size();
      ASSERT_EQ (full.cloud->size(), kept + removed);
      EXPECT_NEAR (fraction, static_cast<double> (removed) / (kept + removed), 0.01);
      // The kept and removed points are those of the full cloud, in its order.
      std::size_t k = 0, r = 0;
      for (const pcl::PointXYZL& p : *full.cloud) {
        if (k < kept && std::memcmp (p.data, (*thinned.cloud)[k].data, 12) == 0) {
          ASSERT_EQ (p.label, (*thinned.cloud)[k].label);
          ++k;
        }
        else {
          ASSERT_LT (r, removed);
          ASSERT_EQ (0, std::memcmp (p.data, (*thinned.removed)[r].data, 12));
          ++r;
        }
      }
      EXPECT_EQ (kept, k);
      EXPECT_EQ (removed, r);
      // Every rim keeps points.
      std::map<std::uint32_t, std::size_t> counts;
      for (const pcl::PointXYZL& p : *thinned.cloud)
        ++counts[p.label];
      for (std::uint32_t label = 1; label <= thinned.holes.size(); ++label)
        EXPECT_GT (counts[label], 0u);
    }
}

TEST (HoleSurfaces, BadParametersThrow)
{
  const auto throws = [] (const HoleSurfaceParameters& parameters) {
    try {
      pcl::tda::generateHoleSurface (parameters);
    }
    catch (const pcl::BadArgumentException& e) {
      EXPECT_NE (std::string::npos, std::string (e.what()).find ("generateHoleSurface"))
          << e.what();
      return true;
    }
    return false;
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  HoleSurfaceParameters p;
  EXPECT_FALSE (throws (p));
  p.num_points = pcl::tda::MIN_HOLE_SURFACE_POINTS - 1;
  EXPECT_TRUE (throws (p));
  p = {};
  for (const float radius : {-3.0f, 0.0f, 0.5f, nan, inf}) {
    p.hole_radii = {3.0f, radius};
    EXPECT_TRUE (throws (p)) << radius;
  }
  p = {};
  for (const float noise : {-0.1f, 1.0f, 2.0f, nan}) {
    p.noise_sigma = noise;
    EXPECT_TRUE (throws (p)) << noise;
  }
  p = {};
  for (const float removal : {-0.1f, 0.9f, 1.0f, nan}) {
    p.removal_fraction = removal;
    EXPECT_TRUE (throws (p)) << removal;
  }
  p = {};
  for (const float band : {0.0f, -1.5f, nan}) {
    p.band_width = band;
    EXPECT_TRUE (throws (p)) << band;
  }
  p = {};
  p.kind = static_cast<HoleSurfaceKind> (99);
  EXPECT_TRUE (throws (p));
  // Holes that do not fit: one too large, or too many.
  for (const HoleSurfaceKind kind : KINDS) {
    SCOPED_TRACE (pcl::tda::holeSurfaceKindName (kind));
    p = {};
    p.kind = kind;
    p.hole_radii = {200.0f};
    EXPECT_TRUE (throws (p));
    p.hole_radii.assign (200, 10.0f);
    EXPECT_TRUE (throws (p));
  }
}

TEST (HoleSurfaces, KindNamesRoundTrip)
{
  for (const HoleSurfaceKind kind : KINDS) {
    HoleSurfaceKind parsed = HoleSurfaceKind::SPHERE;
    EXPECT_TRUE (
        pcl::tda::parseHoleSurfaceKind (pcl::tda::holeSurfaceKindName (kind), parsed));
    EXPECT_EQ (kind, parsed);
  }
  HoleSurfaceKind kind = HoleSurfaceKind::TORUS;
  EXPECT_FALSE (pcl::tda::parseHoleSurfaceKind ("cube", kind));
  EXPECT_FALSE (pcl::tda::parseHoleSurfaceKind ("Plane", kind));
  EXPECT_EQ (HoleSurfaceKind::TORUS, kind);
}
