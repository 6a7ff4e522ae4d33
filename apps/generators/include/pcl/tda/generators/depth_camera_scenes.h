#pragma once

// Depth camera scenes: bowls, cones, rings, L-shaped blocks and lying capsules on a
// table, ray-cast by a simulated structured-light depth camera into an organized
// frame, each object labelled. A second scene generator, made independently of
// tabletop_scenes.h (other objects, camera, noise and density), to validate
// choices tuned on the first.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Label of the table and of the pixels that see no object in a depth camera
 * scene. */
constexpr std::uint32_t DEPTH_BACKGROUND_LABEL = 0;
/** \brief Label of the first object of a depth camera scene; object k (0-based) has
 * label DEPTH_FIRST_OBJECT_LABEL + k. */
constexpr std::uint32_t DEPTH_FIRST_OBJECT_LABEL = 1;
/** \brief Most objects a depth camera scene holds (one distinct colour each). */
constexpr std::size_t MAX_DEPTH_CAMERA_OBJECTS = 8;

/** \brief Kind of object standing on the table of a depth camera scene. */
enum class DepthObjectKind {
  /** A hemispherical bowl, open at the top, with walls 6 mm thick. */
  BOWL,
  /** A solid truncated cone, wider at the bottom. */
  CONE,
  /** A ring (torus) lying flat. */
  RING,
  /** An L-shaped block: a base slab with an upright slab at one end, each a third
   * of the block's length thick; the base is a third of the block's height. */
  L_BLOCK,
  /** A capsule (a cylinder with hemispherical ends) lying on its side. */
  CAPSULE
};

/** \brief Parameters of generateDepthCameraScene().
 *
 * The world frame has z up; the table top is the rectangle |x| <= table_width / 2,
 * |y| <= table_depth / 2 of the plane z = 0, and the objects stand inside the disc
 * of radius \a layout_radius about its centre. The camera looks at the table centre
 * from a distance and an elevation (angle above the table plane) drawn from the
 * given ranges, from any direction, without roll. It casts one ray through the
 * centre of every pixel of a pinhole camera and measures the depth z (along the
 * optical axis) of the first surface hit, as a structured-light sensor does:
 * - a pixel is lost (NaN) when the ray hits nothing, when the surface point is in
 *   the shadow of an object as seen from the projector (\a baseline metres along
 *   the camera's x axis) if \a projector_shadows, and with a probability rising
 *   linearly from 0 to 1 as the angle between the ray and the surface normal goes
 *   from \a grazing_start_deg to \a grazing_full_deg;
 * - the depth gets Gaussian noise of standard deviation noise_coefficient * z^2,
 *   truncated at 4 standard deviations, and is then quantized: the disparity
 *   fx * baseline / z is rounded to a multiple of \a disparity_step pixels. */
struct DepthCameraParameters {
  /** \brief Fewest objects in the scene (the count is drawn from the seed), >= 1. */
  std::size_t min_objects = 3;
  /** \brief Most objects in the scene, min_objects to MAX_DEPTH_CAMERA_OBJECTS. */
  std::size_t max_objects = 6;
  /** \brief Image width in pixels, 1 to 4096. */
  std::size_t width = 640;
  /** \brief Image height in pixels, 1 to 4096. */
  std::size_t height = 480;
  /** \brief Horizontal focal length in pixels. */
  float fx = 525.0f;
  /** \brief Vertical focal length in pixels. */
  float fy = 525.0f;
  /** \brief Column of the principal point (pixel u has its centre at u). */
  float cx = 319.5f;
  /** \brief Row of the principal point (pixel v has its centre at v). */
  float cy = 239.5f;
  /** \brief Smallest distance from the camera to the table centre, in metres; the
   * camera must be above the objects: min_distance * sin(min_elevation) > 0.2 m. */
  float min_distance = 0.8f;
  /** \brief Largest distance from the camera to the table centre, in metres. */
  float max_distance = 1.5f;
  /** \brief Smallest elevation of the camera above the table plane, in degrees,
   * in (0, 90). */
  float min_elevation_deg = 30.0f;
  /** \brief Largest elevation of the camera above the table plane, in degrees, in
   * [min_elevation_deg, 90). */
  float max_elevation_deg = 60.0f;
  /** \brief Extent of the table top along x, in metres. */
  float table_width = 1.2f;
  /** \brief Extent of the table top along y, in metres. */
  float table_depth = 0.8f;
  /** \brief Radius of the disc about the table centre that holds the objects'
   * footprints, in metres; at most half the table's smaller side. */
  float layout_radius = 0.25f;
  /** \brief Probability in [0, 1] that an object (after the first) is placed close
   * to one already placed, at a gap drawn in [min_close_gap, max_close_gap];
   * otherwise it is placed at least \a min_far_gap from all. */
  float close_probability = 0.5f;
  /** \brief Smallest gap of close objects, in metres; every two objects are at
   * least this far apart. Gaps are distances between footprints (the objects'
   * outlines seen from above), which bound the distances in space from below. */
  float min_close_gap = 0.01f;
  /** \brief Largest gap of close objects, in metres. */
  float max_close_gap = 0.03f;
  /** \brief Smallest gap between an object placed far and every other, in metres. */
  float min_far_gap = 0.06f;
  /** \brief Depth noise: standard deviation noise_coefficient * z^2 at depth z, in
   * metres (noise_coefficient in 1/m). */
  float noise_coefficient = 1.5e-3f;
  /** \brief Distance from the camera to the projector along the camera's x axis, in
   * metres. */
  float baseline = 0.075f;
  /** \brief Step of the disparity quantization, in pixels; 0: no quantization. */
  float disparity_step = 0.125f;
  /** \brief Angle of incidence at which pixels start to drop out, in degrees. */
  float grazing_start_deg = 60.0f;
  /** \brief Angle of incidence from which all pixels drop out, in degrees, from
   * grazing_start_deg to 90. */
  float grazing_full_deg = 85.0f;
  /** \brief Lose the pixels the projector does not light (shadows of objects). */
  bool projector_shadows = true;
  /** \brief Set the table pixels to NaN (label DEPTH_BACKGROUND_LABEL), as after
   * removing the table plane; the random draws and the object pixels are the same
   * either way. */
  bool remove_table = true;
  /** \brief Seed of the random generator; equal seeds give identical scenes. */
  std::uint64_t seed = 0;
};

