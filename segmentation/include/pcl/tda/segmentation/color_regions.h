#pragma once

#include <pcl/tda/common/cielab.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_diagram.h>
#include <pcl/tda/common/point3d.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Marks a vertex that belongs to no region. */
constexpr std::uint32_t NO_REGION = std::numeric_limits<std::uint32_t>::max();

/** \brief How long a region lives in the homogeneity filtration (the colour
 * threshold growing from 0): its bar in the H0 barcode of the regions of at least
 * the minimum size. */
struct RegionLifetime {
  /** \brief The colour threshold (Delta E) at which its component first has the
   * minimum size. */
  double birth = 0.0;
  /** \brief The threshold at which it joins an older region of at least the minimum
   * size (the elder rule: older by birth, then by smallest vertex), infinity if it
   * never does within the graph. */
  double death = std::numeric_limits<double>::infinity();
};

/** \brief The regions of one colour threshold, per vertex. */
struct ColorRegions {
  /** \brief Region of vertex v: 0 .. lifetimes.size() - 1, or NO_REGION. */
  std::vector<std::uint32_t> region_of;
  /** \brief Lifetime of each region. */
  std::vector<RegionLifetime> lifetimes;
  /** \brief The region barcode: the lifetime of every component that reaches the
   * minimum size anywhere in the filtration (not only of the regions of this
   * threshold), as H0 intervals. The number of bars alive at a threshold is the
   * number of its regions. */
  PersistenceDiagram bars;
};

/** \brief The minimum spanning forest of the edges of finite value of a homogeneity
 * graph (valueByHomogeneity()), in filtration order: all that the components of
 * every threshold need (thesis Sec 4.1.4). */
std::vector<FilteredEdge>
homogeneityForest (std::size_t num_vertices, const std::vector<FilteredEdge>& edges);

/** \brief The regions at colour threshold \a threshold (thesis Alg 4.7, Sec 4.2.6):
 * the components of the \a forest edges of value <= threshold. Components of at least
 * \a min_size points are the regions, with their lifetimes over the whole forest;
 * the vertices of smaller ones get NO_REGION; the bars of all the components that
 * reach the minimum size are in ColorRegions::bars. Regions are numbered by decreasing
 * size, equal sizes by smallest vertex, so that with vertices in a canonical order
 * the result does not depend on the input order.
 * \param[in] num_vertices number of vertices
 * \param[in] forest homogeneityForest() of the graph
 * \param[in] threshold the colour threshold (Delta E)
 * \param[in] min_size fewest points of a region (0 is taken as 1) */
ColorRegions
regionsAtThreshold (std::size_t num_vertices,
                    const std::vector<FilteredEdge>& forest,
                    double threshold,
                    std::size_t min_size);

/** \brief Post-processing of region growing (thesis Sec 4.2.5), so that the regions
 * cover the cloud (Eq 4.1): every component of the \a forest edges of value <=
 * \a threshold that is smaller than \a min_size joins the adjacent region (a
 * neighbour by any edge of the \a graph) of the most similar mean colour, by Delta E
 * of the mean CIELAB colours, if that difference is at most \a max_difference.
 * Small components are taken smallest first (equal sizes by smallest vertex) and
 * join a region, or another small component, which then grows; a component with no
 * neighbour, or farther than \a max_difference from all of them (a speck of
 * another colour, too small to be a region), stays out (NO_REGION), unless smaller
 * ones join it up to the minimum size. Unlike pcl::RegionGrowingRGB, which merges a
 * small region into the nearest one by distance alone, whatever its colour, the
 * choice is made by colour.
 * \param[in] graph the homogeneity graph (all its edges, also those of infinite
 * value: neighbours that are not similar are still neighbours)
 * \param[in] forest homogeneityForest() of the graph
 * \param[in] colors CIELAB colour of every vertex
 * \param[in] threshold the colour threshold of the regions
 * \param[in] min_size fewest points of a region
 * \param[in] max_difference the largest Delta E76 between the mean colours of a
 * small component and the region it joins (infinity: always the most similar)
 * \param[in,out] regions the regions of regionsAtThreshold() with the same threshold
 * and \a min_size; on return every vertex with a neighbour within
 * \a max_difference has a region, and the regions are numbered again by decreasing
 * size
 * \return the vertices of the small components with no neighbour (isolated points
 * and islands), in increasing order, for attachIsolatedPoints() */
