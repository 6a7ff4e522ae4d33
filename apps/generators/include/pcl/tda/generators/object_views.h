#pragma once

// Object views: single-view depth camera renders of random instances of household
// object categories (mugs, cups, rings, discs, frames, tiles, balls, cans, boxes,
// cones, bowls, bottles), each view the object's own points only, as in the RGB-D
// Object Dataset (Lai et al., ICRA 2011): ground truth for 3D object category
// classification. Pairs of categories differ mainly in topology (a mug's handle, a
// ring's or a frame's hole), the others in shape only. The camera is that of
// depth_camera_scenes.h.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Category of household object of the object views. Sizes are in metres,
 * drawn uniformly from the ranges given, per instance; "extent" is the largest side
 * of the object's bounding box, from OBJECT_MIN_EXTENT to OBJECT_MAX_EXTENT. */
enum class ObjectCategory {
  /** A cup with a handle: an open cylindrical shell with a bottom, outer radius
   * 0.035-0.05, height 0.08-0.12, wall and bottom 0.003-0.006 thick; the handle is
   * half a torus in the vertical plane through the axis, on the side, centre line
   * radius 0.25-0.35 of the height, tube radius 0.005-0.008, its ends in the wall
   * (genus 1). */
  MUG,
  /** A MUG without its handle (genus 0). */
  CUP,
  /** A torus, like a donut or a bangle: centre circle radius 0.035-0.07, tube
   * radius 0.006 to min(0.02, centre radius - 0.02), so that the hole is at least
   * 0.02 in radius (genus 1). Tilted. */
  RING,
  /** A flat solid cylinder of a RING's outer size: radius and thickness those of the
   * outer radius and tube diameter of a ring drawn as for RING (genus 0). Tilted. */
  DISC,
  /** A square plate with a square hole through it, like a picture frame: side
   * 0.10-0.25, thickness 0.01-0.025, border 0.15-0.3 of the side (genus 1).
   * Tilted. */
  FRAME,
  /** A FRAME without its hole: a square slab (genus 0). Tilted. */
  TILE,
  /** A sphere of radius 0.03-0.11. */
  BALL,
  /** A closed solid cylinder: radius 0.025-0.05, height 0.07-0.16. */
  CAN,
  /** A cuboid: length 0.08-0.25, width 0.05-0.15, height 0.05-0.20. */
  BOX,
  /** A solid pointed cone: base radius 0.03-0.07, height 0.08-0.20. */
  CONE,
  /** A hemispherical shell open at the top: outer radius 0.06-0.12, wall
   * 0.004-0.008. */
  BOWL,
  /** A closed bottle: a cylindrical body of radius 0.025-0.045 over 0.5-0.65 of the
   * height (0.15-0.25), a conical shoulder over 0.1-0.2 of it, and a cylindrical
   * neck of 0.3-0.45 of the body radius up to the top. */
  BOTTLE
};

/** \brief Number of object categories. */
constexpr std::size_t NUM_OBJECT_CATEGORIES = 12;

/** \brief Smallest extent (largest bounding box side) of an object instance, in
 * metres. */
constexpr float OBJECT_MIN_EXTENT = 0.05f;
/** \brief Largest extent (largest bounding box side) of an object instance, in
 * metres. */
constexpr float OBJECT_MAX_EXTENT = 0.25f;

/** \brief Every category, in the order of ObjectCategory. */
std::vector<ObjectCategory>
allObjectCategories ();

/** \brief The name of a category: "mug", "cup", "ring", "disc", "frame", "tile",
 * "ball", "can", "box", "cone", "bowl" or "bottle" (lower case, as in file
 * names). */
std::string
objectCategoryName (ObjectCategory category);

/** \brief The names of every category, in the order of ObjectCategory. */
std::vector<std::string>
objectCategoryNames ();

/** \brief Reads a category name (objectCategoryName()) into \a category; false,
 * with \a category unchanged, for an unknown name. */
bool
parseObjectCategory (const std::string& name, ObjectCategory& category);

/** \brief Parameters of renderObjectView(): the data set of views it defines
 * (categories x instances x views) and the camera.
 *
 * Each instance of a category is an object drawn from the seed, its category and
 * its index only (sizes, pose, colour); each view of an instance is a camera pose
 * drawn from those and the view index only, so that a view does not depend on the
 * other views, nor on the numbers of categories, instances and views: views can be
 * made in parallel and any one regenerated alone. The object's bounding box centre
 * is at the origin of the world frame (z up); upright categories stand with a
 * random rotation about the vertical axis, tilted ones (RING, DISC, FRAME, TILE)
 * are also tilted by an angle uniform in [0, 90] degrees about a horizontal axis
 * (from lying flat to standing on edge). The camera looks at the origin from a
 * distance uniform in [min_distance, max_distance], an elevation uniform in
 * [min_elevation_deg, max_elevation_deg] and any azimuth, without roll, and sees as
 * the structured-light camera of DepthCameraParameters does with its defaults
 * (640 x 480 pixels, fx = fy = 525, projector shadows, grazing dropouts, disparity
 * quantization), with the depth noise times \a noise_multiplier. */
