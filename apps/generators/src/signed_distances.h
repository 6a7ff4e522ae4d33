#pragma once

// Signed distances of the solids that the ray-cast generators (depth camera scenes,
// object views) trace: exact distances to boxes, cylinders, cones, tori and
// hemispherical shells, negative inside. Internal to pcl_tda_generators.

#include <Eigen/Core>

namespace pcl {
namespace tda {

/** \brief Exact distance to the box of half sides \a half centred at the origin
 * (negative inside). */
double
boxDistance (const Eigen::Vector3d& p, const Eigen::Vector3d& half);

/** \brief Exact distance to the solid cylinder about the z axis of radius \a radius
 * from z = \a bottom to z = \a top (negative inside). */
double
cylinderDistance (const Eigen::Vector3d& p, double radius, double bottom, double top);

/** \brief Exact distance to the solid truncated cone about the z axis standing on
 * z = 0: bottom radius \a r1, top radius \a r2 (0: a pointed cone), height \a h
 * (negative inside). */
double
coneDistance (const Eigen::Vector3d& p, double r1, double r2, double h);

/** \brief Exact distance to the solid torus about the z axis centred at the origin:
 * radius \a radius of the tube's centre circle, tube radius \a tube (negative
 * inside). */
double
torusDistance (const Eigen::Vector3d& p, double radius, double tube);

/** \brief A lower bound of the distance to the lower half (z <= 0) of the spherical
 * shell of outer radius \a radius and thickness \a wall centred at the origin: a
 * bowl open at the top. Exact but near the rim; negative inside. */
double
hemisphericalShellDistance (const Eigen::Vector3d& p, double radius, double wall);

} // namespace tda
} // namespace pcl
