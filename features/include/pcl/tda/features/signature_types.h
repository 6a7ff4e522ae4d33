#pragma once

// The point types of PCL-TDA's global descriptors, registered with PCL like
// pcl::ESFSignature640, so that they are stored in pcl::PointCloud, written to PCD
// files and fed to PCL's machine learning like PCL's own signatures.

#include <pcl/register_point_struct.h>
#include <pcl/type_traits.h>

#include <cstddef>

namespace pcl {
namespace tda {

/** \brief Levels of the STPP signature: the input cloud at its own radius, then
 * coarser copies of it (see STPPEstimation). */
constexpr std::size_t STPP_LEVELS = 4;
/** \brief Radii at which the Betti curves of one level are sampled. */
constexpr std::size_t STPP_CURVE_SAMPLES = 8;
/** \brief Values per level in the Betti-0 part: the curve and the count of
 * components. */
constexpr std::size_t STPP_BETTI0_PER_LEVEL = STPP_CURVE_SAMPLES + 1;
/** \brief Values per level in the Betti-1 part: the curve, the count of essential
 * 1-cycles and the count of long-lived 1-cycles. */
constexpr std::size_t STPP_BETTI1_PER_LEVEL = STPP_CURVE_SAMPLES + 2;
/** \brief Functions whose sublevel sets the Betti-0 part follows (shapeFunctions()):
 * the distance from the centroid and the coordinates along the three principal
 * axes. */
constexpr std::size_t STPP_SUBLEVEL_FUNCTIONS = 4;
/** \brief Values per function in the Betti-0 part (sublevelValues()): the fraction
 * of the points and the count of lasting components of the sublevel set at each
 * curve sample, and the function's range. */
constexpr std::size_t STPP_SUBLEVEL_PER_FUNCTION = 2 * STPP_CURVE_SAMPLES + 1;
/** \brief Index of the first value of the Betti-0 part of an STPP signature. */
constexpr std::size_t STPP_BETTI0_OFFSET = 0;
/** \brief Index of the first sublevel-set value, within the Betti-0 part, after the
 * levels' values. */
constexpr std::size_t STPP_SUBLEVEL_OFFSET =
    STPP_BETTI0_OFFSET + STPP_LEVELS * STPP_BETTI0_PER_LEVEL;
/** \brief Index of the first value of the Betti-1 part of an STPP signature. */
constexpr std::size_t STPP_BETTI1_OFFSET =
    STPP_SUBLEVEL_OFFSET + STPP_SUBLEVEL_FUNCTIONS * STPP_SUBLEVEL_PER_FUNCTION;
/** \brief Index of the size value of an STPP signature (its last value). */
constexpr std::size_t STPP_SIZE_OFFSET =
    STPP_BETTI1_OFFSET + STPP_LEVELS * STPP_BETTI1_PER_LEVEL;
/** \brief Number of values of an STPP signature. */
constexpr std::size_t STPP_SIGNATURE_SIZE = STPP_SIZE_OFFSET + 1;

/** \brief The STPP signature of a cloud (STPPEstimation): a fixed-length vector of
 * Betti curves and counts over several scales, made from the persistence pairs of
 * the cloud. The layout (STPPEstimation documents each value):
 * - [STPP_BETTI0_OFFSET, STPP_BETTI1_OFFSET): per level, the Betti-0 curve and
 *   the count of components; then, from STPP_SUBLEVEL_OFFSET, per function, the
 *   sublevel sets' point fraction and component curves and the function's range;
 * - [STPP_BETTI1_OFFSET, STPP_SIZE_OFFSET): per level, the Betti-1 curve, the
 *   count of essential 1-cycles and the count of long-lived 1-cycles;
 * - STPP_SIZE_OFFSET: log10 of the size of the cloud in metres (0 when the
 *   signature is scale invariant). */
struct STPPSignature {
  float histogram[STPP_SIGNATURE_SIZE] = {0.0f};
  static constexpr int
  descriptorSize ()
  {
    return static_cast<int> (STPP_SIGNATURE_SIZE);
  }
};

/** \brief Features per point of the topological covariance descriptor: position
 * (3), colour in CIELAB (3), normal (3) and the Betti-0 value at each of the three
 * steps of the filtration (3). */
constexpr std::size_t COVARIANCE_FEATURES = 12;
/** \brief Number of values of a covariance signature: the upper triangle of the
 * log of the covariance matrix. */
constexpr std::size_t COVARIANCE_SIGNATURE_SIZE =
    COVARIANCE_FEATURES * (COVARIANCE_FEATURES + 1) / 2;

/** \brief The topological covariance descriptor of a cloud
 * (TopologicalCovarianceEstimation): the matrix logarithm of the covariance of the
 * per-point features, as a vector (thesis Sec 6.5, Experiment 4). */
struct CovarianceSignature {
  float histogram[COVARIANCE_SIGNATURE_SIZE] = {0.0f};
  static constexpr int
  descriptorSize ()
  {
    return static_cast<int> (COVARIANCE_SIGNATURE_SIZE);
  }
};

} // namespace tda
} // namespace pcl

POINT_CLOUD_REGISTER_POINT_STRUCT (
    pcl::tda::STPPSignature, (float[pcl::tda::STPP_SIGNATURE_SIZE], histogram, stpp))
POINT_CLOUD_REGISTER_POINT_STRUCT (pcl::tda::CovarianceSignature,
                                   (float[pcl::tda::COVARIANCE_SIGNATURE_SIZE],
                                    histogram,
                                    covariance))
