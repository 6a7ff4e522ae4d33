#pragma once

#include <pcl/features/feature.h>
#include <pcl/tda/common/persistence_diagram.h>
#include <pcl/tda/common/resource_settings.h>
#include <pcl/tda/features/signature_types.h>
#include <pcl/tda/features/stpp_levels.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief STPP, the Signature of Topologically Persistent Points (thesis Ch. 6): a
 * global descriptor of a cloud (one object, segmented) made of the persistence of
 * its components and 1-cycles, beside pcl::VFHEstimation and pcl::ESFEstimation.
 * It needs no normals and no preprocessing.
 *
 * The thesis' STPP is the raw pairing of the Vietoris-Rips complex VR_r of the
 * cloud (getPairingVector()): one entry per vertex and edge, so its length differs
 * from cloud to cloud and a classifier cannot take it as it is. compute() gives a
 * fixed-length signature (STPPSignature) made from the same pairs, at STPP_LEVELS
 * scales:
 * - level 0: the cloud itself (or a uniform sample of setMaxPoints() points of
 *   it, hashedSample()) at the
 *   radius r_0 (setRadius(), or AUTO_RADIUS_PER_SPACING times its surface
 *   spacing: the scale of its sampling);
 * - levels 1 to STPP_LEVELS - 1: coarse copies of the cloud
 *   (coarseCopy(), spacing r_k / COARSE_RADIUS_PER_SPACING, each from the one
 *   before, the first from all points) at the radii r_k = S / 8,
 *   S / 4, S / 2, S the size of the cloud (cloudSize()): the scales of the
 *   object's own parts, handles and holes.
 *
 * Each level gives the Betti curves of its complex, sampled at STPP_CURVE_SAMPLES
 * radii up to r_k (from twice the coarse copy's spacing on the coarse levels, where
 * its own sampling cycles are gone) and divided by its number of points, and counts of
 * components, essential and long-lived 1-cycles (betti0LevelValues(),
 * betti1LevelValues()). The Betti-0 part also follows the components of the
 * sublevel sets of four functions on the coarse copy of level SUBLEVEL_LEVEL (the
 * distance from the centroid and the coordinates along the principal axes,
 * shapeFunctions()): how much of the object, and in how many pieces, lies below each
 * of STPP_CURVE_SAMPLES values, and the function's range (sublevelValues()), its
 * outline and profile. The last value is log10 of S in metres. Every value but the
 * last is invariant to scale (radii are relative to the spacing or to S), and, as the
 * curves are per point and the coarse copies have a set spacing, about invariant to the
 * number of points; setScaleInvariant() zeroes the last. The signature depends neither
 * on the input order nor on the number of threads (the points are taken in a canonical
 * order).
 *
 * \code
 * pcl::tda::STPPEstimation<pcl::PointXYZ, pcl::tda::STPPSignature> stpp;
 * stpp.setInputCloud (cloud);
 * pcl::PointCloud<pcl::tda::STPPSignature> signature;
 * stpp.compute (signature);               // one point, like VFH
 * stpp.getPairingVector ();               // the thesis' raw vector (Fig 6.2)
 * \endcode */
