#pragma once

#include <pcl/features/feature.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_diagram.h>
#include <pcl/tda/common/progress.h>
#include <pcl/tda/common/resource_settings.h>
#include <pcl/tda/features/hole_rims.h>
#include <pcl/tda/search/point_spacing.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The holes of a scanned surface from its minimal 1-cycles (thesis Ch. 5,
 * Alg 5.15), with per-point boundary flags that take the place of
 * pcl::BoundaryEstimation in a pipeline.
 *
 * The finite points (among the indices) are the vertices of the Vietoris-Rips
 * complex VR_r at the radius r. Its 1-classes still open at the persistence radius
 * (PERSISTENCE_RADIUS_PER_MIN_HOLE_RADIUS times the smallest hole radius, or r when
 * smaller) are the
 * holes, handles and loops around tubes; the gaps of the sampling, most of the
 * classes open at r, fill in before. Each class searched gives minimal 1-cycles
 * (minimalCycles()), and so does a polygon around each border of the surface
 * (borderPolygons()), for the holes that homology cannot tell apart; a cycle that
 * the surface around it spans is a hole (holeRims(): the test that keeps loops
 * around handles and tubes out).
 *
 * compute() gives one pcl::Boundary per index: boundary_point is 1 for the points of
 * the rim band: the points within the band width of the hole's edge, on the
 * surface's side (measured from the hole's empty region, see rimBand()), the band
 * pcl::BoundaryEstimation flags along a border. getHoles() gives every hole's rim
 * in cycle order as input indices, with its perimeter, area, plane and birth. A rim
 * is a shortest cycle around the hole: it cuts corners, and on a scan with uneven
 * sampling some of its points lie further from the edge than the band reaches (16
 * of the 31 of the hole of milk.pcd), so take a hole's points from its rim, its
 * band from the flags (getRimBandLabels()).
 *
 * On a closed surface (a sphere, a torus) with k holes there are only k - 1
 * independent hole classes besides the handles; the border polygons find the
 * others where the border test sees their rim whole.
 *
 * The results depend neither on the input order nor on the number of threads.
 *
 * \code
 * pcl::tda::HoleBoundaryEstimation<pcl::PointXYZ, pcl::Boundary> hb;
 * hb.setInputCloud (cloud);
 * hb.setRadius (0.003);          // or automatic
 * pcl::PointCloud<pcl::Boundary> flags;
 * hb.compute (flags);
 * for (const auto& hole : hb.getHoles ()) ...
 * \endcode */
