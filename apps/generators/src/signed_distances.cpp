#include "signed_distances.h"

#include <algorithm>
#include <cmath>

namespace pcl {
namespace tda {

double
boxDistance (const Eigen::Vector3d& p, const Eigen::Vector3d& half)
{
  const Eigen::Vector3d q = p.cwiseAbs() - half;
  return q.cwiseMax (0.0).norm() + std::min (q.maxCoeff(), 0.0);
}

double
cylinderDistance (const Eigen::Vector3d& p, double radius, double bottom, double top)
{
  const Eigen::Vector2d q (p.head<2>().norm() - radius,
                           std::abs (p.z() - 0.5 * (bottom + top)) -
                               0.5 * (top - bottom));
  return q.cwiseMax (0.0).norm() + std::min (q.maxCoeff(), 0.0);
}

double
coneDistance (const Eigen::Vector3d& p, double r1, double r2, double h)
{
  const double half = 0.5 * h;
  const Eigen::Vector2d q (p.head<2>().norm(), p.z() - half);
  const Eigen::Vector2d k1 (r2, half);
  const Eigen::Vector2d k2 (r2 - r1, h);
  const Eigen::Vector2d ca (q.x() - std::min (q.x(), q.y() < 0.0 ? r1 : r2),
                            std::abs (q.y()) - half);
  const Eigen::Vector2d cb =
      q - k1 + k2 * std::clamp ((k1 - q).dot (k2) / k2.squaredNorm(), 0.0, 1.0);
  const double sign = cb.x() < 0.0 && ca.y() < 0.0 ? -1.0 : 1.0;
  return sign * std::sqrt (std::min (ca.squaredNorm(), cb.squaredNorm()));
}

double
torusDistance (const Eigen::Vector3d& p, double radius, double tube)
{
  return Eigen::Vector2d (p.head<2>().norm() - radius, p.z()).norm() - tube;
}

double
hemisphericalShellDistance (const Eigen::Vector3d& p, double radius, double wall)
{
  const double shell = std::abs (p.norm() - (radius - 0.5 * wall)) - 0.5 * wall;
  return std::max (shell, p.z());
}

} // namespace tda
} // namespace pcl
