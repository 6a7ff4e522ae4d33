#pragma once

// Tabletop scenes: boxes, cylinders and spheres on a table as a noisy depth camera
// sees them, each labelled, as ground truth for the segmentation of objects.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Label of the table top in a tabletop scene. */
constexpr std::uint32_t TABLE_LABEL = 1;
/** \brief Label of the first object of a tabletop scene; object k (0-based) has
 * label FIRST_OBJECT_LABEL + k. */
constexpr std::uint32_t FIRST_OBJECT_LABEL = 2;
/** \brief Most objects a tabletop scene holds (one distinct colour each). */
constexpr std::size_t MAX_TABLETOP_OBJECTS = 8;

/** \brief Kind of primitive standing on the table of a tabletop scene. */
enum class PrimitiveType { BOX, CYLINDER, SPHERE };

/** \brief Parameters of generateTabletopScene().
 *
 * The world frame has z up; the table top is the rectangle |x| <= table_width / 2,
 * |y| <= table_depth / 2 of the plane z = 0. A virtual depth camera at
 * \a camera_position looks at the table. Surfaces are sampled on a jittered grid of
 * cell size \a point_spacing; with \a visible_only only the points that face the
 * camera and are not hidden behind another object are kept, as a depth sensor
 * would see them. Each point is then moved along its viewing ray by Gaussian depth
 * noise of standard deviation noise_sigma * (d / 1 m)^2 at distance d from the
 * camera, truncated at 4 standard deviations, and dropped with probability
 * \a dropout. */
struct TabletopParameters {
  /** \brief Number of objects on the table, 0 to MAX_TABLETOP_OBJECTS. */
  std::size_t num_objects = 4;
  /** \brief Extent of the table top along x, in metres. */
  float table_width = 1.0f;
  /** \brief Extent of the table top along y, in metres. */
  float table_depth = 0.7f;
  /** \brief Cell size of the sampling grid, in metres (one point per cell). */
  float point_spacing = 0.01f;
  /** \brief Standard deviation of the depth noise at 1 m from the camera, in
   * metres; it grows with the square of the distance. */
  float noise_sigma = 0.001f;
  /** \brief Standard deviation of the per-channel colour noise, in 0-255 levels,
   * truncated at 3 standard deviations. */
  float colour_noise = 4.0f;
  /** \brief Probability in [0, 1) that a sampled point is dropped. */
  float dropout = 0.0f;
  /** \brief Keep only points facing the camera and not hidden by another object
   * (otherwise every surface except the bottoms resting on the table is sampled). */
  bool visible_only = true;
  /** \brief Guaranteed minimum distance, in metres, between any two points of
   * different objects, noise included. */
  float min_gap = 0.05f;
  /** \brief Position of the virtual camera, in metres; must be above the table. */
  Eigen::Vector3f camera_position = Eigen::Vector3f (0.0f, -0.6f, 1.0f);
  /** \brief Seed of the random generator; equal seeds give identical scenes. */
  std::uint64_t seed = 0;
};

/** \brief Ground truth of one object of a tabletop scene. */
struct TabletopObject {
  /** \brief Kind of primitive. */
  PrimitiveType type = PrimitiveType::BOX;
  /** \brief Label of its points (FIRST_OBJECT_LABEL + index in the scene). */
  std::uint32_t label = FIRST_OBJECT_LABEL;
  /** \brief Centre of the primitive (its bottom rests on z = 0). */
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  /** \brief Side lengths of its bounding box in its own frame: box sides, cylinder
   * (2 radius, 2 radius, height), sphere (2 radius, 2 radius, 2 radius). */
  Eigen::Vector3f dimensions = Eigen::Vector3f::Zero();
  /** \brief Rotation about the z axis, in radians (boxes only; 0 otherwise). */
  float yaw = 0.0f;
  /** \brief Colour before noise. */
  std::uint8_t r = 0, g = 0, b = 0;
  /** \brief Number of its points in the cloud. */
  std::size_t num_points = 0;
};

/** \brief A generated tabletop scene with its ground truth. */
struct TabletopScene {
  /** \brief The points: label TABLE_LABEL for the table, FIRST_OBJECT_LABEL + k for
   * object k; sensor_origin_ holds the camera position. Table points come first,
   * then the objects in label order. */
  pcl::PointCloud<pcl::PointXYZRGBL>::Ptr cloud;
  /** \brief The objects, in label order. */
  std::vector<TabletopObject> objects;
  /** \brief Colour of the table before noise. */
  std::uint8_t table_r = 0, table_g = 0, table_b = 0;
  /** \brief Number of table points in the cloud. */
  std::size_t num_table_points = 0;
  /** \brief Coefficients (a, b, c, d) of the table plane ax + by + cz + d = 0. */
  Eigen::Vector4f table_plane = Eigen::Vector4f (0.0f, 0.0f, 1.0f, 0.0f);
  /** \brief Bound on the displacement of any point by the depth noise, in metres. */
  float max_noise_displacement = 0.0f;
};

/** \brief Generates a tabletop scene: a table with boxes, cylinders and spheres
 * resting on it, each with its own colour, as seen by a noisy depth camera.
 *
 * Types, sizes (5 to 20 cm), poses and colours are drawn from the seed. Objects
 * lie inside the table and are placed so that any two points of different objects
 * are at least \a min_gap apart after noise, and so that no object hides any part
 * of another (objects may hide parts of the table): each object's points form one
 * connected patch. After removing the table plane, Euclidean clustering with a
 * tolerance between about 3 * point_spacing and min_gap recovers the objects.
 * \throws pcl::BadArgumentException on invalid parameters, or when no such layout
 * is found (too many objects or too much noise for the table) */
TabletopScene
generateTabletopScene (const TabletopParameters& parameters);

} // namespace tda
} // namespace pcl
