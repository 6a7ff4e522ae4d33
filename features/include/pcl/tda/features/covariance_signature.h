#pragma once

// The parts of the topological covariance descriptor (thesis Sec 6.5, Experiment
// 4) that do not depend on the point type: the per-point Betti-0 values and the
// log-Euclidean vector of a covariance matrix.

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/features/signature_types.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The per-point features of the covariance descriptor, one row per point. */
using CovarianceFeatures = Eigen::Matrix<double, Eigen::Dynamic, COVARIANCE_FEATURES>;

/** \brief Per vertex of \a complex (in its order), the value of the edge that kills
 * the vertex's 0-class by the elder rule (the thesis' STPP Betti-0 entry as a
 * radius), or infinity when it lives through the complex. \a result must hold H0. */
std::vector<double>
vertexDeathValues (const FilteredComplex& complex, const PersistenceResult& result);

/** \brief Writes the log-Euclidean vector of the covariance of \a features (rows:
 * points, at least 2) into \a values[0, COVARIANCE_SIGNATURE_SIZE): C = the sample
 * covariance (divided by n - 1) plus \a regularization times the identity, so that it
 * is positive definite when a feature is constant; L = log(C) by its eigen
 * decomposition; the values are L's upper triangle row by row, the off-diagonal
 * entries times sqrt(2), so that the Euclidean distance of two vectors is the
 * log-Euclidean (Frobenius) distance of the matrices. */
void
logCovarianceVector (const CovarianceFeatures& features,
                     double regularization,
                     float* values);

} // namespace tda
} // namespace pcl