template <typename PointInT, typename PointOutT>
class HoleBoundaryEstimation : public pcl::Feature<PointInT, PointOutT>,
                               public ResourceSettings {
public:
  using Ptr = shared_ptr<HoleBoundaryEstimation<PointInT, PointOutT>>;
  using ConstPtr = shared_ptr<const HoleBoundaryEstimation<PointInT, PointOutT>>;
  using PointCloudOut = typename pcl::Feature<PointInT, PointOutT>::PointCloudOut;

  /** \brief The automatic radius in units of the surface spacing (see setRadius()):
   * a little above the radius at which the neighbours of 90 % of the points of a
   * near-uniform sampling surround them (no angular gap over 90 degrees: 1.9-2.0
   * spacings on the generated surfaces), so that real scans, sampled denser along
   * their scan lines than across them, are a surface at it too. */
  static constexpr double AUTO_RADIUS_PER_SPACING = 2.2;
  /** \brief The largest radius compute() accepts, in units of the surface spacing.
   * At r the complex fills every hole narrower than about r / sqrt(3), and the
   * triangles H1 goes through grow as (r / spacing)^4 per point: at 10 spacings, a
   * point has some 300 neighbours on a surface and its H1 takes seconds for 20,000
   * points; on the whole unit square of 20,000 points (r = 5 m, 700 spacings) it ran
   * for minutes at 7 GB before this bound. */
  static constexpr double MAX_RADIUS_PER_SPACING = 10.0;
  /** \brief The default smallest hole radius, in units of the spacing (see
   * setMinHoleRadius()): below the 3 spacings of the smallest generated holes, and
   * measured in the local spacing around each rim (localSurfaceSpacings()), where
   * a real scan is sampled more sparsely than on average, so that the gaps of its
   * sparse parts are not holes. */
  static constexpr double DEFAULT_MIN_HOLE_RADIUS_PER_SPACING = 2.0;
  /** \brief The persistence radius in units of the smallest hole radius, counted
   * up to the radius r: the classes of VR_r searched for holes are those still
   * alive at this many times the smaller of the two (or at r, when larger). A round
   * hole of empty radius rho lives until about sqrt(3) rho, less on a noisy rim, so
   * one at least the smallest hole radius wide is still open at 1.3 times it; most
   * gaps of the sampling die before. */
  static constexpr double PERSISTENCE_RADIUS_PER_MIN_HOLE_RADIUS = 1.3;
  /** \brief The automatic rim band width in units of the surface spacing. */
  static constexpr double AUTO_BAND_PER_SPACING = 1.5;
  /** \brief The default largest tilt of a hole's rim against its surface. */
  static constexpr double DEFAULT_MAX_TILT_DEGREES = 45.0;

  HoleBoundaryEstimation() { this->feature_name_ = "HoleBoundaryEstimation"; }

  /** \brief Sets the radius r of the complex; 0 (the default) chooses it:
   * AUTO_RADIUS_PER_SPACING times the surface spacing (surfaceSpacing()). compute()
   * refuses a radius over MAX_RADIUS_PER_SPACING times the spacing. */
  void
  setRadius (double radius)
  {
    radius_ = radius;
  }

  double
  getRadius () const
  {
    return radius_;
  }

  /** \brief Sets the largest number of points of a rim; a longer minimal cycle is
   * not reported (the thesis caps rims at 8, 16 or 32 points). 0 (default): no
   * limit. */
  void
  setMaxCycleLength (std::size_t points)
  {
    max_cycle_length_ = points;
  }

  std::size_t
  getMaxCycleLength () const
  {
    return max_cycle_length_;
  }

  /** \brief Sets the largest median angle, in degrees (in [0, 90]), between a rim's
   * plane and the surface at its points for the rim to be a hole; loops around
   * handles and tubes stand at about 90 degrees. */
  void
  setMaxTiltAngle (double degrees)
  {
    max_tilt_degrees_ = degrees;
  }

  double
  getMaxTiltAngle () const
  {
    return max_tilt_degrees_;
  }

  /** \brief Sets the smallest radius of a hole: the radius of the largest empty
   * disk inside its rim must be at least this. 0 (the default):
   * DEFAULT_MIN_HOLE_RADIUS_PER_SPACING times the surface spacing, and as many times
   * the local spacing around the rim (the median over its points of
   * localSurfaceSpacings()) where that is larger. The gaps of the sampling that the
   * complex's triangles leave open are narrower (measured on generated surfaces at
   * every noise level, and on real scans relative to their local spacing). The
   * filtration is built up to PERSISTENCE_RADIUS_PER_MIN_HOLE_RADIUS times the
   * smaller of it and the radius (at least to the radius). */
  void
  setMinHoleRadius (double radius)
  {
    min_hole_radius_ = radius;
  }

  double
  getMinHoleRadius () const
  {
    return min_hole_radius_;
  }

  /** \brief Sets the surface spacing h that the automatic radius, band width and
   * smallest hole radius are measured in, e.g. one a caller measured already to
   * choose or check a radius; 0 (the default): surfaceSpacing() of the indexed
   * points, measured by compute() (the same value). */
  void
  setSpacing (double spacing)
  {
    spacing_ = spacing;
  }

  double
  getSpacing () const
  {
    return spacing_;
  }

  /** \brief Sets the width of the flagged rim band (see rimBand()), at most the
   * radius; 0 (the default): AUTO_BAND_PER_SPACING times the surface spacing, capped
   * at the radius. */
  void
  setRimBandWidth (double width)
  {
    band_width_ = width;
  }

  double
  getRimBandWidth () const
  {
    return band_width_;
  }

  /** \brief Sets a callback told the progress of compute(), as (done, 2000): the
   * complex's construction (0 to 500), its H1 (500 to 1000), then the search of the
   * initial cycles (1000 to 2000). Called from the calling thread; it may throw to
   * cancel the computation, and the exception reaches the caller of compute(). */
  void
  setProgressCallback (const ProgressCallback& progress)
  {
    progress_ = progress;
  }

  /** \brief The holes found by the last compute(), longest rim first; the rims'
   * points are input indices. */
  const std::vector<HoleRim>&
  getHoles () const
  {
    return holes_;
  }

  /** \brief Per input point (all of them, indexed or not), the number of the hole
   * (1, 2, ... in the order of getHoles()) whose rim band it is in, or 0: the
   * boundary flags of compute(), hole by hole. */
  const std::vector<std::uint32_t>&
  getRimBandLabels () const
  {
    return rim_band_labels_;
  }

  /** \brief The persistence diagram (dimensions 0 and 1) of the Vietoris-Rips
   * filtration of the last compute() up to the persistence radius: the classes
   * born by the radius and alive at the end are the ones searched for holes. */
  const PersistenceDiagram&
  getPersistenceDiagram () const
  {
    return diagram_;
  }

  /** \brief The radius used by the last compute() (the chosen one when automatic). */
  double
  getUsedRadius () const
  {
    return used_radius_;
  }

  /** \brief The persistence radius used by the last compute(): the classes searched
   * for holes are those of VR_r still alive there (see
   * PERSISTENCE_RADIUS_PER_MIN_HOLE_RADIUS). */
  double
  getUsedPersistenceRadius () const
  {
    return used_persistence_radius_;
  }

  /** \brief The rim band width used by the last compute(). */
  double
  getUsedRimBandWidth () const
  {
    return used_band_width_;
  }

  /** \brief The 1-skeleton of the Vietoris-Rips complex of the last compute(), up to
   * the persistence radius; the rims are searched in its edges up to the radius. */
  const FilteredComplex&
  getComplex () const
  {
    return complex_;
  }

  /** \brief What the last compute() searched, for reports. */
  struct SearchCounts {
    /** \brief The edges of VR_r. */
    std::size_t edges = 0;
    /** \brief The triangles of the complex up to the persistence radius (counted by
     * its H1, not listed; getComplex() holds its edges). */
    std::uint64_t triangles = 0;
    /** \brief The 1-classes of VR_r: born by r, alive at r. */
    std::size_t open_classes = 0;
    /** \brief Those still alive at the persistence radius, whose initial cycles
     * were searched. */
    std::size_t persistent_classes = 0;
    /** \brief The polygons around borders that were searched (borderPolygons()). */
    std::size_t border_polygons = 0;
  };

  /** \brief What the last compute() searched. */
  const SearchCounts&
  getSearchCounts () const
  {
    return search_counts_;
  }

protected:
  using pcl::Feature<PointInT, PointOutT>::getClassName;
  using pcl::Feature<PointInT, PointOutT>::indices_;
  using pcl::Feature<PointInT, PointOutT>::input_;

  /** \brief Clears the results of the last run (a refused run leaves none), then
   * checks the input and the parameters; unlike pcl::Feature, no search radius or k
   * is needed and no search tree is built. */
  bool
  initCompute () override;

  void
  computeFeature (PointCloudOut& output) override;

private:
  /** \brief Finds the holes of the input; false, with a PCL_ERROR, on failure. */
  bool
  findHoles ();

  /** \brief Forgets the results of the last run (before a run, and after a refused
   * one: a refused run leaves none). */
  void
  clearResults ();

  double radius_ = 0.0;
  double spacing_ = 0.0;
  std::size_t max_cycle_length_ = 0;
  double max_tilt_degrees_ = DEFAULT_MAX_TILT_DEGREES;
  double band_width_ = 0.0;
  double min_hole_radius_ = 0.0;
  ProgressCallback progress_;
  /** The units of each half of the progress (the builder reports thousandths). */
  static constexpr std::size_t PROGRESS_UNITS = 1000;

  FilteredComplex complex_;
  std::vector<HoleRim> holes_;
  std::vector<std::uint32_t> rim_band_labels_;
  PersistenceDiagram diagram_;
  double used_radius_ = 0.0;
  double used_persistence_radius_ = 0.0;
  SearchCounts search_counts_;
  double used_band_width_ = 0.0;
};

} // namespace tda
} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl/tda/features/impl/hole_boundary_estimation.hpp>
#endif
