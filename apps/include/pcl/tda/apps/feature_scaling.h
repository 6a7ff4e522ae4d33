#pragma once

#include <cstddef>
#include <vector>

namespace pcl {
namespace tda {

/** \brief How descriptor values are scaled before an SVM sees them. */
enum class FeatureScalingMode {
  /** Each value minus its training mean, over its training standard deviation. */
  Z_SCORE,
  /** Each value mapped to [0, 1] over its training range (docs/EVALUATION.md). */
  MIN_MAX
};

/** \brief The per-value affine map x -> (x - offset) * factor that scales the
 * descriptor vectors of a classifier's views, fitted on its training views only
 * (fitFeatureScaling()), so that nothing of the test views leaks into training. */
struct FeatureScaling {
  std::vector<double> offset;
  std::vector<double> factor;

  /** \brief \a row scaled.
   * \throws pcl::BadArgumentException when \a row has another size */
  std::vector<float>
  apply (const std::vector<float>& row) const;
};

/** \brief Fits the scaling of \a mode on the rows \a training of \a rows (vectors of
 * one size). A value that is constant over the training rows gets factor 0: it
 * tells the training views nothing apart, and any other value in a test view
 * must not outweigh the rest.
 *
 * \a parts gives the sizes of the descriptors that were concatenated into each row
 * (e.g. {60, 640} for stpp+esf; empty or one size for a single descriptor). Each
 * part's factors are multiplied by sqrt(D / (K d_k)), D the row size, K the number
 * of parts and d_k the part's size, so that every part weighs the same in the
 * squared distance of an RBF kernel (a 640-value ESF would otherwise drown a
 * 60-value STPP) while the expected squared norm of a row stays D.
 * \throws pcl::BadArgumentException when \a training is empty, the rows differ in
 * size, or \a parts does not add up to their size */
FeatureScaling
fitFeatureScaling (const std::vector<std::vector<float>>& rows,
                   const std::vector<std::size_t>& training,
                   const std::vector<std::size_t>& parts,
                   FeatureScalingMode mode);

} // namespace tda
} // namespace pcl
