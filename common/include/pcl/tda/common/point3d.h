#pragma once

#include <pcl/tda/common/host_device.h>

#include <array>
#include <cmath>

namespace pcl {
namespace tda {

/** \brief A point of R^3 in double precision, as the complex builders
 * measure distances. */
using Point3d = std::array<double, 3>;

/** \brief Euclidean distance of two points: the filtration value of an edge. */
PCL_TDA_HOST_DEVICE inline double
distance (const Point3d& a, const Point3d& b)
{
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt (dx * dx + dy * dy + dz * dz);
}

/** \brief The one test of "within the radius" of PCL-TDA: true when distance(\a p,
 * \a q) <= \a radius, i.e. an edge of length exactly r is in VR_r. It decides on the
 * squared distance where that is clear (outside a relative band of 1e-9 around
 * r^2) and takes the square root only near the radius, so that it agrees with
 * distance() exactly. */
PCL_TDA_HOST_DEVICE inline bool
withinRadius (const Point3d& p, const Point3d& q, double radius)
{
  const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
  const double squared = dx * dx + dy * dy + dz * dz;
  const double squared_radius = radius * radius;
  if (squared < squared_radius * (1.0 - 1e-9))
    return true;
  if (squared > squared_radius * (1.0 + 1e-9))
    return false;
  return std::sqrt (squared) <= radius;
}

/** \brief The power of two that brings \a magnitude (finite, >= 0) to [0.5, 1); 1 for
 * 0. Coordinates divided by that of their largest magnitude keep their digits in
 * float, and their squares neither overflow nor underflow it: float searches (FLANN,
 * PCL's k-d tree, eigen33) so work on clouds in any unit (coordinates of 1e25 or
 * 1e-25), and give the same results as in metres. */
inline double
powerOfTwoScale (double magnitude)
{
  if (magnitude == 0.0)
    return 1.0;
  int exponent = 0;
  std::frexp (magnitude, &exponent);
  return std::ldexp (1.0, exponent);
}

} // namespace tda
} // namespace pcl
