#include <pcl/tda/features/covariance_signature.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>

namespace pcl {
namespace tda {

std::vector<double>
vertexDeathValues (const FilteredComplex& complex, const PersistenceResult& result)
{
  std::vector<double> deaths (complex.numVertices(),
                              std::numeric_limits<double>::infinity());
  for (std::size_t v = 0; v < deaths.size(); ++v)
    if (result.vertex_killer[v] != INVALID_SIMPLEX)
      deaths[v] = complex.edges()[result.vertex_killer[v]].value;
  return deaths;
}

void
logCovarianceVector (const CovarianceFeatures& features,
                     double regularization,
                     float* values)
{
  using Matrix = Eigen::Matrix<double, COVARIANCE_FEATURES, COVARIANCE_FEATURES>;
  const Eigen::RowVectorXd mean = features.colwise().mean();
  const CovarianceFeatures centred = features.rowwise() - mean;
  Matrix covariance =
      (centred.transpose() * centred) / static_cast<double> (features.rows() - 1);
  covariance += regularization * Matrix::Identity();
  const Eigen::SelfAdjointEigenSolver<Matrix> solver (covariance);
  // Its eigenvalues are at least the regularization; computed, those of constant
  // features may fall below it (even below 0) by the solver's rounding, about 1e-16
  // times the largest (positions in millimetres vary by 1e6 and more): clamped.
  const Matrix logarithm =
      solver.eigenvectors() *
      solver.eigenvalues().array().max (regularization).log().matrix().asDiagonal() *
      solver.eigenvectors().transpose();
  std::size_t k = 0;
  for (std::size_t i = 0; i < COVARIANCE_FEATURES; ++i)
    for (std::size_t j = i; j < COVARIANCE_FEATURES; ++j)
      values[k++] = static_cast<float> (
          (i == j ? 1.0 : std::sqrt (2.0)) *
          logarithm (static_cast<Eigen::Index> (i), static_cast<Eigen::Index> (j)));
}

} // namespace tda
} // namespace pcl
