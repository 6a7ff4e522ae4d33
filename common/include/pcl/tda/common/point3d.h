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

} // namespace tda
} // namespace pcl
