#pragma once

#include <pcl/tda/apps/category_protocol.h>
#include <pcl/tda/apps/feature_scaling.h>
#include <pcl/tda/apps/svm_classifier.h>
#include <pcl/tda/apps/view_manifest.h>
#include <pcl/tda/search/parallel_progress.h>

#include <cstddef>
#include <vector>

namespace pcl {
namespace tda {

/** \brief How the classifier of the category protocol is set up. */
struct ClassificationSettings {
  /** \brief The values of C tried by the cross-validation: 2^-1, 2^1, ..., 2^9. */
  std::vector<double> c_values{0.5, 2.0, 8.0, 32.0, 128.0, 512.0};
  /** \brief The values of gamma tried, in units of 1 / (descriptor dimension):
   * 2^-7, 2^-5, ..., 2^5 (libsvm's default gamma is 1 / dimension; values in [0, 1]
   * spread less than z-scores and need the larger ones). */
  std::vector<double> gamma_factors{1.0 / 128, 1.0 / 32, 1.0 / 8, 0.5, 2.0, 8.0, 32.0};
  /** \brief How descriptor values are scaled, on the training views only: to
   * [0, 1], as EVALUATION.md defines the protocol. */
  FeatureScalingMode scaling = FeatureScalingMode::MIN_MAX;
};

/** \brief The outcome of one trial for one descriptor. */
struct TrialOutcome {
  /** \brief The held-out views, those classified right, and those whose descriptor
   * failed (counted as wrong). */
  std::size_t tested = 0, correct = 0, failed = 0;
  /** \brief correct / tested. */
  double accuracy = 0.0;
  /** \brief The parameters chosen by the cross-validation, and its accuracy. */
  SVMParameters chosen;
  double validation_accuracy = 0.0;
};

/** \brief The outcome of the category protocol for one descriptor. */
struct DescriptorOutcome {
  std::vector<TrialOutcome> trials;
  /** \brief confusion[true category][predicted category] over the held-out views
   * of all trials; the extra last column counts views whose descriptor failed. */
  std::vector<std::vector<std::size_t>> confusion;

  /** \brief The mean accuracy over the trials. */
  double
  meanAccuracy () const;

  /** \brief The sample standard deviation of the accuracy over the trials (0 for
   * one trial). */
  double
  accuracyDeviation () const;
};

/** \brief The units of work evaluateDescriptor() reports for \a trials: one per SVM
 * it trains. */
std::size_t
classificationWork (const std::vector<ProtocolTrial>& trials,
                    const ClassificationSettings& settings);

/** \brief Runs the category protocol (thesis Sec 6.5.1) for one descriptor whose
 * vector for view i of \a manifest is \a rows[i] (empty when the descriptor failed
 * on the view; all others of one size). For each trial of \a trials:
 * - the SVM's C and gamma are chosen on the training views only, by
 *   cross-validation over the trial's instance folds: for each pair of the grid of
 *   \a settings, an SVM is trained on all folds but one (values scaled with those
 *   folds' statistics) and tested on the views of the last, fold after fold; the
 *   pair with most views right wins, ties going to the smaller gamma, then the
 *   smaller C (the smoother classifier);
 * - an SVM with these parameters is trained on all training views (values scaled
 *   with their statistics) and classifies the held-out views.
 * Views whose descriptor failed take no part in training and count as wrong when
 * held out. \a parts are the sizes of the descriptors concatenated in a row
 * (fitFeatureScaling()). The SVMs are trained in parallel (OpenMP); the outcome
 * does not depend on the number of threads.
 * \param[in] progress advanced by one per SVM trained (may be null) */
DescriptorOutcome
evaluateDescriptor (const std::vector<std::vector<float>>& rows,
                    const std::vector<std::size_t>& parts,
                    const ViewManifest& manifest,
                    const std::vector<ProtocolTrial>& trials,
                    const ClassificationSettings& settings,
                    ParallelProgress* progress = nullptr);

} // namespace tda
} // namespace pcl
