#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_diagram.h>
#include <pcl/tda/common/progress.h>
#include <pcl/tda/common/resource_settings.h>
#include <pcl/tda/segmentation/color_regions.h>
#include <pcl/tda/segmentation/homogeneity_graph.h>
#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/PointIndices.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Whether \a normal can orient its point in PersistentRegionGrowingRGB:
 * finite and not zero (a point without one is left out when normals are given). */
template <typename NormalT>
bool
isUsableNormal (const NormalT& normal)
{
  return pcl::isNormalFinite (normal) &&
         normal.getNormalVector3fMap().squaredNorm() > 0.0f;
}

/** \brief Region growing on colour and normals by topological persistence (thesis
 * Sec 4.2, Alg 4.7): a seed-free, order-independent drop-in beside
 * pcl::RegionGrowingRGB that compares colours perceptually and says how stable each
 * region is.
 *
 * The points (the finite ones among the indices, with finite normals when normals
 * are set) are the vertices of the radius graph of max distance r. Colours are
 * compared in CIELAB (Delta E76, Eq 4.5; each colour converted once, D65), after a
 * median filter over each point's neighbours (setColorSmoothing()), normals (set, or
 * estimated from the graph with setEstimateNormals()) by the angle between them
 * (Eq 4.6, on |u . v|, so that flipped normals do not matter).
 * Like pcl::RegionGrowingRGB, with its point and region colour thresholds, it grows
 * in two filtrations, each an H0 persistence computation (union-find and the elder
 * rule on a minimum spanning forest), so that the result is seed-free and does not
 * depend on the order of anything:
 *
 * 1. Points (Alg 4.7, Sec 4.2.6): each edge of the radius graph is valued by the
 *    Delta E of its ends, or by infinity when their normals differ by more than the
 *    angle threshold. The components of the edges of value <= the colour threshold
 *    (setColorThreshold()) are patches: connected (Eq 4.2), homogeneous between
 *    neighbours (4.3). Patches under the minimum size join their most similar
 *    neighbour by mean colour (Sec 4.2.5, mergeSmallRegions()), and points farther
 *    than the radius from every region join the most similar of their nearest
 *    region points (attachIsolatedPoints()), so that the regions cover the cloud
 *    (Eq 4.1), except specks of another colour (setMaxMergeColorDifference());
 *    setMergeSmallRegions(false) leaves all of them out instead.
 * 2. Regions: adjacent patches (joined by an edge whose normals agree) are valued
 *    by the Delta E of their mean colours; the components of the pairs within the
 *    region colour threshold (setRegionColorThreshold(), 0: off) are the regions
 *    (4.4: adjacent regions differ). Means do not drift along a colour gradient, so
 *    a region does not leak into the next through a blurred or shaded border the way
 *    point-to-point growing does. The bars of this filtration (getRegionBarcode())
 *    say over which thresholds each region stays as it is, and
 *    setAutoColorThreshold(true) chooses the threshold from them.
 *
 * The regions are sorted largest first (equal sizes by their first point in
 * (x, y, z) order), each sorted, with the header of the input; they do not depend on
 * the input order or the number of threads. getPersistenceDiagram() is the H0
 * diagram of the first filtration (or of the thesis' filtration by distance,
 * setFiltration()).
 *
 * \code
 * pcl::tda::PersistentRegionGrowingRGB<pcl::PointXYZRGB, pcl::Normal> rg;
 * rg.setInputCloud(cloud);
 * rg.setInputNormals(normals);   // optional: colour only without
 * rg.setMaxDistance(0.01);
 * rg.setColorThreshold(6.0);          // Delta E between neighbours
 * rg.setAutoColorThreshold(true);      // Delta E between regions: from the bars
 * rg.setNormalAngleThreshold(10.0);
 * rg.setMinClusterSize(50);
 * std::vector<pcl::PointIndices> regions;
 * rg.extract(regions);
 * \endcode
 */
