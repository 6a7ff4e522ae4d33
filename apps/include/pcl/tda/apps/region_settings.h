#pragma once

#include <pcl/tda/segmentation/persistent_region_growing_rgb.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>

namespace pcl {
namespace tda {

/** \brief The region growing class as the tools use it, on XYZRGB points. */
using ToolRegionGrowing = PersistentRegionGrowingRGB<pcl::PointXYZRGB, pcl::Normal>;

/** \brief The settings of pcl_tda_regions, with its defaults: what
 * `pcl_tda_regions in.pcd out.pcd` does with no options, and what the benchmark
 * measures as our default. */
struct RegionSettings {
  /** \brief The default radius, in units of the cloud's spacing. */
  static constexpr double RADIUS_PER_SPACING = 1.1;
  /** \brief The spacing is measured to the SPACING_NEIGHBOR-th nearest point: about
   * the eight neighbours of a point on a grid, also across the scan lines. */
  static constexpr std::size_t SPACING_NEIGHBOR = 6;
  /** \brief The quantile of those distances that is the spacing. */
  static constexpr double SPACING_QUANTILE = 0.9;
  /** \brief Upper bound of the automatic region colour threshold (Delta E76). */
  static constexpr double MAX_AUTO_COLOR_THRESHOLD = 40.0;
  /** \brief Fewest neighbours of a point: points with fewer within the radius are
   * also joined to their nearest points (setMinNeighbors()). */
  static constexpr std::size_t MIN_NEIGHBORS = 5;
  /** \brief Default longest edge between neighbouring pixels of an organized cloud
   * per unit of range (setImageNeighborRatio()): twice the gap between the pixels of a
   * 640-pixel, 58-degree depth camera on a surface seen at 80 degrees from its
   * normal (1.6 mrad / cos 80 = 0.0093 per unit of range). */
  static constexpr double IMAGE_NEIGHBOR_RATIO = 0.02;

  /** \brief Radius of the neighbour graph; 0: RADIUS_PER_SPACING times the
   * cloud's spacing (regionRadius()). */
  double radius = 0.0;
  /** \brief Colour threshold of the first filtration (between neighbours). */
  double point_color = ToolRegionGrowing::DEFAULT_COLOR_THRESHOLD;
  /** \brief Colour threshold of the second (between adjacent patches); 0: chosen
   * automatically up to MAX_AUTO_COLOR_THRESHOLD. */
  double region_color = 0.0;
  /** \brief Largest angle between the normals of neighbours, in degrees. */
  double angle = ToolRegionGrowing::DEFAULT_NORMAL_ANGLE;
  /** \brief Compare normals (the input's, or estimated from the neighbour graph). */
  bool use_normals = true;
  /** \brief Longest edge between neighbouring pixels of an organized cloud per unit
   * of range (0: the image is not used). */
  double image_ratio = IMAGE_NEIGHBOR_RATIO;
  /** \brief Smallest region, in points. */
  pcl::uindex_t min_size = 20;
};

/** \brief The radius of \a settings, or the default one: RADIUS_PER_SPACING times
 * the SPACING_QUANTILE quantile of the distances to the SPACING_NEIGHBOR-th nearest
 * point (pointSpacing()), which follows the sparser parts of a cloud and the gaps
 * between scan lines. 0 when the cloud has fewer than
 * two distinct finite points. */
double
regionRadius (const RegionSettings& settings,
              const pcl::PointCloud<pcl::PointXYZRGB>& cloud);

/** \brief Sets up \a growing with \a settings, the \a radius and the \a normals (null:
 * estimated from the neighbour graph when settings.use_normals, else colours only).
 */
void
configureRegionGrowing (ToolRegionGrowing& growing,
                        const RegionSettings& settings,
                        double radius,
                        const pcl::PointCloud<pcl::Normal>::ConstPtr& normals);

} // namespace tda
} // namespace pcl
