#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>

namespace pcl {
namespace tda {

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

/** \brief The largest magnitude of a finite coordinate of \a cloud; -1 when no
 * point is finite. */
template <typename PointT>
double
largestCoordinate (const pcl::PointCloud<PointT>& cloud)
{
  float largest = -1.0f;
  for (const PointT& point : cloud)
    if (pcl::isXYZFinite (point))
      largest = std::max (largest, point.getVector3fMap().cwiseAbs().maxCoeff());
  return largest;
}

/** \brief The power of two by which float searches measure \a cloud:
 * powerOfTwoScale() of its largest finite coordinate magnitude (1 without one). */
template <typename PointT>
double
cloudScale (const pcl::PointCloud<PointT>& cloud)
{
  return powerOfTwoScale (std::max (largestCoordinate (cloud), 0.0));
}

/** \brief The positions of \a cloud divided by \a scale (cloudScale(): a power of
 * two, so exact in float), for float searches and estimations that then work in any
 * unit; lengths given to them are divided by \a scale too. */
template <typename PointT>
pcl::PointCloud<pcl::PointXYZ>::Ptr
scaledPositions (const pcl::PointCloud<PointT>& cloud, double scale)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr scaled (new pcl::PointCloud<pcl::PointXYZ>);
  scaled->reserve (cloud.size());
  for (const PointT& p : cloud)
    scaled->push_back (pcl::PointXYZ (static_cast<float> (p.x / scale),
                                      static_cast<float> (p.y / scale),
                                      static_cast<float> (p.z / scale)));
  scaled->is_dense = cloud.is_dense;
  return scaled;
}

} // namespace tda
} // namespace pcl