template <typename PointT, typename NormalT = pcl::Normal>
class PersistentRegionGrowingRGB : public pcl::PCLBase<PointT>,
                                   public ResourceSettings {
public:
  using Ptr = shared_ptr<PersistentRegionGrowingRGB<PointT, NormalT>>;
  using ConstPtr = shared_ptr<const PersistentRegionGrowingRGB<PointT, NormalT>>;
  using PointCloud = pcl::PointCloud<PointT>;
  using Normals = pcl::PointCloud<NormalT>;
  using NormalsConstPtr = typename Normals::ConstPtr;

  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  /** \brief The value of the filtration whose H0 diagram getPersistenceDiagram()
   * gives; the regions are the same for both. */
  enum class Filtration {
    /** Edges valued by the colour difference Delta E of their ends: the bars say
     * at which threshold each region joins another. */
    COLOR,
    /** The thesis' Alg 4.7: edges valued by their length, only the similar pairs
     * (Delta E <= the threshold, normals within the angle). */
    DISTANCE
  };

  /** \brief Default of setColorThreshold(), in Delta E76. */
  static constexpr double DEFAULT_COLOR_THRESHOLD = 3.0;
  /** \brief Default of setRegionColorThreshold(), in Delta E76. */
  static constexpr double DEFAULT_REGION_COLOR_THRESHOLD = 10.0;
  /** \brief Default of setNormalAngleThreshold(), in degrees (pcl::RegionGrowing's
   * default smoothness threshold). */
  static constexpr double DEFAULT_NORMAL_ANGLE = 30.0;
  /** \brief Default of setAutoMinColorThreshold(): about a just noticeable
   * difference, in Delta E76. */
  static constexpr double DEFAULT_AUTO_MIN_COLOR_THRESHOLD = 2.3;
  /** \brief Default of setAutoGapRatio(). */
  static constexpr double DEFAULT_GAP_RATIO = 1.5;
  /** \brief Default of setMaxMergeColorDifference(), in Delta E76: colours this far
   * apart are different colours to anyone (the white and the red of a label), while
   * the fragments that colour noise breaks off a region stay well within it. */
  static constexpr double DEFAULT_MAX_MERGE_COLOR_DIFFERENCE = 30.0;
  /** \brief Nearest region points a point far from every region chooses from
   * (attachIsolatedPoints()). */
  static constexpr std::size_t ISOLATED_NEIGHBORS = 8;
  /** \brief The colour smoothing takes the neighbours within, and changes a colour
   * by at most, this many times the colour threshold, or 3 times the noise if that
   * is more (medianSmoothedColors()). */
  static constexpr double SMOOTHING_RANGE = 2.5;
  /** \brief Bytes per edge of the radius graph at the peak of extract(): the graph
   * and the copy of its similar edges for the spanning forest. */
  static constexpr std::size_t BYTES_PER_EDGE = 2 * sizeof (FilteredEdge);

  PersistentRegionGrowingRGB() = default;

  /** \brief Sets the normals, one per input point (same size as the input cloud);
   * without them (the default) only colours are compared. */
  void
  setInputNormals (const NormalsConstPtr& normals)
  {
    normals_ = normals;
  }

  NormalsConstPtr
  getInputNormals () const
  {
    return normals_;
  }

  /** \brief Whether, when no normals are set, each point's normal is estimated from
   * its neighbours in the graph (neighborNormals(): the PCA normal of
   * pcl::NormalEstimation with a radius search of the max distance, without a second
   * search) and compared (default false: colours only). */
  void
  setEstimateNormals (bool enabled)
  {
    estimate_normals_ = enabled;
  }

  bool
  getEstimateNormals () const
  {
    return estimate_normals_;
  }

  /** \brief Sets the radius r of the neighbour graph (> 0): points at most r apart
   * are neighbours. */
  void
  setMaxDistance (double max_distance)
  {
    max_distance_ = max_distance;
  }

  double
  getMaxDistance () const
  {
    return max_distance_;
  }

  /** \brief Sets the fewest neighbours of a point (default 0): a point with fewer
   * within the max distance is also joined to its 3 k nearest points
   * (addNearestNeighbors()), so that sparse parts of a cloud, e.g. the far side of a
   * depth frame whose rows of points lie farther apart than the radius, are not cut
   * into strips. 0 keeps the pure radius graph of the thesis. */
  void
  setMinNeighbors (std::size_t k)
  {
    min_neighbors_ = k;
  }

  std::size_t
  getMinNeighbors () const
  {
    return min_neighbors_;
  }

  /** \brief Sets the longest edge between neighbouring pixels per unit of range
   * (>= 0, default 0: off). With an organized input (a depth image), each point is
   * also joined to those of its 8 neighbours in the image that lie beyond the max
   * distance but within \a ratio times the range of the nearer one (its distance
   * from the cloud's sensor_origin_; addImageNeighbors()): the rows of a surface
   * seen at a grazing angle, farther apart than the max distance, then stay one
   * surface, while the jumps in depth at an object's outline stay cut. Unorganized
   * inputs are not affected, nor are those one pixel wide (a list of points written
   * as a column, WIDTH 1: not an image). */
  void
  setImageNeighborRatio (double ratio)
  {
    image_neighbor_ratio_ = ratio;
  }

  double
  getImageNeighborRatio () const
  {
    return image_neighbor_ratio_;
  }

  /** \brief Sets the colour threshold of the first filtration (> 0, default
   * DEFAULT_COLOR_THRESHOLD): the largest Delta E76 between the CIELAB colours of two
   * neighbours in one patch (pcl::RegionGrowingRGB's point colour threshold). */
  void
  setColorThreshold (double delta_e)
  {
    color_threshold_ = delta_e;
  }

  double
  getColorThreshold () const
  {
    return color_threshold_;
  }

  /** \brief Sets the colour threshold of the second filtration (>= 0, default
   * DEFAULT_REGION_COLOR_THRESHOLD): the largest Delta E76 between the mean colours
   * of two adjacent patches in one region (pcl::RegionGrowingRGB's region colour
   * threshold); 0 leaves the patches as they are, as the thesis does. With
   * setAutoColorThreshold(true) it bounds the search instead. */
  void
  setRegionColorThreshold (double delta_e)
  {
    region_color_threshold_ = delta_e;
  }

  double
  getRegionColorThreshold () const
  {
    return region_color_threshold_;
  }

  /** \brief Sets the largest angle between the normals of two similar neighbours,
   * in degrees, in (0, 90] (default DEFAULT_NORMAL_ANGLE); used only with normals
   * (set or estimated). */
  void
  setNormalAngleThreshold (double degrees)
  {
    normal_angle_ = degrees;
  }

  double
  getNormalAngleThreshold () const
  {
    return normal_angle_;
  }

  /** \brief Whether the colours are compared after a median filter over each
   * point's neighbours (medianSmoothedColors(); default true), which removes sensor
   * colour noise and keeps the borders between colours sharp; false compares the
   * raw colours, as the thesis does. */
  void
  setColorSmoothing (bool enabled)
  {
    color_smoothing_ = enabled;
  }

  bool
  getColorSmoothing () const
  {
    return color_smoothing_;
  }

  /** \brief Sets the smallest number of points of a region (default 1); smaller
   * components are merged or left out, see setMergeSmallRegions(). */
  void
  setMinClusterSize (pcl::uindex_t min_cluster_size)
  {
    min_pts_per_cluster_ = min_cluster_size;
  }

  pcl::uindex_t
  getMinClusterSize () const
  {
    return min_pts_per_cluster_;
  }

  /** \brief Sets the largest number of points of a region (default: no limit);
   * larger regions are left out with a PCL_WARN, as pcl::RegionGrowing drops them. */
  void
  setMaxClusterSize (pcl::uindex_t max_cluster_size)
  {
    max_pts_per_cluster_ = max_cluster_size;
  }

  pcl::uindex_t
  getMaxClusterSize () const
  {
    return max_pts_per_cluster_;
  }

  /** \brief Whether components under the minimum size join their most similar
   * neighbour (true, the default; see mergeSmallRegions() for the rule) or are left
   * out as noise (false). */
  void
  setMergeSmallRegions (bool merge)
  {
    merge_small_regions_ = merge;
  }

  bool
  getMergeSmallRegions () const
  {
    return merge_small_regions_;
  }

  /** \brief Sets the largest Delta E76 between a component under the minimum size
   * and the region it joins (default DEFAULT_MAX_MERGE_COLOR_DIFFERENCE; infinity
   * joins every one to its most similar neighbour, as pcl::RegionGrowingRGB joins
   * them to the nearest): a smaller patch farther than this from every neighbouring
   * region, a speck of another colour too small to be a region, is left out (no
   * region, label 0 in pcl_tda_regions) rather than painted into a region of
   * another colour. Used when setMergeSmallRegions(true). */
  void
  setMaxMergeColorDifference (double delta_e)
  {
    max_merge_color_difference_ = delta_e;
  }

  double
  getMaxMergeColorDifference () const
  {
    return max_merge_color_difference_;
  }

  /** \brief Chooses the filtration of getPersistenceDiagram() (default
   * Filtration::COLOR). */
  void
  setFiltration (Filtration filtration)
  {
    filtration_ = filtration;
  }

  Filtration
  getFiltration () const
  {
    return filtration_;
  }

  /** \brief Sets the number of steps of the thesis' stepped filtration (Sec 4.5.1):
   * the diagram's deaths are rounded up to multiples of end / n, where the end is
   * the colour threshold (Filtration::COLOR) or the max distance (DISTANCE), and the
   * deaths beyond it set to it. 0 (the default) keeps the exact values over the
   * whole filtration. The regions are the same. */
  void
  setFiltrationSteps (unsigned int steps)
  {
    filtration_steps_ = steps;
  }

  unsigned int
  getFiltrationSteps () const
  {
    return filtration_steps_;
  }

  /** \brief Lets extract() choose the region colour threshold from the region
   * barcode (default false), in [auto min threshold, region colour threshold]; the
   * region colour threshold is then the upper bound of the search. Every patch has a
   * bar from 0 to the threshold at which it joins a larger patch, so the number of
   * regions is a step function of the threshold; the longest of its steps (by
   * log(high / low)) with two regions or more is taken when it is clear (at least
   * the gap ratio times as long as every other), otherwise the first that spans a
   * factor of at least the gap ratio, and the threshold is its geometric middle
   * (chooseColorThreshold()): regions that stay the same over a wide range of
   * thresholds, not yet merged with regions of a close colour. When no step is that
   * long, DEFAULT_REGION_COLOR_THRESHOLD is used, with a PCL_WARN. Only ratios enter;
   * deterministic and independent of the input order and the number of threads. */
  void
  setAutoColorThreshold (bool enabled)
  {
    auto_color_threshold_ = enabled;
  }

  bool
  getAutoColorThreshold () const
  {
    return auto_color_threshold_;
  }

  /** \brief Sets the floor of the automatic threshold (> 0, default
   * DEFAULT_AUTO_MIN_COLOR_THRESHOLD): no threshold below it is chosen. */
  void
  setAutoMinColorThreshold (double delta_e)
  {
    auto_min_color_threshold_ = delta_e;
  }

  double
  getAutoMinColorThreshold () const
  {
    return auto_min_color_threshold_;
  }

  /** \brief Sets the gap ratio q (> 1, default DEFAULT_GAP_RATIO) of the automatic
   * threshold. */
  void
  setAutoGapRatio (double ratio)
  {
    gap_ratio_ = ratio;
  }

  double
  getAutoGapRatio () const
  {
    return gap_ratio_;
  }

  /** \brief Sets a callback told the progress of the graph's construction, the
   * longest phase. */
  void
  setProgressCallback (const ProgressCallback& progress)
  {
    progress_ = progress;
  }

  /** \brief Extracts the regions of the input points (or of the indexed ones). On
   * failure (no input, normals of another size than the cloud, no usable point, a
   * parameter out of range, a graph over the memory limit) prints a PCL_ERROR naming
   * the problem and leaves \a regions empty. */
  void
  extract (std::vector<pcl::PointIndices>& regions);

  /** \brief The H0 diagram of the last extract() (see setFiltration()); zero-length
   * intervals are left out, essential intervals have death infinity. */
  const PersistenceDiagram&
  getPersistenceDiagram () const
  {
    return diagram_;
  }

  /** \brief The lifetime of each region of the last extract(), in the order of the
   * regions: the range of region colour thresholds over which it is exactly this
   * region (mergeSimilarRegions()). Without the second filtration: the colour
   * thresholds from which its patch has the minimum size to the one at which it
   * joins an older patch (regionsAtThreshold()); patches made only by merging small
   * ones have birth = death = the threshold. */
  const std::vector<RegionLifetime>&
  getRegionLifetimes () const
  {
    return lifetimes_;
  }

  /** \brief The region barcode of the last extract(): the bars of the second
   * filtration (mergeSimilarRegions()), one per patch, from 0 to the region colour
   * threshold at which it joins a larger patch; the number of bars alive at a
   * threshold is its number of regions, and the automatic threshold is read from
   * it. Without the second filtration, the bars of the patches over the first
   * (regionsAtThreshold()). */
  const PersistenceDiagram&
  getRegionBarcode () const
  {
    return region_barcode_;
  }

  /** \brief The region colour threshold of the last extract(): the set one, or the
   * one chosen by setAutoColorThreshold(true). */
  double
  getChosenRegionColorThreshold () const
  {
    return chosen_region_threshold_;
  }

  /** \brief Whether the automatic threshold of the last extract() came from a clear
   * gap; when not, extract() printed a PCL_WARN. False without it. */
  bool
  getAutoColorThresholdIsClear () const
  {
    return auto_threshold_is_clear_;
  }

  /** \brief Number of edges of the neighbour graph of the last extract(). */
  std::size_t
  getNumEdges () const
  {
    return num_edges_;
  }

  /** \brief Number of indexed points left out of the last extract() for a
   * non-finite position or normal. */
  std::size_t
  getNumSkippedPoints () const
  {
    return num_skipped_points_;
  }

  /** \brief The input cloud coloured by the regions of the last extract(), as
   * pcl::RegionGrowing::getColoredCloud() gives it: each region in its own colour
   * (the Glasbey table, by region order), the other points white; null before a
   * successful extract(). The cloud is the one of that extract(), also when the
   * input has been replaced since. */
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr
  getColoredCloud () const;

protected:
  /** \brief The class name, as PCL's classes report it in their messages. */
  const std::string&
  getClassName () const
  {
    return class_name_;
  }

private:
  /** Prints a PCL_ERROR for the first invalid parameter or input; true when all are
   * valid. */
  bool
  checkParameters () const;

  /** The usable indexed points in canonical order, as vertices; their input indices
   * in \a point_of. */
  void
  gatherVertices (HomogeneityVertices& vertices, pcl::Indices& point_of);

  NormalsConstPtr normals_;
  bool estimate_normals_ = false;
  std::size_t min_neighbors_ = 0;
  double image_neighbor_ratio_ = 0.0;
  double max_distance_ = 0.0;
  double color_threshold_ = DEFAULT_COLOR_THRESHOLD;
  double region_color_threshold_ = DEFAULT_REGION_COLOR_THRESHOLD;
  double normal_angle_ = DEFAULT_NORMAL_ANGLE;
  bool color_smoothing_ = true;
  pcl::uindex_t min_pts_per_cluster_ = 1;
  pcl::uindex_t max_pts_per_cluster_ = std::numeric_limits<pcl::uindex_t>::max();
  bool merge_small_regions_ = true;
  double max_merge_color_difference_ = DEFAULT_MAX_MERGE_COLOR_DIFFERENCE;
  Filtration filtration_ = Filtration::COLOR;
  unsigned int filtration_steps_ = 0;
  bool auto_color_threshold_ = false;
  double auto_min_color_threshold_ = DEFAULT_AUTO_MIN_COLOR_THRESHOLD;
  double gap_ratio_ = DEFAULT_GAP_RATIO;
  ProgressCallback progress_;

  PersistenceDiagram diagram_;
  std::vector<RegionLifetime> lifetimes_;
  PersistenceDiagram region_barcode_;
  std::vector<pcl::PointIndices> last_regions_;
  /** The cloud of the last successful extract(), which last_regions_ index (the input
   * may have been replaced since). */
  typename pcl::PointCloud<PointT>::ConstPtr extracted_cloud_;
  double chosen_region_threshold_ = 0.0;
  bool auto_threshold_is_clear_ = false;
  std::size_t num_edges_ = 0;
  std::size_t num_skipped_points_ = 0;
  std::string class_name_ = "PersistentRegionGrowingRGB";
};

} // namespace tda
} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl/tda/segmentation/impl/persistent_region_growing_rgb.hpp>
#endif
