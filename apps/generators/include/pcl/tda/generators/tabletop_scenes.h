#pragma once

// Tabletop scenes: boxes, cylinders and spheres on a table as a noisy depth camera
// sees them, each labelled, as ground truth for the segmentation of objects and,
// with the objects painted in several colours, of colour regions.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <utility>
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
/** \brief The largest point spacing of a tabletop scene, in metres: the smallest
 * object must still get a few points. */
constexpr double TABLETOP_MAX_POINT_SPACING = 0.02;

/** \brief Kind of primitive standing on the table of a tabletop scene. */
enum class PrimitiveType { BOX, CYLINDER, SPHERE };

/** \brief Smallest colour difference (CIE76 Delta E in CIELAB, D65) between the
 * colours of two adjacent regions of a tabletop scene painted in colour regions. */
constexpr float SIMILAR_REGION_MIN_DELTA_E = 10.0f;
/** \brief Largest colour difference (CIE76 Delta E) between the two regions of a
 * similar pair (TabletopScene::similar_regions). */
constexpr float SIMILAR_REGION_MAX_DELTA_E = 18.0f;
/** \brief Smallest colour difference (CIE76 Delta E) between a region of an object
 * and every other region of the same object or the table, except its similar
 * partner. */
constexpr float DISTINCT_REGION_MIN_DELTA_E = 25.0f;

/** \brief Depth and colour noise of the camera of a tabletop scene, as a named
 * level (TabletopParameters::setNoise()). */
struct TabletopNoise {
  /** \brief Name of the level ("none", "moderate", "heavy"). */
  const char* name;
  /** \brief Standard deviation of the depth noise at 1 m from the camera, in metres
   * (TabletopParameters::noise_sigma). */
  float depth_sigma;
  /** \brief Standard deviation of the per-channel colour noise, in 0-255 levels
   * (TabletopParameters::colour_noise). */
  float colour_sigma;
};

/** \brief No noise: exact depths and colours. */
inline constexpr TabletopNoise TABLETOP_NO_NOISE = {"none", 0.0f, 0.0f};
/** \brief Moderate noise: depth sigma 0.5 mm at 1 m, colour sigma 4 levels. */
inline constexpr TabletopNoise TABLETOP_MODERATE_NOISE = {"moderate", 0.0005f, 4.0f};
/** \brief Heavy noise: depth sigma 1.5 mm at 1 m, colour sigma 8 levels. */
inline constexpr TabletopNoise TABLETOP_HEAVY_NOISE = {"heavy", 0.0015f, 8.0f};

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
  /** \brief Paint every object in several colour regions instead of one colour:
   * each face of a box its own colour; a cylinder in 2 or 3 horizontal bands and its
   * top cap; a sphere in two halves split by a tilted plane through its centre, or
   * in two caps and the band between them. On each object one pair of regions that
   * share a boundary (one or two disjoint pairs on a box), chosen among the pairs
   * whose regions have at least 15 samples each, is painted only
   * SIMILAR_REGION_MIN_DELTA_E to SIMILAR_REGION_MAX_DELTA_E apart; all other
   * regions of the object and the table are at least DISTINCT_REGION_MIN_DELTA_E
   * apart; regions of different objects are at least SIMILAR_REGION_MIN_DELTA_E
   * apart. Painted channels are within 24-231, so that colour noise up to 8 levels
   * is never clipped. The colours and the region boundaries come from a random
   * generator of their own, seeded from \a seed: the points, their object labels
   * and the noise are those of the scene without painting. */
  bool colour_regions = false;
  /** \brief Seed of the random generator; equal seeds give identical scenes. */
  std::uint64_t seed = 0;

  /** \brief Sets the depth and colour noise to those of \a noise. */
  void
  setNoise (const TabletopNoise& noise)
  {
    noise_sigma = noise.depth_sigma;
    colour_noise = noise.colour_sigma;
  }
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
  /** \brief Colour before noise (with TabletopParameters::colour_regions, the
   * colour of its first region, part 0). */
  std::uint8_t r = 0, g = 0, b = 0;
  /** \brief Number of its points in the cloud. */
  std::size_t num_points = 0;
};

/** \brief Ground truth of one colour region of a tabletop scene: the table, an
 * object (without painting) or one painted part of an object. */
struct TabletopColourRegion {
  /** \brief Its label in TabletopScene::region_labels (its index in
   * TabletopScene::regions plus 1; TABLE_LABEL for the table). */
  std::uint32_t label = TABLE_LABEL;
  /** \brief Label of the object it belongs to in the cloud: TABLE_LABEL for the
   * table, FIRST_OBJECT_LABEL + k for object k. */
  std::uint32_t object_label = TABLE_LABEL;
  /** \brief Which part of its object it is: 0 for the table and for unpainted
   * objects; box: 0 top, 1 side -y, 2 side +y, 3 side -x, 4 side +x (in the box's
   * own frame); cylinder with n bands: 0 to n - 1 the bands from the bottom up, n
   * the top cap; sphere: its parts in order along the (upward) axis of its
   * splitting planes, 0 the lowest (two halves, or a cap, the band and the other
   * cap). */
  std::uint32_t part = 0;
  /** \brief Red of its colour before noise. */
  std::uint8_t r = 0;
  /** \brief Green of its colour before noise. */
  std::uint8_t g = 0;
  /** \brief Blue of its colour before noise. */
  std::uint8_t b = 0;
  /** \brief Number of its points in the cloud. */
  std::size_t num_points = 0;
};

/** \brief A generated tabletop scene with its ground truth. */
struct TabletopScene {
  /** \brief The points: label TABLE_LABEL for the table, FIRST_OBJECT_LABEL + k for
   * object k (also when painted: the colour regions are in \a region_labels and
   * regionLabelledCloud()); sensor_origin_ holds the camera position. Table points come
   * first, then the objects in label order. */
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
  /** \brief Colour region of each point of the cloud (same order): a label from
   * TABLE_LABEL (the table) up to regions.size(), contiguous. Without
   * TabletopParameters::colour_regions every object is one region and the labels
   * equal the cloud's object labels. */
  std::vector<std::uint32_t> region_labels;
  /** \brief The colour regions that have points, in label order: the table, then
   * the regions of object 0 by part, of object 1, and so on. */
  std::vector<TabletopColourRegion> regions;
  /** \brief The similar pairs: labels (a, b), a < b, of adjacent regions of one
   * object whose colours are only SIMILAR_REGION_MIN_DELTA_E to
   * SIMILAR_REGION_MAX_DELTA_E apart, in increasing order (empty without
   * TabletopParameters::colour_regions). */
  std::vector<std::pair<std::uint32_t, std::uint32_t>> similar_regions;
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
 * With TabletopParameters::colour_regions the objects are painted in colour regions,
 * as ground truth for the segmentation of colour regions (TabletopScene::regions).
 * \throws pcl::BadArgumentException on invalid parameters, or when no such layout
 * is found (too many objects or too much noise for the table) */
TabletopScene
generateTabletopScene (const TabletopParameters& parameters);

/** \brief A copy of the scene's cloud whose labels are the colour region labels
 * (TabletopScene::region_labels) instead of the object labels. */
pcl::PointCloud<pcl::PointXYZRGBL>::Ptr
regionLabelledCloud (const TabletopScene& scene);

} // namespace tda
} // namespace pcl