/** \brief Ground truth of one object of a depth camera scene. */
struct DepthCameraObject {
  /** \brief Kind of object. */
  DepthObjectKind kind = DepthObjectKind::BOWL;
  /** \brief Label of its points (DEPTH_FIRST_OBJECT_LABEL + index in the scene). */
  std::uint32_t label = DEPTH_FIRST_OBJECT_LABEL;
  /** \brief Centre of its footprint on the table (world frame, z = 0). */
  Eigen::Vector3f position = Eigen::Vector3f::Zero();
  /** \brief Rotation about the z axis, in radians. */
  float yaw = 0.0f;
  /** \brief Side lengths of its bounding box in its own frame (before the yaw);
   * bowl: (2 R, 2 R, R) for the outer radius R; cone: (2 r, 2 r, height) for the
   * bottom radius r; ring: (2 (R + r), 2 (R + r), 2 r) for the radii R of the
   * centre circle and r of the tube; L-shaped block: (length, width, height), the
   * upright slab at +x; capsule: (length + 2 r, 2 r, 2 r), its axis along x. */
  Eigen::Vector3f dimensions = Eigen::Vector3f::Zero();
  /** \brief Radius of the top of a cone (0 for the other kinds), in metres. */
  float top_radius = 0.0f;
  /** \brief Distance from its footprint to the nearest other object's footprint,
   * in metres (infinite when it is alone). */
  float gap = 0.0f;
  /** \brief Red of its colour before shading. */
  std::uint8_t r = 0;
  /** \brief Green of its colour before shading. */
  std::uint8_t g = 0;
  /** \brief Blue of its colour before shading. */
  std::uint8_t b = 0;
  /** \brief Number of its points (pixels) in the cloud. */
  std::size_t num_points = 0;
};

/** \brief A generated depth camera scene with its ground truth. */
struct DepthCameraScene {
  /** \brief The organized frame, width x height pixels, in the camera's optical
   * frame (x right, y down, z forward; the sensor origin is 0): one point per pixel,
   * label DEPTH_BACKGROUND_LABEL for the table and the lost pixels (NaN
   * coordinates, colour 0), DEPTH_FIRST_OBJECT_LABEL + k for object k. Colours are
   * the object colours shaded by the angle of incidence. */
  pcl::PointCloud<pcl::PointXYZRGBL>::Ptr cloud;
  /** \brief The objects, in label order. */
  std::vector<DepthCameraObject> objects;
  /** \brief Pose of the camera: maps camera coordinates to world coordinates. */
  Eigen::Isometry3f camera_pose = Eigen::Isometry3f::Identity();
  /** \brief Distance from the camera to the table centre, in metres. */
  float distance = 0.0f;
  /** \brief Elevation of the camera above the table plane, in degrees. */
  float elevation_deg = 0.0f;
  /** \brief Coefficients (a, b, c, d) of the table plane ax + by + cz + d = 0 in the
   * camera frame, (a, b, c) its unit normal pointing towards the camera. */
  Eigen::Vector4f table_plane = Eigen::Vector4f::Zero();
  /** \brief Number of table pixels measured (before any removal by
   * \a remove_table). */
  std::size_t num_table_points = 0;
};

/** \brief Generates a depth camera scene: a table with 3 to 6 (by default) objects
 * of five kinds, seen by a simulated structured-light depth camera.
 *
 * Count, kinds, sizes (extents of 2.4 to 23 cm), poses, colours and the camera
 * pose are drawn from the seed. Each object after the first is placed close to a
 * random earlier one (footprint gap in [min_close_gap, max_close_gap]) or far from
 * all (gap at least min_far_gap), inside the layout disc. Objects may hide parts of
 * one another, as in real frames; num_points tells how much of each is seen.
 * \throws pcl::BadArgumentException on invalid parameters, or when no layout is
 * found (objects too many or gaps too large for the layout disc) */
DepthCameraScene
generateDepthCameraScene (const DepthCameraParameters& parameters);

} // namespace tda
} // namespace pcl
