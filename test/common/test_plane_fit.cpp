/** PlaneFit: the normal of points on a known plane, and a finite normal across the
 * line when the points are on a line (pcl::eigen33 gives none there). */
#include <pcl/tda/common/plane_fit.h>

#include <gtest/gtest.h>

#include <random>

namespace {

using pcl::tda::PlaneFit;
using pcl::tda::Point3d;

TEST (PlaneFit, NormalOfPointsOnATiltedPlane)
{
  const Eigen::Vector3d normal = Eigen::Vector3d (1.0, 2.0, 2.0) / 3.0;
  const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross (u);
  std::mt19937 random (5);
  std::uniform_real_distribution<double> coordinate (-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d origin (coordinate (random), 3.0, 1.0);
    PlaneFit plane (Point3d{origin.x(), origin.y(), origin.z()});
    for (int k = 0; k < 30; ++k) {
      const Eigen::Vector3d p =
          origin + coordinate (random) * u + coordinate (random) * v;
      plane.add ({p.x(), p.y(), p.z()});
    }
    EXPECT_NEAR (std::abs (plane.normal().cast<double>().dot (normal)), 1.0, 1e-5);
    EXPECT_NEAR (std::abs (plane.principalAxes().col (2).dot (normal)), 1.0, 1e-9);
  }
}

TEST (PlaneFit, PointsOnALineGetAFiniteNormalAcrossIt)
{
  const Eigen::Vector3d direction = Eigen::Vector3d (3.0, -1.0, 2.0).normalized();
  for (const int count : {2, 3, 10}) {
    PlaneFit plane (Point3d{1.0, 1.0, 1.0});
    for (int k = 0; k < count; ++k) {
      const Eigen::Vector3d p = Eigen::Vector3d (1.0, 1.0, 1.0) + 0.5 * k * direction;
      plane.add ({p.x(), p.y(), p.z()});
    }
    const Eigen::Vector3f normal = plane.normal();
    ASSERT_TRUE (normal.allFinite()) << count << " points";
    EXPECT_NEAR (normal.norm(), 1.0f, 1e-5f);
    EXPECT_NEAR (normal.cast<double>().dot (direction), 0.0, 1e-5);
  }
}

} // namespace
