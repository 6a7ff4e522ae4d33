#pragma once

#include <pcl/common/eigen.h>
#include <pcl/tda/common/coordinate_scale.h>
#include <pcl/tda/common/point3d.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cstddef>

namespace pcl {
namespace tda {

/** \brief The least-squares plane of a set of points, accumulated one point at a
 * time: the normals of region growing and the planes of hole rims both come from it.
 *
 * Offsets are taken from a reference point of the set (shifting by a point of the
 * set keeps the sums small and the covariance exact), and the normal is the
 * eigenvector of the smallest eigenvalue of the covariance, as
 * pcl::computePointNormal gives it. */
class PlaneFit {
public:
  /** \param[in] origin a point of the set or near it; it is not added */
  explicit PlaneFit (const Point3d& origin) : origin_ (origin[0], origin[1], origin[2])
  {}

  void
  add (const Point3d& p)
  {
    const Eigen::Vector3d d (p[0] - origin_[0], p[1] - origin_[1], p[2] - origin_[2]);
    sum_ += d;
    products_ += d * d.transpose();
    ++count_;
  }

  std::size_t
  size () const
  {
    return count_;
  }

  /** \brief The mean of the added points. */
  Eigen::Vector3d
  centroid () const
  {
    return origin_ + sum_ / static_cast<double> (count_);
  }

  /** \brief The unit normal of the plane (sign arbitrary); needs two points. */
  Eigen::Vector3f
  normal () const
  {
    const double n = static_cast<double> (count_);
    Eigen::Matrix3d covariance = (products_ - sum_ * sum_.transpose() / n) / n;
    // Scaled by a power of two (the normal stays): in float, also the covariance of
    // points in units where squares overflow or underflow.
    covariance /= powerOfTwoScale (covariance.cwiseAbs().maxCoeff());
    float eigenvalue = 0.0f;
    Eigen::Vector3f normal;
    pcl::eigen33 (Eigen::Matrix3f (covariance.cast<float>()), eigenvalue, normal);
    normal.normalize();
    // eigen33 gives no vector when the smallest eigenvalue is double (points on a
    // line): any axis across the line is then a normal.
    if (!normal.allFinite())
      return principalAxes().col (2).cast<float>();
    return normal;
  }

  /** \brief The unit axes of the spread of the added points, largest variance first
   * (signs arbitrary): their principal axes, in double precision; needs two
   * points. */
  Eigen::Matrix3d
  principalAxes () const
  {
    const double n = static_cast<double> (count_);
    const Eigen::Matrix3d covariance = (products_ - sum_ * sum_.transpose() / n) / n;
    // The solver's eigenvalues increase: its columns reversed.
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (covariance)
        .eigenvectors()
        .rowwise()
        .reverse();
  }

private:
  Eigen::Vector3d origin_;
  Eigen::Vector3d sum_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d products_ = Eigen::Matrix3d::Zero();
  std::size_t count_ = 0;
};

} // namespace tda
} // namespace pcl