struct ObjectViewParameters {
  /** \brief The categories of the data set, without repetition, not empty. */
  std::vector<ObjectCategory> categories = allObjectCategories();
  /** \brief Instances per category, >= 1. */
  std::size_t instances = 4;
  /** \brief Views per instance, >= 1. */
  std::size_t views = 12;
  /** \brief Factor of the depth noise's standard deviation, >= 0: 1 for the
   * Kinect-like camera (DepthCameraParameters::noise_coefficient), 3 for three
   * times its noise, 0 for none (the disparity quantization stays). */
  float noise_multiplier = 1.0f;
  /** \brief Colour noise in 0-255 levels, as DepthCameraParameters::colour_noise,
   * >= 0; drawn from a random generator of its own, so that the points do not
   * depend on it. */
  float colour_noise = 4.0f;
  /** \brief Half-width, in metres, of a uniform perturbation of every coordinate
   * of every point after the view is taken (thesis Experiment 3: 0.0005, 0.001 and
   * 0.003), >= 0, at most 0.1; drawn from a random generator of its own. */
  float perturbation = 0.0f;
  /** \brief Smallest distance from the camera to the object centre, in metres,
   * >= 0.3 (the camera stays outside every object). */
  float min_distance = 0.6f;
  /** \brief Largest distance from the camera to the object centre, in metres, from
   * min_distance to 10. */
  float max_distance = 1.2f;
  /** \brief Smallest elevation of the camera above the horizontal plane through the
   * object centre, in degrees, in [0, 89]. */
  float min_elevation_deg = 10.0f;
  /** \brief Largest elevation, in degrees, from min_elevation_deg to 89. */
  float max_elevation_deg = 70.0f;
  /** \brief Fewest points of a view, >= 1: a camera pose that sees fewer is
   * replaced by another one drawn after it. */
  std::size_t min_points = 200;
  /** \brief Seed of the random generators; equal seeds give identical views. */
  std::uint64_t seed = 0;
};

/** \brief Checks the parameters of renderObjectView().
 * \throws pcl::BadArgumentException naming the parameter at fault */
void
checkObjectViewParameters (const ObjectViewParameters& parameters);

/** \brief Ground truth of one object instance. */
struct ObjectInstance {
  /** \brief Its category. */
  ObjectCategory category = ObjectCategory::MUG;
  /** \brief Its index among the instances of its category. */
  std::size_t instance = 0;
  /** \brief Side lengths of its bounding box in its own frame (z up, before its
   * rotation), in metres; the largest is in [OBJECT_MIN_EXTENT,
   * OBJECT_MAX_EXTENT]. MUG: x along the handle. */
  Eigen::Vector3f dimensions = Eigen::Vector3f::Zero();
  /** \brief Radius of its hole, in metres: RING, the hole's (centre radius - tube
   * radius); FRAME, half the hole's side; MUG, the inner radius of the handle; 0
   * for the others. */
  float hole_radius = 0.0f;
  /** \brief Number of holes through the solid (its genus): 1 for MUG, RING and
   * FRAME, 0 for the others. A single view may not show them. */
  int genus = 0;
  /** \brief Rotation about the vertical axis, in radians. */
  float yaw = 0.0f;
  /** \brief Tilt about a horizontal axis, in radians (0 for upright categories). */
  float tilt = 0.0f;
  /** \brief Maps its own frame (bounding box centred at the origin, z up) to the
   * world frame: the rotation by \a tilt about x, then by \a yaw about z. */
  Eigen::Isometry3f pose = Eigen::Isometry3f::Identity();
  /** \brief Red of its colour before shading and noise. */
  std::uint8_t r = 0;
  /** \brief Green of its colour before shading and noise. */
  std::uint8_t g = 0;
  /** \brief Blue of its colour before shading and noise. */
  std::uint8_t b = 0;
};

/** \brief One rendered view of an object instance. */
struct ObjectView {
  /** \brief The object seen. */
  ObjectInstance object;
  /** \brief Index of the view among the views of the instance. */
  std::size_t view = 0;
  /** \brief The object's measured points only, in the camera's optical frame (x
   * right, y down, z forward, metres), unorganized (height 1), all finite, in pixel
   * order (row by row); colours are the object's, shaded by the angle of incidence,
   * plus colour noise. */
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr cloud;
  /** \brief Pose of the camera: maps camera coordinates to world coordinates (the
   * object's centre is the world origin). */
  Eigen::Isometry3f camera_pose = Eigen::Isometry3f::Identity();
  /** \brief Distance from the camera to the object centre, in metres. */
  float distance = 0.0f;
  /** \brief Elevation of the camera, in degrees. */
  float elevation_deg = 0.0f;
  /** \brief Azimuth of the camera about the vertical axis, in degrees. */
  float azimuth_deg = 0.0f;
  /** \brief Camera poses drawn (1 + those that saw fewer than min_points). */
  std::size_t poses_drawn = 1;
};

/** \brief Draws instance \a instance of \a category of the data set of
 * \a parameters: its ground truth, without rendering.
 * \throws pcl::BadArgumentException on invalid parameters, a category not in the
 * data set or an instance index out of range */
ObjectInstance
drawObjectInstance (const ObjectViewParameters& parameters,
                    ObjectCategory category,
                    std::size_t instance);

/** \brief Renders view \a view of instance \a instance of \a category of the data set
 * of \a parameters, as ObjectViewParameters documents. Deterministic: the view
 * depends on the seed, the category, the instance and view indices, the camera
 * ranges, the noise and min_points only.
 * \throws pcl::BadArgumentException on invalid parameters or indices, or when 100
 * camera poses in a row see fewer than min_points points (camera too far) */
ObjectView
renderObjectView (const ObjectViewParameters& parameters,
                  ObjectCategory category,
                  std::size_t instance,
                  std::size_t view);

} // namespace tda
} // namespace pcl
