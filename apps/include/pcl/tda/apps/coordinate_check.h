#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/tda/common/coordinate_scale.h>
#include <pcl/exceptions.h>
#include <pcl/point_cloud.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The finest share of a tool's length scale (its radius, its leaf) that the
 * float coordinates of its input may round to: 1/100. */
constexpr double MAX_RESOLUTION_PER_SCALE = 0.01;

/** \brief The float resolution at \a magnitude (>= 0): the step of 32-bit floats
 * (PCL's point coordinates) there, the rounding a coordinate may carry (0.5 at 5e6,
 * as in UTM coordinates; 2.4e-7 at 2; 0 at 0). */
inline double
floatResolution (double magnitude)
{
  // Floats in [2^(e - 1), 2^e) are 2^(e - 24) apart.
  return magnitude > 0.0 ? std::ldexp (powerOfTwoScale (magnitude), -24) : 0.0;
}

/** \brief The smallest length scale that coordinates up to \a magnitude (>= 0)
 * resolve, as checkToolCoordinates() requires of a tool's radius or leaf: the float
 * resolution there divided by MAX_RESOLUTION_PER_SCALE. */
inline double
resolvedScale (double magnitude)
{
  return floatResolution (magnitude) / MAX_RESOLUTION_PER_SCALE;
}

/** \brief resolvedScale() at the largest coordinate of \a cloud (0 for a cloud with
 * no finite point, or at the origin). */
template <typename PointT>
double
smallestResolvedScale (const pcl::PointCloud<PointT>& cloud)
{
  return resolvedScale (std::max (largestCoordinate (cloud), 0.0));
}

/** \brief Checks a tool's input before the work: it has a finite point, and its
 * coordinates resolve the tool's length scale \a scale, given by option \a option
 * ("-radius"): the float resolution at its largest coordinate is at most
 * MAX_RESOLUTION_PER_SCALE of it. Far from the origin they do not: a scan in UTM
 * coordinates (x near 5e6 m) has points 0.5 m apart in float, whatever its file
 * holds, and its diagrams, clusters and holes would be those of the rounded points.
 * \throws pcl::BadArgumentException saying which check failed and what to do */
template <typename PointT>
void
checkToolCoordinates (const pcl::PointCloud<PointT>& cloud,
                      double scale,
                      const std::string& option)
{
  const double largest = largestCoordinate (cloud);
  if (largest < 0.0)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "The input has no finite point (all "
                             << cloud.size() << " are NaN or infinite).");
  const double resolution = floatResolution (largest);
  if (resolvedScale (largest) > scale)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "The coordinates reach "
                             << largest
                             << ", where 32-bit floats (PCL's point coordinates) "
                                "are "
                             << resolution << " apart: too coarse for " << option << " "
                             << scale << " (at most 1/"
                             << 1.0 / MAX_RESOLUTION_PER_SCALE
                             << " of it). Move the cloud near the origin first "
                                "(subtract one of its points from all).");
}

/** \brief The share of coincident points from which coincidentPointsAdvice() speaks
 * of them: 1 %. */
constexpr double COINCIDENT_SHARE_TO_MENTION = 0.01;

/** \brief The finite points of \a cloud: how many, and how many distinct positions
 * they take. */
struct FinitePositions {
  std::size_t finite = 0;
  std::size_t distinct = 0;
};

template <typename PointT>
FinitePositions
countFinitePositions (const pcl::PointCloud<PointT>& cloud)
{
  std::vector<std::array<float, 3>> positions;
  for (const PointT& point : cloud)
    if (pcl::isXYZFinite (point))
      positions.push_back ({point.x, point.y, point.z});
  std::sort (positions.begin(), positions.end());
  const auto distinct = std::unique (positions.begin(), positions.end());
  return {positions.size(), static_cast<std::size_t> (distinct - positions.begin())};
}

/** \brief Advice for a complex refused as too large, when at least
 * COINCIDENT_SHARE_TO_MENTION of the finite points of \a cloud share their position
 * with another (such as the invalid pixels some drivers write as 0, 0, 0: every
 * pair of them is an edge at any radius); "" otherwise. */
template <typename PointT>
std::string
coincidentPointsAdvice (const pcl::PointCloud<PointT>& cloud)
{
  const FinitePositions positions = countFinitePositions (cloud);
  const std::size_t coincident = positions.finite - positions.distinct;
  if (coincident == 0 ||
      coincident < COINCIDENT_SHARE_TO_MENTION * static_cast<double> (positions.finite))
    return "";
  return std::to_string (coincident) + " of the " + std::to_string (positions.finite) +
         " points repeat the position of another (invalid pixels written as 0, 0, "
         "0?): every pair of them is an edge at any radius. Remove them, or merge "
         "them with a voxel grid.";
}

} // namespace tda
} // namespace pcl
