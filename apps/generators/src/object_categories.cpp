#include "object_categories.h"

#include "signed_distances.h"

#include <algorithm>
#include <cmath>

namespace pcl {
namespace tda {
namespace {

// Sizes, in metres (or fractions where said), as ObjectCategory documents them.
constexpr double CUP_MIN_RADIUS = 0.035, CUP_MAX_RADIUS = 0.05;
constexpr double CUP_MIN_HEIGHT = 0.08, CUP_MAX_HEIGHT = 0.12;
constexpr double CUP_MIN_WALL = 0.003, CUP_MAX_WALL = 0.006;
/** Handle: centre line radius as a fraction of the height; tube radius. */
constexpr double HANDLE_MIN_RADIUS = 0.25, HANDLE_MAX_RADIUS = 0.35;
constexpr double HANDLE_MIN_TUBE = 0.005, HANDLE_MAX_TUBE = 0.008;
constexpr double RING_MIN_RADIUS = 0.035, RING_MAX_RADIUS = 0.07;
constexpr double RING_MIN_TUBE = 0.006, RING_MAX_TUBE = 0.02;
constexpr double RING_MIN_HOLE = 0.02;
constexpr double FRAME_MIN_SIDE = 0.10, FRAME_MAX_SIDE = 0.25;
constexpr double FRAME_MIN_THICKNESS = 0.01, FRAME_MAX_THICKNESS = 0.025;
/** Border of a frame, as a fraction of its side. */
constexpr double FRAME_MIN_BORDER = 0.15, FRAME_MAX_BORDER = 0.3;
constexpr double BALL_MIN_RADIUS = 0.03, BALL_MAX_RADIUS = 0.11;
constexpr double CAN_MIN_RADIUS = 0.025, CAN_MAX_RADIUS = 0.05;
constexpr double CAN_MIN_HEIGHT = 0.07, CAN_MAX_HEIGHT = 0.16;
constexpr double BOX_MIN_LENGTH = 0.08, BOX_MAX_LENGTH = 0.25;
constexpr double BOX_MIN_WIDTH = 0.05, BOX_MAX_WIDTH = 0.15;
constexpr double BOX_MIN_HEIGHT = 0.05, BOX_MAX_HEIGHT = 0.20;
constexpr double CONE_MIN_RADIUS = 0.03, CONE_MAX_RADIUS = 0.07;
constexpr double CONE_MIN_HEIGHT = 0.08, CONE_MAX_HEIGHT = 0.20;
constexpr double BOWL_MIN_RADIUS = 0.06, BOWL_MAX_RADIUS = 0.12;
constexpr double BOWL_MIN_WALL = 0.004, BOWL_MAX_WALL = 0.008;
constexpr double BOTTLE_MIN_RADIUS = 0.025, BOTTLE_MAX_RADIUS = 0.045;
constexpr double BOTTLE_MIN_HEIGHT = 0.15, BOTTLE_MAX_HEIGHT = 0.25;
/** Bottle: body and shoulder heights as fractions of the height; neck radius as a
 * fraction of the body radius. */
constexpr double BOTTLE_MIN_BODY = 0.5, BOTTLE_MAX_BODY = 0.65;
constexpr double BOTTLE_MIN_SHOULDER = 0.1, BOTTLE_MAX_SHOULDER = 0.2;
constexpr double BOTTLE_MIN_NECK = 0.3, BOTTLE_MAX_NECK = 0.45;

/** The box from -half to half. */
void
centredBox (const Eigen::Vector3d& half, Eigen::Vector3d& low, Eigen::Vector3d& high)
{
  low = -half;
  high = half;
}

} // namespace

ObjectSolid::ObjectSolid (ObjectCategory category, PortableRandom& random)
: category_ (category)
{
  switch (category) {
  case ObjectCategory::MUG:
  case ObjectCategory::CUP:
    // Built standing on z = 0; the mug's handle on the +x side.
    radius_ = random.uniform (CUP_MIN_RADIUS, CUP_MAX_RADIUS);
    height_ = random.uniform (CUP_MIN_HEIGHT, CUP_MAX_HEIGHT);
    wall_ = random.uniform (CUP_MIN_WALL, CUP_MAX_WALL);
    box_min_ = Eigen::Vector3d (-radius_, -radius_, 0.0);
    box_max_ = Eigen::Vector3d (radius_, radius_, height_);
    if (category == ObjectCategory::MUG) {
      handle_radius_ = height_ * random.uniform (HANDLE_MIN_RADIUS, HANDLE_MAX_RADIUS);
      handle_tube_ = random.uniform (HANDLE_MIN_TUBE, HANDLE_MAX_TUBE);
      box_max_.x() = radius_ - 0.5 * wall_ + handle_radius_ + handle_tube_;
    }
    break;
  case ObjectCategory::RING:
  case ObjectCategory::DISC: {
    // Built centred; a disc has the outer radius and thickness of a ring.
    const double radius = random.uniform (RING_MIN_RADIUS, RING_MAX_RADIUS);
    const double tube = random.uniform (
        RING_MIN_TUBE, std::min (RING_MAX_TUBE, radius - RING_MIN_HOLE));
    radius_ = category == ObjectCategory::RING ? radius : radius + tube;
    tube_ = tube;
    height_ = 2.0 * tube;
    centredBox (
        Eigen::Vector3d (radius + tube, radius + tube, tube), box_min_, box_max_);
    break;
  }
  case ObjectCategory::FRAME:
  case ObjectCategory::TILE: {
    const double side = random.uniform (FRAME_MIN_SIDE, FRAME_MAX_SIDE);
    height_ = random.uniform (FRAME_MIN_THICKNESS, FRAME_MAX_THICKNESS);
    const double border = side * random.uniform (FRAME_MIN_BORDER, FRAME_MAX_BORDER);
    hole_side_ = category == ObjectCategory::FRAME ? side - 2.0 * border : 0.0;
    half_ = Eigen::Vector3d (0.5 * side, 0.5 * side, 0.5 * height_);
    centredBox (half_, box_min_, box_max_);
    break;
  }
  case ObjectCategory::BALL:
    radius_ = random.uniform (BALL_MIN_RADIUS, BALL_MAX_RADIUS);
    centredBox (Eigen::Vector3d::Constant (radius_), box_min_, box_max_);
    break;
  case ObjectCategory::CAN:
  case ObjectCategory::CONE:
    radius_ = category == ObjectCategory::CAN
                  ? random.uniform (CAN_MIN_RADIUS, CAN_MAX_RADIUS)
                  : random.uniform (CONE_MIN_RADIUS, CONE_MAX_RADIUS);
    height_ = category == ObjectCategory::CAN
                  ? random.uniform (CAN_MIN_HEIGHT, CAN_MAX_HEIGHT)
                  : random.uniform (CONE_MIN_HEIGHT, CONE_MAX_HEIGHT);
    box_min_ = Eigen::Vector3d (-radius_, -radius_, 0.0);
    box_max_ = Eigen::Vector3d (radius_, radius_, height_);
    break;
  case ObjectCategory::BOX:
    half_ = 0.5 * Eigen::Vector3d (random.uniform (BOX_MIN_LENGTH, BOX_MAX_LENGTH),
                                   random.uniform (BOX_MIN_WIDTH, BOX_MAX_WIDTH),
                                   random.uniform (BOX_MIN_HEIGHT, BOX_MAX_HEIGHT));
    centredBox (half_, box_min_, box_max_);
    break;
  case ObjectCategory::BOWL:
    radius_ = random.uniform (BOWL_MIN_RADIUS, BOWL_MAX_RADIUS);
    wall_ = random.uniform (BOWL_MIN_WALL, BOWL_MAX_WALL);
    height_ = radius_;
    box_min_ = Eigen::Vector3d (-radius_, -radius_, 0.0);
    box_max_ = Eigen::Vector3d (radius_, radius_, radius_);
    break;
  case ObjectCategory::BOTTLE:
    radius_ = random.uniform (BOTTLE_MIN_RADIUS, BOTTLE_MAX_RADIUS);
    height_ = random.uniform (BOTTLE_MIN_HEIGHT, BOTTLE_MAX_HEIGHT);
    body_height_ = height_ * random.uniform (BOTTLE_MIN_BODY, BOTTLE_MAX_BODY);
    shoulder_height_ =
        height_ * random.uniform (BOTTLE_MIN_SHOULDER, BOTTLE_MAX_SHOULDER);
    neck_radius_ = radius_ * random.uniform (BOTTLE_MIN_NECK, BOTTLE_MAX_NECK);
    box_min_ = Eigen::Vector3d (-radius_, -radius_, 0.0);
    box_max_ = Eigen::Vector3d (radius_, radius_, height_);
    break;
  }
}

double
ObjectSolid::distance (const Eigen::Vector3d& p) const
{
  return builtDistance (p + 0.5 * (box_min_ + box_max_));
}

double
ObjectSolid::builtDistance (const Eigen::Vector3d& p) const
{
  switch (category_) {
  case ObjectCategory::MUG:
  case ObjectCategory::CUP: {
    const double cup =
        std::max (cylinderDistance (p, radius_, 0.0, height_),
                  -cylinderDistance (p, radius_ - wall_, wall_, height_ + wall_));
    if (category_ == ObjectCategory::CUP)
      return cup;
    // The handle: the half (x >= 0) of a torus about the y axis centred in the
    // middle of the wall, so that its ends are inside the wall.
    const Eigen::Vector3d q =
        p - Eigen::Vector3d (radius_ - 0.5 * wall_, 0.0, 0.5 * height_);
    const double handle = std::max (
        torusDistance (
            Eigen::Vector3d (q.x(), q.z(), q.y()), handle_radius_, handle_tube_),
        -q.x());
    return std::min (cup, handle);
  }
  case ObjectCategory::RING:
    return torusDistance (p, radius_, tube_);
  case ObjectCategory::DISC:
    return cylinderDistance (p, radius_, -0.5 * height_, 0.5 * height_);
  case ObjectCategory::FRAME:
    return std::max (
        boxDistance (p, half_),
        -boxDistance (p,
                      Eigen::Vector3d (0.5 * hole_side_, 0.5 * hole_side_, height_)));
  case ObjectCategory::TILE:
  case ObjectCategory::BOX:
    return boxDistance (p, half_);
  case ObjectCategory::BALL:
    return p.norm() - radius_;
  case ObjectCategory::CAN:
    return cylinderDistance (p, radius_, 0.0, height_);
  case ObjectCategory::CONE:
    return coneDistance (p, radius_, 0.0, height_);
  case ObjectCategory::BOWL:
    return hemisphericalShellDistance (
        p - Eigen::Vector3d (0.0, 0.0, radius_), radius_, wall_);
  case ObjectCategory::BOTTLE: {
    const double neck_bottom = body_height_ + shoulder_height_;
    return std::min ({cylinderDistance (p, radius_, 0.0, body_height_),
                      coneDistance (p - Eigen::Vector3d (0.0, 0.0, body_height_),
                                    radius_,
                                    neck_radius_,
                                    shoulder_height_),
                      cylinderDistance (p, neck_radius_, neck_bottom, height_)});
  }
  }
  return 0.0;
}

double
ObjectSolid::holeRadius() const
{
  switch (category_) {
  case ObjectCategory::MUG:
    return handle_radius_ - handle_tube_;
  case ObjectCategory::RING:
    return radius_ - tube_;
  case ObjectCategory::FRAME:
    return 0.5 * hole_side_;
  default:
    return 0.0;
  }
}

int
ObjectSolid::genus() const
{
  return holeRadius() > 0.0 ? 1 : 0;
}

bool
ObjectSolid::tilted (ObjectCategory category)
{
  return category == ObjectCategory::RING || category == ObjectCategory::DISC ||
         category == ObjectCategory::FRAME || category == ObjectCategory::TILE;
}

} // namespace tda
} // namespace pcl
