#pragma once

#include <pcl/search/search.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/common/resource_settings.h>
#include <pcl/pcl_base.h>
#include <pcl/PointIndices.h>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The automatic cluster distance of chooseClusterDistance() and how it was
 * found. */
struct ClusterDistanceChoice {
  /** \brief The chosen distance, in (0, max distance]. */
  double distance = 0.0;
  /** \brief The sampling scale: the median nearest-neighbour distance of the points
   * (0 when no positive distance exists). */
  double sampling_scale = 0.0;
  /** \brief The chosen step [low, high) of the count of significant components
   * (see the rule); distance is the geometric middle of its part after the pieces
   * that join their objects within it. Both 0 when there is none. */
  double low = 0.0;
  double high = 0.0;
  /** \brief The number of significant components in that interval. */
  std::size_t num_clusters = 0;
  /** \brief Whether the H0 diagram shows a clear gap: the step spans a factor of at
   * least the gap ratio q and is at least q times as long (in log) as every other
   * step with two clusters or more. */
  bool clear = false;
};

/** \brief The automatic cluster distance (see
 * PersistentEuclideanClusterExtraction::setAutoMaxDistance(), which states the rule)
 * from the H0 persistence of a complex built up to \a max_distance.
 * \param[in] complex the complex
 * \param[in] h0 the result of computeH0Persistence() on \a complex
 * \param[in] max_distance the end of the filtration
 * \param[in] min_cluster_size components of at least this many points (and at
 * least 2) are the significant ones
 * \param[in] gap_ratio the ratio q (> 1): a split must be stable over a factor q
 * of scales to be taken, and q times longer (in log) than any other to be clear
 * \param[in] min_distance a floor from the caller, e.g. a voxel grid's leaf size
 * \param[in] piece_ratio in [0, 1): a significant component that merges into one
 * with more than 1 / piece_ratio times its points is a piece of it, not a would-be
 * cluster (0: none is)
 * \return the distance, in (0, max_distance], and how it was chosen; max_distance,
 * not clear, when the floor is not below it or no significant component exists */
ClusterDistanceChoice
chooseClusterDistance (const FilteredComplex& complex,
                       const PersistenceResult& h0,
                       double max_distance,
                       std::size_t min_cluster_size,
                       double gap_ratio,
                       double min_distance,
                       double piece_ratio);

/** \brief Euclidean cluster extraction by topological persistence (thesis Sec 4.1,
 * Alg 4.6): a drop-in replacement for pcl::EuclideanClusterExtraction that also
 * gives the H0 persistence diagram, i.e. how stable every cluster is, and can
 * choose its distance by itself.
 *
 * The points (their finite ones among the indices) are the vertices of the radius
 * graph, the 1-skeleton of the Vietoris-Rips complex VR_r at r = max distance; its
 * edges enter the filtration at their lengths. H0 is computed by union-find and the
 * elder rule (Sec 4.1.4): one bar per component, essential bars for the components
 * left at r. The clusters are the point sets joined to the essential classes (Sec
 * 4.1.5) whose size is within [min, max], sorted largest first (equal sizes by
 * smallest index), each sorted, with the header of the input. They do not depend on
 * the input order or the number of threads.
 *
 * Same clusters as pcl::EuclideanClusterExtraction with cluster tolerance r and the
 * same size limits, with two documented conventions:
 * - By default an edge is in when its length, computed in double precision from
 *   the float coordinates, is at most r: an edge of length exactly r is in, as in
 *   VR_r. PCL's k-d tree keeps a neighbour when its squared distance, computed in
 *   float, is strictly below float(r^2): a pair at exactly r is out there, and a
 *   pair within float rounding of r (about 1e-7 r) can fall either way, e.g. on
 *   scans whose coordinates are quantized to a grid that r is a multiple of.
 *   setPCLDistanceTest(true) applies PCL's test instead, for identical clusters
 *   in those cases too.
 * - A component of more than max points is reported (a PCL_WARN and
 *   getNumOversizedClusters()); it is dropped, like PCL does silently, unless
 *   setKeepOversizedClusters(true).
 *
 * \code
 * pcl::tda::PersistentEuclideanClusterExtraction<pcl::PointXYZ> ec;
 * ec.setInputCloud(cloud);
 * ec.setMaxDistance(0.02);
 * ec.setMinClusterSize(32);
 * std::vector<pcl::PointIndices> clusters;
 * ec.extract(clusters);
 * const pcl::tda::PersistenceDiagram& diagram = ec.getPersistenceDiagram();
 * \endcode
 */
