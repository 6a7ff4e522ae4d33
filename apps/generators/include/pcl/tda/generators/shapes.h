#pragma once

// Point clouds sampled from shapes with known topology (circle, torus, sphere): each
// comes with its Betti numbers and a Vietoris-Rips radius at which the complex of
// the cloud has them, as ground truth for the persistence computations.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <cstdint>

namespace pcl {
namespace tda {

/** \brief Label of all points of a synthetic shape. The generators never use label
 * 0, so that it can mean "unlabelled". */
constexpr std::uint32_t SHAPE_LABEL = 1;

/** \brief A sampled shape with known topology: the cloud, the Betti numbers of
 * the shape, and a Vietoris-Rips radius at which the complex of the cloud has them.
 *
 * At \a suggested_radius the Vietoris-Rips complex of \a cloud (edges of length
 * <= r, triangles of diameter <= r) has exactly \a beta0 components and \a beta1
 * independent 1-cycles. It is 4 h + 7 sigma, where h is the sampling cell size
 * (arc length per point on the circle, square root of the area per point on a
 * surface) and sigma the noise: checked with Ripser over many seeds, the Betti
 * numbers are right on an interval of radii from about 0.55 r to about 1.7 r (the
 * circle and sphere keep them much longer), so the radius is robust to the seed. */
struct SyntheticShape {
  /** \brief The sampled points (label SHAPE_LABEL, one colour per shape kind). */
  pcl::PointCloud<pcl::PointXYZRGBL>::Ptr cloud;
  /** \brief Number of connected components of the shape. */
  int beta0 = 0;
  /** \brief Number of independent 1-cycles (holes) of the shape. */
  int beta1 = 0;
  /** \brief Vietoris-Rips radius (maximal edge length) at which the complex of
   * \a cloud has Betti numbers \a beta0 and \a beta1. */
  float suggested_radius = 0.0f;
};

/** \brief Parameters of generateCircle(): a circle of radius \a radius in the
 * plane z = 0, centred at the origin.
 *
 * The angles form a jittered grid (one uniformly drawn angle in each of
 * \a num_points equal arcs). Every point is moved by isotropic 3D Gaussian noise of
 * standard deviation \a noise_sigma per axis, truncated (redrawn) at a displacement
 * length of 4 sigma, so no point is farther than 4 * noise_sigma from the circle.
 * The generator throws pcl::BadArgumentException when the points are too few or the
 * noise too strong for the ground truth to hold (suggested radius above radius / 2).
 */
struct CircleParameters {
  /** \brief Number of points, exact. */
  std::size_t num_points = 1000;
  /** \brief Radius of the circle. */
  float radius = 1.0f;
  /** \brief Standard deviation of the Gaussian noise per axis (0 = on the circle). */
  float noise_sigma = 0.01f;
  /** \brief Seed of the random generator; equal seeds give identical clouds. */
  std::uint64_t seed = 0;
};

/** \brief Parameters of generateTorus(): a torus around the z axis, centred at the
 * origin, with tube centre-line radius \a major_radius and tube radius
 * \a minor_radius.
 *
 * The surface is cut into rings of equal width along the tube; each ring gets a
 * number of points proportional to its area, on a jittered grid, so the sampling is
 * area-uniform and free of large gaps. Noise as in CircleParameters. Throws
 * pcl::BadArgumentException when the suggested radius would exceed the tube radius
 * or the radius of the central hole (major_radius - minor_radius). */
struct TorusParameters {
  /** \brief Number of points, exact. */
  std::size_t num_points = 2500;
  /** \brief Distance from the z axis to the centre line of the tube. */
  float major_radius = 1.0f;
  /** \brief Radius of the tube; must be below major_radius. */
  float minor_radius = 0.4f;
  /** \brief Standard deviation of the Gaussian noise per axis (0 = on the torus). */
  float noise_sigma = 0.01f;
  /** \brief Seed of the random generator; equal seeds give identical clouds. */
  std::uint64_t seed = 0;
};

/** \brief Parameters of generateSphere(): a sphere of radius \a radius centred at
 * the origin, sampled area-uniformly on rings of equal polar width (jittered grid).
 * Noise as in CircleParameters. Throws pcl::BadArgumentException when the suggested
 * radius would exceed radius / 2. */
struct SphereParameters {
  /** \brief Number of points, exact. */
  std::size_t num_points = 1500;
  /** \brief Radius of the sphere. */
  float radius = 1.0f;
  /** \brief Standard deviation of the Gaussian noise per axis (0 = on the sphere). */
  float noise_sigma = 0.01f;
  /** \brief Seed of the random generator; equal seeds give identical clouds. */
  std::uint64_t seed = 0;
};

/** \brief Samples a noisy circle (beta0 = 1, beta1 = 1).
 * \throws pcl::BadArgumentException on invalid or too sparse/noisy parameters */
SyntheticShape
generateCircle (const CircleParameters& parameters);

/** \brief Samples a noisy torus surface (beta0 = 1, beta1 = 2).
 * \throws pcl::BadArgumentException on invalid or too sparse/noisy parameters */
SyntheticShape
generateTorus (const TorusParameters& parameters);

/** \brief Samples a noisy sphere surface (beta0 = 1, beta1 = 0).
 * \throws pcl::BadArgumentException on invalid or too sparse/noisy parameters */
SyntheticShape
generateSphere (const SphereParameters& parameters);

} // namespace tda
} // namespace pcl
