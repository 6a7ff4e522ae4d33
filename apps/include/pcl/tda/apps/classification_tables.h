#pragma once

#include <pcl/tda/apps/category_classification.h>
#include <pcl/tda/apps/view_descriptors.h>
#include <pcl/tda/apps/view_manifest.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief What pcl_tda_classify reports for one descriptor. */
struct DescriptorSummary {
  std::string name;
  /** \brief The size of its vectors. */
  std::size_t dimension = 0;
  /** \brief The views, and those on which it failed. */
  std::size_t views = 0, failed_views = 0;
  /** \brief The median over the views of the milliseconds to compute it. */
  double median_milliseconds = 0.0;
  /** \brief The seconds to compute it on all views (summed over threads). */
  double total_seconds = 0.0;
  DescriptorOutcome outcome;
};

/** \brief The SVM parameters chosen most often over the trials of \a outcome (ties:
 * the first trial's), and in how many trials. */
std::pair<SVMParameters, std::size_t>
mostChosen (const DescriptorOutcome& outcome);

/** \brief Writes one CSV row per descriptor: descriptor, dimension, views,
 * failed_views, trials, accuracy_mean, accuracy_sd (sample standard deviation over
 * the trials), C and gamma (mostChosen()), chosen_in (its number of trials),
 * ms_per_view_median, seconds_total, then per trial, space-separated:
 * trial_accuracies, trial_C, trial_gamma. */
void
writeResultsCSV (std::ostream& out, const std::vector<DescriptorSummary>& summaries);

/** \brief Writes every view's descriptors, one CSV row per view and descriptor:
 * path (as in the manifest), category, instance, view, descriptor, dimension,
 * failure (empty, or why the descriptor failed), then the values space-separated in
 * one field (shortest decimal that reads back as the same float).
 * \a computed[i][k] is descriptor \a names[k] of view i. */
void
writeFeaturesCSV (std::ostream& out,
                  const ViewManifest& manifest,
                  const std::vector<std::string>& names,
                  const std::vector<std::vector<ViewDescriptor>>& computed);

} // namespace tda
} // namespace pcl