template <typename PointT>
class PersistentEuclideanClusterExtraction : public pcl::PCLBase<PointT>,
                                             public ResourceSettings {
public:
  using Ptr = shared_ptr<PersistentEuclideanClusterExtraction<PointT>>;
  using ConstPtr = shared_ptr<const PersistentEuclideanClusterExtraction<PointT>>;
  using PointCloud = pcl::PointCloud<PointT>;
  using KdTree = pcl::search::Search<PointT>;
  using KdTreePtr = typename KdTree::Ptr;

  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  /** \brief Default of setAutoGapRatio(). */
  static constexpr double DEFAULT_GAP_RATIO = 1.5;
  /** \brief Default of setAutoPieceRatio(). */
  static constexpr double DEFAULT_PIECE_RATIO = 0.2;

  PersistentEuclideanClusterExtraction() = default;

  /** \brief Sets a search object for the radius queries (the whole radius graph is
   * then built by VietorisRipsBuilder on it). Without one (the default), uniform
   * grids give the minimum spanning forest of the radius graph scale by scale,
   * looking only at pairs of points not yet joined (radiusGraphSpanningForest()),
   * which is much faster, above all at the large max distance of the automatic
   * distance; the clusters and the diagram are the same. */
  void
  setSearchMethod (const KdTreePtr& tree)
  {
    tree_ = tree;
  }

  KdTreePtr
  getSearchMethod () const
  {
    return tree_;
  }

  /** \brief Sets the filtration's last radius r (> 0): points closer than r (or at
   * exactly r) are in one cluster, as with the cluster tolerance of
   * pcl::EuclideanClusterExtraction. With setAutoMaxDistance(true) it bounds the
   * search for the distance instead. */
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

  /** \brief The name of setMaxDistance() in pcl::EuclideanClusterExtraction, so
   * that code written for it compiles unchanged. */
  void
  setClusterTolerance (double tolerance)
  {
    setMaxDistance (tolerance);
  }

  /** \brief The name of getMaxDistance() in pcl::EuclideanClusterExtraction. */
  double
  getClusterTolerance () const
  {
    return getMaxDistance();
  }

  /** \brief Sets the smallest number of points of a cluster (default 1). */
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

  /** \brief Sets the largest number of points of a cluster (default: no limit);
   * larger components are reported and dropped or kept, see
   * setKeepOversizedClusters(). */
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

  /** \brief Whether components of more than the maximum number of points are kept
   * as clusters (true) or dropped (false, the default, as PCL does). Either way
   * extract() warns about them and getNumOversizedClusters() counts them. */
  void
  setKeepOversizedClusters (bool keep)
  {
    keep_oversized_clusters_ = keep;
  }

  bool
  getKeepOversizedClusters () const
  {
    return keep_oversized_clusters_;
  }

  /** \brief Whether two points are neighbours by PCL's k-d tree test, float squared
   * distance strictly below float(r^2) (true), or by length in double precision at
   * most r (false, the default, as in VR_r). Only pairs within float rounding of r
   * are affected; the diagram keeps their lengths in double precision. */
  void
  setPCLDistanceTest (bool enabled)
  {
    pcl_distance_test_ = enabled;
  }

  bool
  getPCLDistanceTest () const
  {
    return pcl_distance_test_;
  }

  /** \brief Sets the number of steps of the thesis' stepped filtration (Sec 4.4.2):
   * the diagram's death values are rounded up to multiples of max distance / n. 0
   * (the default) keeps the exact edge lengths. The clusters are the same. */
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

  /** \brief Lets extract() choose the cluster distance from the H0 diagram of the
   * filtration up to max distance (default false). The rule (chooseClusterDistance()),
   * with q the gap ratio (setAutoGapRatio()):
   *
   * 1. Would-be clusters. Replaying the minimum spanning forest's edges (the H0
   *    deaths) in order, a component becomes significant when it first has
   *    max(min cluster size, 2) points; the count of significant components rises
   *    by 1 there and falls by 1 when two significant components merge. But a
   *    significant component that merges into one with more than 1 / p times its
   *    points, p the piece ratio (setAutoPieceRatio(), 0.2), is a piece of it (a
   *    part of a scan cut off by a gap in the sampling, a shadow): it is taken off
   *    the count over all the scales it counted. The count is a step function of the
   *    scale.
   * 2. The floor: the larger of the sampling scale, the median nearest-neighbour
   *    distance of the points (each point's shortest spanning forest edge), and the
   *    caller's floor (setAutoMinDistance(), e.g. a voxel leaf). The distance is
   *    never below it.
   * 3. The candidates: the steps of the count over (floor, max distance], each
   *    [low, high) measured by log(high / low). The earliest (finest) step with two
   *    clusters or more that spans a factor of at least q is taken: the first split
   *    that is stable (objects standing close together merge at the later steps,
   *    which may well be much longer). When no split spans q, the longest step with
   *    one cluster (all points one object) is taken, if any.
   * 4. The distance is the geometric middle sqrt(j high) of the part of that step
   *    after the last piece that joins its object within it (j that join's scale;
   *    low when none does): the pieces are not counted, so they should be with their
   *    objects in the clusters too. The choice is clear when the step spans a factor
   *    of at least q and is at least q times as long (in log) as every other step
   *    with two clusters or more; otherwise extract() prints a PCL_WARN and
   *    getAutoDistanceIsClear() is false.
   *
   * Only ratios of scales enter, so the rule does not depend on the units; it is
   * deterministic and, as the diagram, independent of the input order and of the
   * number of threads. Max distance bounds the search and should be a generous upper
   * bound, e.g. twice the gap expected between objects; a one-cluster step ending
   * there counts only when no split is stable. An object with fewer than p times the
   * points of an object it stands next to (closer than its own gaps) is taken as a
   * piece of it: set the piece ratio to 0 where such objects are expected. */
  void
  setAutoMaxDistance (bool enabled)
  {
    auto_max_distance_ = enabled;
  }

  bool
  getAutoMaxDistance () const
  {
    return auto_max_distance_;
  }

  /** \brief Sets the ratio q (> 1, default DEFAULT_GAP_RATIO) of the rule of
   * setAutoMaxDistance(): a split into clusters is taken only when it is stable over
   * a factor q of scales, and is clear when also q times longer (in log) than any
   * other split. */
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

  /** \brief Sets the piece ratio p (in [0, 1), default DEFAULT_PIECE_RATIO) of the
   * rule of setAutoMaxDistance(): a would-be cluster that merges into one with more
   * than 1 / p times its points is a piece of it, not counted (0: none is). */
  void
  setAutoPieceRatio (double ratio)
  {
    piece_ratio_ = ratio;
  }

  double
  getAutoPieceRatio () const
  {
    return piece_ratio_;
  }

  /** \brief Sets a floor (>= 0, default 0) of the rule of setAutoMaxDistance(): the
   * chosen distance is never below it, e.g. the leaf size of a voxel grid applied
   * before. */
  void
  setAutoMinDistance (double min_distance)
  {
    auto_min_distance_ = min_distance;
  }

  double
  getAutoMinDistance () const
  {
    return auto_min_distance_;
  }

  /** \brief Bytes per edge of the radius graph at the peak of extract(): with a
   * search method, the memory limit refuses a graph whose edges would not fit; without
   * one, a scale whose edges would not fit is searched by Borůvka's rounds instead
   * (radiusGraphSpanningForest()), so no max distance is refused. */
  static constexpr std::size_t BYTES_PER_EDGE = sizeof (FilteredEdge);

  /** \brief Extracts the clusters of the input points (or of the indexed ones).
   * On failure (no input, no finite point, max distance not positive and finite,
   * min size above max size, a bad gap ratio, with a search method a graph over the
   * memory limit) prints a PCL_ERROR naming the problem and leaves \a clusters
   * empty. */
  void
  extract (std::vector<pcl::PointIndices>& clusters);

  /** \brief The H0 diagram of the last extract(): one interval per component that
   * merged before max distance (death: the merging edge's length, stepped if
   * setFiltrationSteps() is set), one essential interval per component left at max
   * distance; zero-length intervals (duplicate points) are left out. */
  const PersistenceDiagram&
  getPersistenceDiagram () const
  {
    return diagram_;
  }

  /** \brief The distance at which the last extract() cut the filtration: the max
   * distance, or the one chosen by setAutoMaxDistance(true). */
  double
  getChosenDistance () const
  {
    return chosen_distance_;
  }

  /** \brief Whether the H0 diagram of the last extract() with setAutoMaxDistance(true)
   * showed a clear gap (ClusterDistanceChoice::clear); when not, extract() printed a
   * PCL_WARN and the chosen distance is a guess. False without the automatic
   * distance. */
  bool
  getAutoDistanceIsClear () const
  {
    return auto_distance_is_clear_;
  }

  /** \brief Number of components larger than the max cluster size in the last
   * extract() (dropped or kept, see setKeepOversizedClusters()). */
  std::size_t
  getNumOversizedClusters () const
  {
    return num_oversized_clusters_;
  }

  /** \brief Number of edges the last extract() listed: with a search method, the
   * edges of the radius graph; without one, the most edges listed at one scale of
   * radiusGraphSpanningForest(), pairs of points not yet joined (far fewer than the
   * graph's edges when the max distance is large), or one per point where Borůvka's
   * rounds took over. */
  std::size_t
  getNumEdges () const
  {
    return num_edges_;
  }

protected:
  /** \brief The class name, as PCL's classes report it in their messages. */
  const std::string&
  getClassName () const
  {
    return class_name_;
  }

private:
  /** PCL's k-d tree test (see setPCLDistanceTest()) on input points \a i, \a j. */
  bool
  passesPCLDistanceTest (pcl::index_t i, pcl::index_t j) const;

  /** Builds the radius graph (or its spanning forest) of the finite indexed points;
   * false after a PCL_ERROR. */
  bool
  buildGraph (FilteredComplex& complex);

  /** Prints a PCL_ERROR for the first invalid parameter; true when all are valid. */
  bool
  checkParameters () const;

  KdTreePtr tree_;
  double max_distance_ = 0.0;
  pcl::uindex_t min_pts_per_cluster_ = 1;
  pcl::uindex_t max_pts_per_cluster_ = std::numeric_limits<pcl::uindex_t>::max();
  bool keep_oversized_clusters_ = false;
  bool pcl_distance_test_ = false;
  unsigned int filtration_steps_ = 0;
  bool auto_max_distance_ = false;
  double gap_ratio_ = DEFAULT_GAP_RATIO;
  double piece_ratio_ = DEFAULT_PIECE_RATIO;
  double auto_min_distance_ = 0.0;

  PersistenceDiagram diagram_;
  double chosen_distance_ = 0.0;
  bool auto_distance_is_clear_ = false;
  std::size_t num_oversized_clusters_ = 0;
  std::size_t num_edges_ = 0;
  std::string class_name_ = "PersistentEuclideanClusterExtraction";
};

} // namespace tda
} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl/tda/segmentation/impl/persistent_euclidean_cluster_extraction.hpp>
#endif
