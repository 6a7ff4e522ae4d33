#pragma once

#include <pcl/tda/apps/view_manifest.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The fold of a held-out (test) instance in ProtocolTrial::instance_folds. */
constexpr std::size_t TEST_FOLD = std::numeric_limits<std::size_t>::max();

/** \brief One trial of the category protocol of thesis Sec 6.5.1: one instance of
 * each category held out for testing, the views of the others for training, and
 * the training instances dealt into folds for the choice of the SVM's parameters
 * by cross-validation (a whole instance in one fold, so that the cross-validation
 * asks the same question as the test: a new object of a known category). */
struct ProtocolTrial {
  /** \brief The held-out instance of each category (indices in
   * ViewManifest::instances), by category. */
  std::vector<std::size_t> test_instances;
  /** \brief The fold of each instance: 0..folds-1 for training instances, TEST_FOLD
   * for the held-out ones. */
  std::vector<std::size_t> instance_folds;
  /** \brief The number of folds (at least 2). */
  std::size_t folds = 0;
};

/** \brief The splits of \a trials trials, the same for every descriptor:
 * - trial t holds out, from each category, an instance drawn uniformly at random
 *   (one generator seeded with \a seed draws them, trial after trial, category by
 *   category in name order), so that the test instances do not depend on \a folds;
 * - its training instances are dealt into min(\a folds, their number) folds (\a folds
 *   0: one fold per training instance, leave-one-instance-out): each category's
 *   instances in a random order (a generator seeded with \a seed and t), dealt round
 *   the folds where the previous category stopped, so that the folds are about
 *   equal and each holds instances of as many categories as it can.
 * Equal seeds give equal trials.
 * \throws pcl::BadArgumentException when \a trials is 0 or \a folds is 1 */
std::vector<ProtocolTrial>
makeProtocolTrials (const ViewManifest& manifest,
                    std::size_t trials,
                    std::size_t folds,
                    std::uint64_t seed);

} // namespace tda
} // namespace pcl
