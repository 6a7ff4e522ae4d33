#pragma once

#include <pcl/tda/common/index_check.h>
#include <pcl/tda/features/setting_checks.h>
#include <pcl/tda/features/stpp_estimation.h>
#include <pcl/tda/features/stpp_sublevel.h>
#include <pcl/tda/features/whole_cloud_signature.h>
#include <pcl/tda/search/canonical_order.h>
#include <pcl/tda/search/point_spacing.h>
#include <pcl/tda/search/radius_edges.h>

#include <cmath>

namespace pcl {
namespace tda {

template <typename PointInT, typename PointOutT>
bool
STPPEstimation<PointInT, PointOutT>::initCompute()
{
  clearResults();
  if (!checkFeatureInput (pcl::PCLBase<PointInT>::initCompute(),
                          getClassName(),
                          this->search_radius_,
                          this->k_,
                          this->tree_ != nullptr,
                          this->surface_ && this->surface_ != input_))
    return false;
  if (homology_ != STPPHomology::BETTI_0 && homology_ != STPPHomology::BETTI_1 &&
      homology_ != STPPHomology::BETTI_0_1) {
    PCL_ERROR ("[pcl::tda::%s::compute] Unknown homology %d: BETTI_0, BETTI_1 or "
               "BETTI_0_1.\n",
               getClassName().c_str(),
               static_cast<int> (homology_));
    return false;
  }
  return indicesAreValid (getClassName() + "::compute", input_->size(), *indices_) &&
         checkOptionalLength (radius_, getClassName(), "radius", "to choose it") &&
         checkMaxPoints (max_points_, radius_, getClassName());
}

template <typename PointInT, typename PointOutT>
void
STPPEstimation<PointInT, PointOutT>::clearResults()
{
  pairing_vector_.clear();
  level_radii_.clear();
  level_diagrams_.clear();
  cloud_size_ = 0.0;
}

template <typename PointInT, typename PointOutT>
bool
STPPEstimation<PointInT, PointOutT>::computeSignature (float* histogram)
{
  std::size_t skipped = 0;
  const pcl::Indices order = canonicalOrder (*input_, *indices_, skipped);
  std::vector<Point3d> all_points;
  all_points.reserve (order.size());
  for (const pcl::index_t index : order) {
    const PointInT& p = (*input_)[index];
    all_points.push_back ({p.x, p.y, p.z});
  }
  cloud_size_ = cloudSize (all_points);
  std::vector<Point3d> points;
  for (const std::size_t i : hashedSample (
           all_points.size(), max_points_ > 0 ? max_points_ : all_points.size()))
    points.push_back (all_points[i]);
  const double spacing =
      radius_ > 0.0
          ? 0.0
          : surfaceSpacing (*toPointCloud (points), SPACING_SAMPLES, threads_);
  if (!(cloud_size_ > 0.0) || (radius_ == 0.0 && !(spacing > 0.0))) {
    PCL_ERROR ("[pcl::tda::%s::compute] The input has too few distinct finite points "
               "(%zu finite of %zu indexed) to describe: at least %zu are needed.\n",
               getClassName().c_str(),
               all_points.size(),
               indices_->size(),
               SURFACE_SPACING_NEIGHBORS + 1);
    return false;
  }
  level_radii_.push_back (radius_ > 0.0 ? radius_ : AUTO_RADIUS_PER_SPACING * spacing);
  for (const double fraction : COARSE_RADII_PER_SIZE)
    level_radii_.push_back (fraction * cloud_size_);

  // Each coarse copy is made from the one before (the first from all points, as a
  // sample has gaps the cloud does not have): its spacing doubles at each level.
  std::vector<std::vector<Point3d>> level_points (STPP_LEVELS);
  level_points[0] = std::move (points);
  for (std::size_t level = 1; level < STPP_LEVELS; ++level)
    level_points[level] = coarseCopy (level == 1 ? all_points : level_points[level - 1],
                                      level_radii_[level] / COARSE_RADIUS_PER_SPACING);

  // The levels are independent: one thread each.
  std::vector<FilteredComplex> complexes (STPP_LEVELS);
  std::vector<PersistenceResult> results (STPP_LEVELS);
  std::vector<std::uint8_t> built (STPP_LEVELS, 0);
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolveThreads(threads_))
  for (std::size_t level = 0; level < STPP_LEVELS; ++level)
    built[level] = levelPersistence (level_points[level],
                                     level_radii_[level],
                                     homology_,
                                     memory_limit_,
                                     1,
                                     complexes[level],
                                     results[level]);

  for (std::size_t level = 0; level < STPP_LEVELS; ++level) {
    const double radius = level_radii_[level];
    if (!built[level]) {
      PCL_ERROR ("[pcl::tda::%s::compute] Cannot build the complex of level %zu, "
                 "radius %g (see above).\n",
                 getClassName().c_str(),
                 level,
                 radius);
      return false;
    }
    // A coarse copy's own sampling cycles are born and die below twice its
    // spacing: its curves start there, where what is left is the object's.
    const double curve_start =
        level == 0 ? 0.0 : 2.0 * radius / COARSE_RADIUS_PER_SPACING;
    if (homology_ != STPPHomology::BETTI_1)
      betti0LevelValues (complexes[level],
                         results[level],
                         curve_start,
                         radius,
                         histogram + STPP_BETTI0_OFFSET +
                             level * STPP_BETTI0_PER_LEVEL);
    if (homology_ != STPPHomology::BETTI_0)
      betti1LevelValues (complexes[level],
                         results[level],
                         curve_start,
                         radius,
                         histogram + STPP_BETTI1_OFFSET +
                             level * STPP_BETTI1_PER_LEVEL);
    level_diagrams_.push_back (results[level].diagram (complexes[level]));
  }
  if (homology_ != STPPHomology::BETTI_1) {
    const auto functions = shapeFunctions (level_points[SUBLEVEL_LEVEL], cloud_size_);
    for (std::size_t k = 0; k < STPP_SUBLEVEL_FUNCTIONS; ++k)
      sublevelValues (complexes[SUBLEVEL_LEVEL],
                      functions[k],
                      histogram + STPP_SUBLEVEL_OFFSET +
                          k * STPP_SUBLEVEL_PER_FUNCTION);
  }
  pairing_vector_ = pairingVector (complexes[0], results[0], homology_);
  histogram[STPP_SIZE_OFFSET] =
      scale_invariant_ ? 0.0f : static_cast<float> (std::log10 (cloud_size_));
  return true;
}

template <typename PointInT, typename PointOutT>
void
STPPEstimation<PointInT, PointOutT>::computeFeature (PointCloudOut& output)
{
  if (!computeWholeCloudSignature (output, STPP_SIGNATURE_SIZE, [this] (float* values) {
        return computeSignature (values);
      }))
    clearResults();
}

} // namespace tda
} // namespace pcl

#define PCL_INSTANTIATE_STPPEstimation(T, OutT)                                        \
  template class PCL_EXPORTS pcl::tda::STPPEstimation<T, OutT>;
