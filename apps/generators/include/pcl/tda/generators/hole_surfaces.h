#pragma once

// Surfaces with round holes cut out (plane, sphere, cylinder, torus, height field),
// every point labelled by whether it lies on the rim of a hole or on the surface's
// own border: ground truth for hole boundary point detection and hole filling
// (thesis Ch 5, Sec 5.6).

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Label of a point of a hole surface that is neither on the rim of a hole
 * nor on the surface's outer border. Points on the rim of hole i (0-based) have label
 * i + 1. */
constexpr std::uint32_t SURFACE_LABEL = 0;
/** \brief Label of a point of a hole surface within the band of the surface's own
 * border (open surfaces only) and on the rim of no hole. */
constexpr std::uint32_t OUTER_BORDER_LABEL = 1000000;

/** \brief Fewest points HoleSurfaceParameters::num_points accepts. */
constexpr std::size_t MIN_HOLE_SURFACE_POINTS = 1000;
/** \brief Smallest hole radius, in units of the sampling spacing h: a smaller hole
 * is no larger than the gaps of the sampling itself. */
constexpr float MIN_HOLE_RADIUS = 1.0f;
/** \brief Removal fractions must be below this. */
constexpr float MAX_HOLE_REMOVAL_FRACTION = 0.9f;
/** \brief The default hole radii of HoleSurfaceParameters, in units of h. */
constexpr std::array<float, 3> DEFAULT_HOLE_RADII = {3.0f, 5.0f, 8.0f};
/** \brief Least gap, in units of h, between the edges of two holes and between a
 * hole's edge and the outer border (widened to 2 band_width + 1 for wide bands, so
 * that two bands never touch). */
constexpr float HOLE_GAP = 4.0f;

/** \brief Side of the square of HoleSurfaceKind::PLANE and ::HEIGHT_FIELD. */
constexpr float HOLE_PLANE_SIDE = 1.0f;
/** \brief Radius of HoleSurfaceKind::SPHERE. */
constexpr float HOLE_SPHERE_RADIUS = 0.5f;
/** \brief Radius of HoleSurfaceKind::CYLINDER. */
constexpr float HOLE_CYLINDER_RADIUS = 0.3f;
/** \brief Height of HoleSurfaceKind::CYLINDER. */
constexpr float HOLE_CYLINDER_HEIGHT = 1.0f;
/** \brief Distance from the z axis to the tube centre line of
 * HoleSurfaceKind::TORUS. */
constexpr float HOLE_TORUS_MAJOR_RADIUS = 0.5f;
/** \brief Tube radius of HoleSurfaceKind::TORUS. */
constexpr float HOLE_TORUS_MINOR_RADIUS = 0.2f;
/** \brief Amplitude a of HoleSurfaceKind::HEIGHT_FIELD. */
constexpr float HEIGHT_FIELD_AMPLITUDE = 0.05f;
/** \brief Wavelength w of HoleSurfaceKind::HEIGHT_FIELD. */
constexpr float HEIGHT_FIELD_WAVELENGTH = 0.5f;

/** \brief The surface of a hole surface, and how distances on it are measured (for
 * the holes, their rims and the outer border).
 *
 * Every surface is centred at the origin. */
enum class HoleSurfaceKind {
  /** The square |x|, |y| <= HOLE_PLANE_SIDE / 2 of the plane z = 0; Euclidean
   * distance; outer border: the square's edges. */
  PLANE,
  /** The sphere of radius HOLE_SPHERE_RADIUS; geodesic (great circle) distance;
   * closed. */
  SPHERE,
  /** The open side of the cylinder of radius HOLE_CYLINDER_RADIUS around the z axis,
   * |z| <= HOLE_CYLINDER_HEIGHT / 2; geodesic distance (straight lines on the
   * unrolled side); outer border: the two end circles. */
  CYLINDER,
  /** The torus of radii HOLE_TORUS_MAJOR_RADIUS and HOLE_TORUS_MINOR_RADIUS around
   * the z axis; Euclidean (chord) distance in 3D between points of the surface, which
   * for holes of radius r differs from the geodesic by about r^3 / (24 * 0.2^2) at
   * most, 1.3% at r = 0.11; closed. Holes lie on the outer half (the points farther
   * from the axis than the tube centre line), where the surface is convex. */
  TORUS,
  /** z = a sin(2 pi x / w) sin(2 pi y / w) over the square of PLANE (a =
   * HEIGHT_FIELD_AMPLITUDE, w = HEIGHT_FIELD_WAVELENGTH, slope at most 0.63); outer
   * border: the square's edges. A hole is the set of points whose (x, y) lie in a
   * disk of radius radius (1 + |grad z|^2)^(-1/4) around the centre's (x, y), the
   * gradient taken at the centre, so that its area on the surface is about
   * pi radius^2. The distance of a point to a hole's edge (or to the border) is, to
   * first order, that in the xy plane times the surface's stretch sqrt(1 + (dz/du)^2)
   * in the direction u towards the point, taken at the point. The gaps between
   * holes and to the border are measured in the xy plane (shorter than along the
   * surface). */
  HEIGHT_FIELD
};

