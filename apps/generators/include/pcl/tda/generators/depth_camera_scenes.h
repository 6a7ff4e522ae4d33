#pragma once

// Depth camera scenes: bowls, cones, rings, L-shaped blocks and lying capsules on a
// table, ray-cast by a simulated structured-light depth camera into an organized
// frame, each object labelled. A second scene generator, made independently of
// tabletop_scenes.h (other objects, camera, noise and density), to validate
// choices tuned on the first; optionally with the objects painted in colour
// regions, as ground truth for the segmentation of colour regions.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <utility>
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

/** \brief Smallest colour difference (CIE76 Delta E in CIELAB, D65) between the two
 * tones of an object painted in subtle colour regions (DepthCameraScene::
 * similar_regions). */
constexpr float DEPTH_SUBTLE_MIN_DELTA_E = 11.0f;
/** \brief Largest colour difference (CIE76 Delta E) between the two tones of an
 * object painted in subtle colour regions. */
constexpr float DEPTH_SUBTLE_MAX_DELTA_E = 17.0f;
/** \brief Smallest colour difference (CIE76 Delta E) between the two tones of an
 * object painted in contrasting colour regions. */
constexpr float DEPTH_CONTRAST_MIN_DELTA_E = 30.0f;
/** \brief Smallest colour difference (CIE76 Delta E) between the table and every
 * object region. */
constexpr float DEPTH_TABLE_MIN_DELTA_E = 25.0f;
/** \brief Smallest colour difference (CIE76 Delta E) between regions of different
 * objects. */
constexpr float DEPTH_OBJECTS_MIN_DELTA_E = 10.0f;

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
  /** \brief Colour noise, in 0-255 levels: each measured pixel's colour, after
   * shading, gets a brightness offset common to its three channels with this
   * standard deviation plus an offset per channel with half of it, both Gaussian
   * truncated at 4 standard deviations; the sum is rounded and clamped to 0-255.
   * Drawn from a random generator of its own, seeded from \a seed, so that the
   * depths and labels do not depend on it; 0: no colour noise. */
  float colour_noise = 0.0f;
  /** \brief Paint each object in two tones, as colour regions: a bowl outside
   * (with the rim) and inside; a cone below and above a height drawn in 35-65 % of
   * its height; a ring in two halves; an L-shaped block's base and upright; a
   * capsule's middle and its two ends (three regions, both ends in the second
   * tone). The first tone is the object's colour (DepthCameraObject::r, g, b),
   * the second one differs from it by DEPTH_SUBTLE_MIN_DELTA_E to
   * DEPTH_SUBTLE_MAX_DELTA_E (subtle, half of the objects on average) or by at
   * least DEPTH_CONTRAST_MIN_DELTA_E; every tone is at least
   * DEPTH_TABLE_MIN_DELTA_E from the table's colour and DEPTH_OBJECTS_MIN_DELTA_E
   * from the tones of the other objects. Drawn from a random generator of its own,
   * seeded from \a seed: the depths and object labels are those of the scene
   * without painting. */
  bool colour_regions = false;
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
  /** \brief Red of its colour before shading (with
   * DepthCameraParameters::colour_regions, of its first tone). */
  std::uint8_t r = 0;
  /** \brief Green of its colour before shading. */
  std::uint8_t g = 0;
  /** \brief Blue of its colour before shading. */
  std::uint8_t b = 0;
  /** \brief Number of its points (pixels) in the cloud. */
  std::size_t num_points = 0;
};

/** \brief Ground truth of one colour region of a depth camera scene: the table
 * (when kept), an object (without painting) or one painted part of an object. */
struct DepthColourRegion {
  /** \brief Its label in DepthCameraScene::region_labels (its index in
   * DepthCameraScene::regions plus 1). */
  std::uint32_t label = 1;
  /** \brief Label of its object in the cloud (DEPTH_FIRST_OBJECT_LABEL + k), or
   * DEPTH_BACKGROUND_LABEL for the table. */
  std::uint32_t object_label = DEPTH_BACKGROUND_LABEL;
  /** \brief Which part of its object it is: 0 for the table and for unpainted
   * objects; bowl: 0 outside and rim, 1 inside; cone: 0 lower, 1 upper part; ring:
   * 0 the half at y < 0 of its own frame, 1 the other; L-shaped block: 0 base, 1
   * upright; capsule: 0 the end at -x, 1 the middle, 2 the end at +x. */
  std::uint32_t part = 0;
  /** \brief Red of its colour before shading and noise. */
  std::uint8_t r = 0;
  /** \brief Green of its colour before shading and noise. */
  std::uint8_t g = 0;
  /** \brief Blue of its colour before shading and noise. */
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
   * the object (or region) colours shaded by the angle of incidence, plus the
   * colour noise. */
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
  /** \brief Colour region of each pixel (same order as the cloud): 0 for the lost
   * pixels and the removed table, else a label from 1 up to regions.size(),
   * contiguous. Without DepthCameraParameters::colour_regions every object is one
   * region. */
  std::vector<std::uint32_t> region_labels;
  /** \brief The colour regions that have points, in label order: the table when
   * it is kept, then the regions of object 0 by part, of object 1, and so on. */
  std::vector<DepthColourRegion> regions;
  /** \brief Labels (a, b), a < b, of the adjacent regions of the objects painted in
   * subtle tones, in increasing order (empty without
   * DepthCameraParameters::colour_regions). */
  std::vector<std::pair<std::uint32_t, std::uint32_t>> similar_regions;
};

/** \brief Generates a depth camera scene: a table with 3 to 6 (by default) objects
 * of five kinds, seen by a simulated structured-light depth camera.
 *
 * Count, kinds, sizes (extents of 2.4 to 23 cm), poses, colours and the camera
 * pose are drawn from the seed. Each object after the first is placed close to a
 * random earlier one (footprint gap in [min_close_gap, max_close_gap]) or far from
 * all (gap at least min_far_gap), inside the layout disc. Objects may hide parts of
 * one another, as in real frames; num_points tells how much of each is seen.
 * With DepthCameraParameters::colour_regions the objects are painted in two tones,
 * as ground truth for the segmentation of colour regions (DepthCameraScene::regions).
 * \throws pcl::BadArgumentException on invalid parameters, or when no layout is
 * found (objects too many or gaps too large for the layout disc) */
DepthCameraScene
generateDepthCameraScene (const DepthCameraParameters& parameters);

/** \brief A copy of the scene's organized cloud whose labels are the colour region
 * labels (DepthCameraScene::region_labels; 0 for the lost pixels) instead of the
 * object labels. */
pcl::PointCloud<pcl::PointXYZRGBL>::Ptr
regionLabelledCloud (const DepthCameraScene& scene);

} // namespace tda
} // namespace pcl
