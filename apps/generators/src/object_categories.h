#pragma once

// The solids of the object categories of object_views.h: the random sizes of an
// instance (the ranges ObjectCategory documents) and its signed distance, for sphere
// tracing. Internal to pcl_tda_generators.

#include <pcl/tda/generators/object_views.h>
#include <pcl/tda/generators/random_sampling.h>

#include <Eigen/Core>

namespace pcl {
namespace tda {

/** \brief The solid of an object instance, in its own frame: z up, the centre of its
 * bounding box at the origin. */
class ObjectSolid {
public:
  /** \brief Draws the sizes of an instance of \a category from \a random. */
  ObjectSolid (ObjectCategory category, PortableRandom& random);

  /** \brief A lower bound of the distance from \a p (own frame) to the solid, exact
   * outside but near edges where parts meet; negative inside. */
  double
  distance (const Eigen::Vector3d& p) const;

  /** \brief Side lengths of the bounding box. */
  Eigen::Vector3d
  dimensions () const
  {
    return box_max_ - box_min_;
  }

  /** \brief Radius of the sphere about the origin that holds the solid. */
  double
  boundRadius () const
  {
    return 0.5 * dimensions().norm();
  }

  /** \brief As ObjectInstance::hole_radius. */
  double
  holeRadius () const;

  /** \brief As ObjectInstance::genus. */
  int
  genus () const;

  /** \brief Whether instances of the category are tilted (RING, DISC, FRAME,
   * TILE). */
  static bool
  tilted (ObjectCategory category);

private:
  /** The distance in the frame the solid is built in (base on z = 0, or centred). */
  double
  builtDistance (const Eigen::Vector3d& p) const;

  ObjectCategory category_;
  /** Main radius (cup body, ring centre circle, disc, ball, can, cone base, bowl,
   * bottle body) and height (or thickness). */
  double radius_ = 0.0, height_ = 0.0;
  /** Wall of a cup or bowl; tube radius of a ring; side of a frame's hole. */
  double wall_ = 0.0, tube_ = 0.0, hole_side_ = 0.0;
  /** Mug handle: radius of its centre line and of its tube. */
  double handle_radius_ = 0.0, handle_tube_ = 0.0;
  /** Bottle: heights of the body and the shoulder, radius of the neck. */
  double body_height_ = 0.0, shoulder_height_ = 0.0, neck_radius_ = 0.0;
  /** Box, frame, tile: half sides. */
  Eigen::Vector3d half_ = Eigen::Vector3d::Zero();
  /** Bounding box in the frame the solid is built in. */
  Eigen::Vector3d box_min_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d box_max_ = Eigen::Vector3d::Zero();
};

} // namespace tda
} // namespace pcl
