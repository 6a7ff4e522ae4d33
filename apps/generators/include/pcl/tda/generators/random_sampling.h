#pragma once

// Seeded random numbers and the samplers of points on surfaces that the synthetic
// cloud generators (shapes.h, tabletop_scenes.h, hole_surfaces.h) share.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Gaussian noise is redrawn beyond this many standard deviations. */
constexpr double NOISE_TRUNCATION = 4.0;

/** \brief Random numbers from std::mt19937_64 with our own transforms, so that a seed
 * gives the same numbers with any standard library.
 *
 * Every draw consumes a fixed number of engine outputs (uniform: one, normal: two),
 * except the truncated normals, which redraw until the value is within bounds. */
class PortableRandom {
public:
  /** \brief Seeds the engine; equal seeds give identical sequences. */
  explicit PortableRandom (std::uint64_t seed) : engine_ (seed) {}

  /** \brief Uniform in [0, 1), from the 53 high bits of one engine output. */
  double
  uniform ()
  {
    return static_cast<double> (engine_() >> 11) * 0x1.0p-53;
  }

  /** \brief Uniform in [a, b). */
  double
  uniform (double a, double b)
  {
    return a + (b - a) * uniform();
  }

  /** \brief Uniform integer in [0, n). */
  std::size_t
  index (std::size_t n)
  {
    return std::min (static_cast<std::size_t> (uniform() * static_cast<double> (n)),
                     n - 1);
  }

  /** \brief Standard normal (Box-Muller). */
  double
  normal ()
  {
    const double u = 1.0 - uniform(); // (0, 1]
    return std::sqrt (-2.0 * std::log (u)) * std::cos (2.0 * M_PI * uniform());
  }

  /** \brief Normal of standard deviation \a sigma, redrawn beyond
   * \a truncation * \a sigma; 0 without a draw when \a sigma is 0. */
  double
  truncatedNormal (double sigma, double truncation)
  {
    if (sigma == 0.0)
      return 0.0;
    for (;;) {
      const double x = normal();
      if (std::abs (x) <= truncation)
        return sigma * x;
    }
  }

  /** \brief Isotropic 3D normal of standard deviation \a sigma per axis, redrawn
   * when its length exceeds NOISE_TRUNCATION * \a sigma; zero without a draw when
   * \a sigma is 0. */
  Eigen::Vector3d
  truncatedNormal3 (double sigma)
  {
    if (sigma == 0.0)
      return Eigen::Vector3d::Zero();
    for (;;) {
      const Eigen::Vector3d x (normal(), normal(), normal());
      if (x.norm() <= NOISE_TRUNCATION)
        return sigma * x;
    }
  }

private:
  std::mt19937_64 engine_;
};

/** \brief A point on a surface with its outward unit normal. */
struct SurfaceSample {
  Eigen::Vector3d point;
  Eigen::Vector3d normal;
};

/** \brief Splits \a total into counts proportional to \a weights (largest remainder,
 * ties to the lower index), so that the counts sum to \a total exactly. */
std::vector<std::size_t>
apportion (const std::vector<double>& weights, std::size_t total);

/** \brief Number of grid cells of size at most \a spacing along \a length (at least
 * one). */
std::size_t
cellCount (double length, double spacing);

/** \brief Exactly \a count points on a sphere of radius \a radius centred at the
 * origin, area-uniform: rings of equal polar width get points in proportion to
 * their area, each point drawn uniformly in its own cell of the ring. */
std::vector<SurfaceSample>
sampleSphere (double radius, std::size_t count, PortableRandom& random);

/** \brief Exactly \a count points on the torus around the z axis, centred at the
 * origin, with tube centre-line radius \a major_radius and tube radius
 * \a minor_radius (below \a major_radius), area-uniform: rings of equal width
 * around the tube get points in proportion to their area, each point drawn
 * uniformly in its own cell of the ring. */
std::vector<SurfaceSample>
sampleTorus (double major_radius,
             double minor_radius,
             std::size_t count,
             PortableRandom& random);

/** \brief Points on the disc of radius \a radius in the plane z = 0 (normal +z), one
 * per cell of about \a spacing x \a spacing: rings of equal width, cells of equal
 * area. */
std::vector<SurfaceSample>
sampleDisc (double radius, double spacing, PortableRandom& random);

/** \brief Appends to \a samples points on the rectangle origin + s * u + t * v,
 * s, t in [0, 1], with normal \a normal, one per cell of a grid of cells of at most
 * \a spacing x \a spacing. */
void
sampleRectangle (const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& u,
                 const Eigen::Vector3d& v,
                 const Eigen::Vector3d& normal,
                 double spacing,
                 PortableRandom& random,
                 std::vector<SurfaceSample>& samples);

} // namespace tda
} // namespace pcl