std::vector<std::uint32_t>
mergeSmallRegions (const std::vector<FilteredEdge>& graph,
                   const std::vector<FilteredEdge>& forest,
                   const std::vector<LabColor>& colors,
                   double threshold,
                   std::size_t min_size,
                   double max_difference,
                   ColorRegions& regions);

/** \brief Post-processing for the points that no edge joins to a region (isolated
 * points and small islands, farther than the radius from every region, as
 * mergeSmallRegions() returns them): each joins the region of the most similar in
 * colour (Delta E76) of its \a k nearest points that have a region, found by a k-d
 * tree (thesis Sec 4.2.5: a nearest neighbours query from the small region). The
 * regions keep their numbers and lifetimes.
 * \param[in] points position of every vertex
 * \param[in] colors CIELAB colour of every vertex
 * \param[in] isolated the vertices to attach (without a region)
 * \param[in] k the nearest points considered (>= 1)
 * \param[in] threads OpenMP threads of the search (0: OpenMP's default); the result
 * does not depend on them
 * \param[in,out] regions the regions; on return every \a isolated vertex has one,
 * unless no vertex has any */
void
attachIsolatedPoints (const std::vector<Point3d>& points,
                      const std::vector<LabColor>& colors,
                      const std::vector<std::uint32_t>& isolated,
                      std::size_t k,
                      unsigned int threads,
                      ColorRegions& regions);

/** \brief The region adjacency graph of a segmentation, valued by colour: an edge
 * between two regions that some edge of finite value of the homogeneity \a graph
 * joins (neighbours whose normals agree), valued by the Delta E76 of the regions'
 * mean CIELAB colours. Returns its minimum spanning forest in filtration order (all
 * that the components of every threshold need); vertices are the region ids.
 * \param[in] graph the homogeneity graph
 * \param[in] colors CIELAB colour of every vertex (the means are taken over them)
 * \param[in] regions the regions (NO_REGION vertices are left out) */
std::vector<FilteredEdge>
regionColorForest (const std::vector<FilteredEdge>& graph,
                   const std::vector<LabColor>& colors,
                   const ColorRegions& regions);

/** \brief The regions of the second filtration: the components of the regions of
 * \a patches joined by the \a forest edges (regionColorForest()) of value <=
 * \a threshold, per vertex, numbered by decreasing number of vertices (equal sizes
 * by smallest vertex). The lifetime of each is the range of thresholds over which
 * it is exactly that union of patches: birth, the largest forest edge inside it (0
 * for a single patch); death, the value at which it joins a region of more patches
 * (the elder rule on the patches, the larger patch older), or infinity.
 * \param[in] patches the regions of the first filtration, the vertices of
 * \a forest
 * \param[in] forest regionColorForest() of the patches
 * \param[in] threshold the threshold of the mean colours (Delta E) */
ColorRegions
mergeSimilarRegions (const ColorRegions& patches,
                     const std::vector<FilteredEdge>& forest,
                     double threshold);

/** \brief The automatic colour threshold of chooseColorThreshold() and how it was
 * found. */
struct ColorThresholdChoice {
  /** \brief The chosen threshold (Delta E). */
  double threshold = 0.0;
  /** \brief The step [low, high) of the region count taken (the threshold is its
   * middle when it spans the gap ratio); both 0 when there is none. */
  double low = 0.0;
  double high = 0.0;
  /** \brief The number of regions in that step. */
  std::size_t num_regions = 0;
  /** \brief Whether the step is clear: it spans a factor of at least the gap ratio
   * q and is at least q times as long (in log) as every other step of two regions
   * or more. */
  bool clear = false;
};

/** \brief Chooses a colour threshold from the region barcode (ColorRegions::bars):
 * the number of bars alive, i.e. of regions, is a step function of the threshold;
 * the step of chooseStableStep() over [\a floor, \a max_threshold] (the longest
 * split when it is clear, otherwise the finest stable split) is taken when it spans
 * a factor of at least \a gap_ratio, and the threshold is its geometric middle
 * sqrt(low high). When no step does (the number of regions falls gradually, as on
 * scans with many shades), the threshold is \a fallback (or max_threshold when
 * lower), and the choice is not clear.
 * \param[in] bars the region barcode
 * \param[in] floor the smallest threshold considered (> 0)
 * \param[in] max_threshold the largest threshold considered
 * \param[in] gap_ratio the ratio q (> 1)
 * \param[in] fallback the threshold when no step spans the gap ratio */
ColorThresholdChoice
chooseColorThreshold (const PersistenceDiagram& bars,
                      double floor,
                      double max_threshold,
                      double gap_ratio,
                      double fallback);

} // namespace tda
} // namespace pcl