/** \brief Parameters of generateHoleSurface().
 *
 * The surface is sampled area-uniformly on a jittered grid (rows of equal width,
 * one point drawn uniformly in each cell of equal area), so it has no large sampling
 * gaps. Its spacing h is sqrt(area / num_points). Then \a hole_radii.size() holes
 * are placed at random: each centre on the surface, at least radius + 4 h (HOLE_GAP)
 * from the edges of the other holes and from the outer border. The points of the
 * holes are removed and the others labelled; then every point is moved by Gaussian
 * noise; then a fraction of the points is removed at random, as in the experiments
 * of thesis Sec 5.6. Equal parameters give identical surfaces. */
struct HoleSurfaceParameters {
  /** \brief The surface and its metric. */
  HoleSurfaceKind kind = HoleSurfaceKind::PLANE;
  /** \brief Number of points sampled before the holes are cut, exactly; it sets the
   * spacing h. At least MIN_HOLE_SURFACE_POINTS. */
  std::size_t num_points = 20000;
  /** \brief Radius of each hole in units of h, at least MIN_HOLE_RADIUS; one hole per
   * entry, none when empty. */
  std::vector<float> hole_radii =
      std::vector<float> (DEFAULT_HOLE_RADII.begin(), DEFAULT_HOLE_RADII.end());
  /** \brief Standard deviation of the Gaussian noise per axis in units of h (0.1 =
   * 10% of a spacing), below 1; the noise is redrawn beyond a length of 4 sigma. */
  float noise_sigma = 0.0f;
  /** \brief Fraction of the points left after cutting the holes that is removed at
   * random (thesis Sec 5.6 uses 0.1, 0.2, 0.3), in [0, MAX_HOLE_REMOVAL_FRACTION). */
  float removal_fraction = 0.0f;
  /** \brief Width of the rim band of a hole and of the outer border's band, in units
   * of h, > 0. */
  float band_width = 1.5f;
  /** \brief Seed of the random generator; equal seeds give identical surfaces. */
  std::uint64_t seed = 0;
};

/** \brief A sampled surface with round holes and the ground truth of its rims. */
struct HoleSurface {
  /** \brief A hole: its centre on the (noise-free) surface, the unit surface normal
   * there (outward on closed surfaces, +z side on the plane and height field) and
   * its radius along the surface (radius in units of h times h). */
  struct Hole {
    Eigen::Vector3f center;
    Eigen::Vector3f normal;
    float radius;
  };

  /** \brief The kept points. A point whose distance to the edge of hole i
   * (0-based), measured on the noise-free surface, is at most band_width * h has
   * label i + 1; else one within band_width * h of the outer border has
   * OUTER_BORDER_LABEL; else SURFACE_LABEL. The noise moves the points after they
   * are labelled. */
  pcl::PointCloud<pcl::PointXYZL>::Ptr cloud;
  /** \brief The points removed at random (HoleSurfaceParameters::removal_fraction)
   * after the noise, for scoring a hole filling; empty when the fraction is 0. */
  pcl::PointCloud<pcl::PointXYZ>::Ptr removed;
  /** \brief The samples the holes cut out, on the noise-free surface, labelled with
   * their hole's number (i + 1): where a hole filling should put its points. */
  pcl::PointCloud<pcl::PointXYZL>::Ptr cut;
  /** \brief The sampling spacing h: sqrt(area / num_points), the square root of
   * the area per point before the holes are cut. */
  float spacing = 0.0f;
  /** \brief The holes in the order of HoleSurfaceParameters::hole_radii; hole i has
   * label i + 1. */
  std::vector<Hole> holes;
  /** \brief True for the surfaces without border (sphere and torus), which have no
   * point labelled OUTER_BORDER_LABEL. */
  bool closed = false;
};

/** \brief Samples a surface, cuts round holes in it at random places and labels the
 * rims (see HoleSurfaceParameters and HoleSurfaceKind).
 * \throws pcl::BadArgumentException on invalid parameters, or when the holes cannot
 * be placed (too many or too large for the surface at this spacing) */
HoleSurface
generateHoleSurface (const HoleSurfaceParameters& parameters);

/** \brief The name of a surface kind as the tools write it: "plane", "sphere",
 * "cylinder", "torus" or "heightfield". */
const char*
holeSurfaceKindName (HoleSurfaceKind kind);

/** \brief Reads a name of holeSurfaceKindName() into \a kind.
 * \return false, \a kind unchanged, for an unknown name */
bool
parseHoleSurfaceKind (const std::string& name, HoleSurfaceKind& kind);

} // namespace tda
} // namespace pcl