template <typename PointInT, typename PointOutT = STPPSignature>
class STPPEstimation : public pcl::Feature<PointInT, PointOutT>,
                       public ResourceSettings {
public:
  using Ptr = shared_ptr<STPPEstimation<PointInT, PointOutT>>;
  using ConstPtr = shared_ptr<const STPPEstimation<PointInT, PointOutT>>;
  using PointCloudOut = typename pcl::Feature<PointInT, PointOutT>::PointCloudOut;

  /** \brief The automatic radius of level 0 in units of the surface spacing
   * (surfaceSpacing()): the sampling's own triangles are in the complex, so its
   * 1-cycles are the gaps and holes of the surface. The thesis' 3.5 mm on Kinect
   * views at about 1 m is 2 to 2.5 spacings. */
  static constexpr double AUTO_RADIUS_PER_SPACING = 2.0;
  /** \brief The radii of the coarse levels as fractions of the cloud's size. */
  static constexpr std::array<double, STPP_LEVELS - 1> COARSE_RADII_PER_SIZE{
      1.0 / 8.0, 1.0 / 4.0, 1.0 / 2.0};
  /** \brief The radius of a coarse level in units of the spacing of its coarse
   * copy: its surface is filled with triangles early, and a hole lives for most of
   * [0, r]. */
  static constexpr double COARSE_RADIUS_PER_SPACING = 3.0;

  /** \brief The level whose coarse copy and complex the sublevel-set values are
   * taken on (sublevelValues()): its points are evenly spread over the surface, so
   * that a fraction of them is a fraction of the object's area, and its edges join
   * the object's parts but not parts apart by more than S / 8. */
  static constexpr std::size_t SUBLEVEL_LEVEL = 1;

  /** \brief The default most points of level 0 (setMaxPoints()). */
  static constexpr std::size_t DEFAULT_MAX_POINTS = 1000;
  /** \brief Points whose neighbours measure the spacing of level 0: its median is
   * within a few percent with this many. */
  static constexpr std::size_t SPACING_SAMPLES = 250;

  STPPEstimation() { this->feature_name_ = "STPPEstimation"; }

  /** \brief Sets the radius r_0 of level 0, the thesis' single radius; 0 (the
   * default) chooses it (AUTO_RADIUS_PER_SPACING). */
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

  /** \brief Sets the most points level 0 is built on: a larger cloud is replaced
   * by a uniform sample of this many (hashedSample()). 0: all points, the thesis'
   * STPP (slower on large clouds: the complex grows with the points). Default
   * DEFAULT_MAX_POINTS. */
  void
  setMaxPoints (std::size_t points)
  {
    max_points_ = points;
  }

  std::size_t
  getMaxPoints () const
  {
    return max_points_;
  }

  /** \brief Sets the homology the descriptor is made of (thesis Experiment 2). With
   * BETTI_0 no triangles are built and the Betti-1 part is 0; with BETTI_1 the
   * Betti-0 part is 0. stppSignatureValues() picks the part that was computed. */
  void
  setHomology (STPPHomology homology)
  {
    homology_ = homology;
  }

  STPPHomology
  getHomology () const
  {
    return homology_;
  }

  /** \brief When true, the size value of the signature is 0, so that the signature
   * is the same for a cloud and a scaled copy of it. Default false: the size tells
   * a ball from a marble. */
  void
  setScaleInvariant (bool invariant)
  {
    scale_invariant_ = invariant;
  }

  bool
  getScaleInvariant () const
  {
    return scale_invariant_;
  }

  /** \brief The thesis' raw STPP vector of level 0 (pairingVector()) for the
   * homology set, from the last compute(): of the whole cloud when it has at most
   * setMaxPoints() points (or with setMaxPoints (0)), else of its sample. */
  const std::vector<std::int64_t>&
  getPairingVector () const
  {
    return pairing_vector_;
  }

  /** \brief The radius of each level used by the last compute(). */
  const std::vector<double>&
  getLevelRadii () const
  {
    return level_radii_;
  }

  /** \brief The persistence diagram (dimensions 0 and, unless BETTI_0, 1) of each
   * level of the last compute(). */
  const std::vector<PersistenceDiagram>&
  getLevelDiagrams () const
  {
    return level_diagrams_;
  }

  /** \brief The size S of the cloud measured by the last compute() (cloudSize()). */
  double
  getCloudSize () const
  {
    return cloud_size_;
  }

protected:
  using pcl::Feature<PointInT, PointOutT>::getClassName;
  using pcl::Feature<PointInT, PointOutT>::indices_;
  using pcl::Feature<PointInT, PointOutT>::input_;

  /** \brief Clears the results of the last compute(), then checks the input and the
   * parameters; unlike pcl::Feature, no search radius or k is needed and no search
   * tree is built. */
  bool
  initCompute () override;

  /** \brief One signature for the whole cloud (the indexed points), as
   * pcl::VFHEstimation gives: \a output becomes one point (pcl::Feature::compute()
   * sized it for every indexed point); empty, with a PCL_ERROR, on failure. */
  void
  computeFeature (PointCloudOut& output) override;

private:
  /** \brief Computes the signature into \a histogram; false, with a PCL_ERROR, on
   * failure. */
  bool
  computeSignature (float* histogram);

  /** \brief Forgets the results of the last run (before a run, and after a refused
   * one: a refused run leaves none). */
  void
  clearResults ();

  double radius_ = 0.0;
  std::size_t max_points_ = DEFAULT_MAX_POINTS;
  STPPHomology homology_ = STPPHomology::BETTI_0_1;
  bool scale_invariant_ = false;

  std::vector<std::int64_t> pairing_vector_;
  std::vector<double> level_radii_;
  std::vector<PersistenceDiagram> level_diagrams_;
  double cloud_size_ = 0.0;
};

} // namespace tda
} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl/tda/features/impl/stpp_estimation.hpp>
#endif
