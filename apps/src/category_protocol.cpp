#include <pcl/tda/apps/category_protocol.h>
#include <pcl/tda/generators/random_sampling.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <utility>

namespace pcl {
namespace tda {
namespace {

/** The seed of trial \a trial's fold generator: \a seed and \a trial mixed
 * (SplitMix64's finaliser), so that neighbouring trials get unrelated folds. */
std::uint64_t
foldSeed (std::uint64_t seed, std::size_t trial)
{
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (trial + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/** Deals the training instances of \a trial into its folds. */
void
dealFolds (const ViewManifest& manifest,
           std::size_t folds,
           std::uint64_t seed,
           ProtocolTrial& trial)
{
  std::size_t training = 0;
  for (const std::size_t fold : trial.instance_folds)
    training += fold != TEST_FOLD ? 1 : 0;
  trial.folds = folds == 0 ? training : std::min (folds, training);
  PortableRandom random (seed);
  std::size_t next = 0;
  for (const auto& instances : manifest.category_instances) {
    std::vector<std::size_t> order;
    for (const std::size_t instance : instances)
      if (trial.instance_folds[instance] != TEST_FOLD)
        order.push_back (instance);
    for (std::size_t i = order.size(); i > 1; --i) // Fisher-Yates
      std::swap (order[i - 1], order[random.index (i)]);
    for (const std::size_t instance : order) {
      trial.instance_folds[instance] = next;
      next = (next + 1) % trial.folds;
    }
  }
}

} // namespace

std::vector<ProtocolTrial>
makeProtocolTrials (const ViewManifest& manifest,
                    std::size_t trials,
                    std::size_t folds,
                    std::uint64_t seed)
{
  if (trials == 0)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException, "The protocol needs a trial.");
  if (folds == 1)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Cross-validation needs at least 2 folds (0: one per "
                         "instance).");
  std::vector<ProtocolTrial> result (trials);
  PortableRandom test_random (seed);
  for (std::size_t t = 0; t < trials; ++t) {
    ProtocolTrial& trial = result[t];
    trial.instance_folds.assign (manifest.instances.size(), 0);
    for (const auto& instances : manifest.category_instances) {
      const std::size_t held_out = instances[test_random.index (instances.size())];
      trial.test_instances.push_back (held_out);
      trial.instance_folds[held_out] = TEST_FOLD;
    }
    dealFolds (manifest, folds, foldSeed (seed, t), trial);
  }
  return result;
}

} // namespace tda
} // namespace pcl
