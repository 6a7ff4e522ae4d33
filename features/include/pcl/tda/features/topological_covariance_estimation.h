#pragma once

#include <pcl/features/feature.h>
#include <pcl/tda/common/resource_settings.h>
#include <pcl/tda/features/signature_types.h>

#include <array>
#include <cstddef>

namespace pcl {
namespace tda {

/** \brief The topological covariance descriptor of a cloud (thesis Sec 6.5,
 * Experiment 4): the covariance of per-point features, mapped to a vector by the
 * matrix logarithm (log-Euclidean metric), as one CovarianceSignature, beside
 * pcl::VFHEstimation (it needs normals like VFH).
 *
 * The features of a point (COVARIANCE_FEATURES of them):
 * - its position x, y, z;
 * - its colour in CIELAB (rgbToLab()) when the point type has one, else 0;
 * - its normal (from setInputNormals());
 * - its Betti-0 value at each of the three steps of the filtration, radii
 *   STEP_FRACTIONS times r (the thesis' 3, 4 and 5 mm): min(d, r_s) / r_s, d the
 *   radius at which the point's component merges into an older one (the elder
 *   rule; vertexDeathValues()), so 1 for a point whose component lives through
 *   the step.
 * The covariance is taken over the points with a finite position and normal (at
 * most setMaxPoints() of them, a uniform sample: a covariance needs no more), and
 * logCovarianceVector() turns it into the signature. The result depends neither on
 * the input order nor on the number of threads.
 *
 * \code
 * pcl::tda::TopologicalCovarianceEstimation<pcl::PointXYZRGB, pcl::Normal,
 *                                           pcl::tda::CovarianceSignature> tc;
 * tc.setInputCloud (cloud);
 * tc.setInputNormals (normals);
 * pcl::PointCloud<pcl::tda::CovarianceSignature> signature;
 * tc.compute (signature);                 // one point
 * \endcode */
template <typename PointInT, typename PointNT, typename PointOutT = CovarianceSignature>
class TopologicalCovarianceEstimation
: public pcl::FeatureFromNormals<PointInT, PointNT, PointOutT>,
  public ResourceSettings {
public:
  using Ptr = shared_ptr<TopologicalCovarianceEstimation<PointInT, PointNT, PointOutT>>;
  using ConstPtr =
      shared_ptr<const TopologicalCovarianceEstimation<PointInT, PointNT, PointOutT>>;
  using PointCloudOut = typename pcl::Feature<PointInT, PointOutT>::PointCloudOut;

  /** \brief The radii of the three steps as fractions of the largest, r. */
  static constexpr std::array<double, 3> STEP_FRACTIONS{0.6, 0.8, 1.0};
  /** \brief The automatic r in units of the surface spacing of the points used:
   * the thesis' 5 mm on Kinect views at about 1 m is 2.5 to 3 spacings. */
  static constexpr double AUTO_RADIUS_PER_SPACING = 3.0;
  /** \brief The default most points the covariance is taken over. */
  static constexpr std::size_t DEFAULT_MAX_POINTS = 2000;
  /** \brief Added to the covariance's diagonal: below any real variance of the
   * features (positions in metres vary by 1e-6 m^2 on a 2 mm object), it keeps
   * the logarithm finite when a feature is constant (no colour). */
  static constexpr double REGULARIZATION = 1e-9;

  TopologicalCovarianceEstimation()
  {
    this->feature_name_ = "TopologicalCovarianceEstimation";
  }

  /** \brief Sets r, the radius of the last step of the filtration; 0 (the
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

  /** \brief Sets the most points the covariance is taken over (0: all). */
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

  /** \brief The radius r used by the last compute(). */
  double
  getUsedRadius () const
  {
    return used_radius_;
  }

protected:
  using pcl::Feature<PointInT, PointOutT>::getClassName;
  using pcl::Feature<PointInT, PointOutT>::indices_;
  using pcl::Feature<PointInT, PointOutT>::input_;
  using pcl::FeatureFromNormals<PointInT, PointNT, PointOutT>::normals_;

  /** \brief Clears the radius of the last compute(), then checks the input, the
   * normals and the parameters; no search radius or k is needed and no search tree is
   * built. */
  bool
  initCompute () override;

  /** \brief One signature for the whole cloud (the indexed points): \a output
   * becomes one point (pcl::Feature::compute() sized it for every indexed point);
   * empty, with a PCL_ERROR, on failure. */
  void
  computeFeature (PointCloudOut& output) override;

private:
  /** \brief Computes the signature into \a values; false, with a PCL_ERROR, on
   * failure. */
  bool
  computeSignature (float* values);

  double radius_ = 0.0;
  std::size_t max_points_ = DEFAULT_MAX_POINTS;
  double used_radius_ = 0.0;
};

} // namespace tda
} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl/tda/features/impl/topological_covariance_estimation.hpp>
#endif
