#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/tda/common/cielab.h>
#include <pcl/tda/common/index_check.h>
#include <pcl/tda/features/covariance_signature.h>
#include <pcl/tda/features/setting_checks.h>
#include <pcl/tda/features/stpp_levels.h>
#include <pcl/tda/features/topological_covariance_estimation.h>
#include <pcl/tda/features/whole_cloud_signature.h>
#include <pcl/tda/search/canonical_order.h>
#include <pcl/tda/search/point_spacing.h>
#include <pcl/type_traits.h>

#include <algorithm>
#include <cmath>

namespace pcl {
namespace tda {

template <typename PointInT, typename PointNT, typename PointOutT>
bool
TopologicalCovarianceEstimation<PointInT, PointNT, PointOutT>::initCompute()
{
  used_radius_ = 0.0;
  if (!pcl::PCLBase<PointInT>::initCompute()) {
    PCL_ERROR ("[pcl::tda::%s::compute] No input cloud: call setInputCloud().\n",
               getClassName().c_str());
    return false;
  }
  if (!normals_) {
    PCL_ERROR ("[pcl::tda::%s::compute] No normals: call setInputNormals().\n",
               getClassName().c_str());
    return false;
  }
  if (!indicesAreValid (getClassName() + "::compute", input_->size(), *indices_))
    return false;
  if (normals_->size() != input_->size()) {
    PCL_ERROR ("[pcl::tda::%s::compute] The normals (%zu) must match the input "
               "cloud (%zu points) one to one.\n",
               getClassName().c_str(),
               static_cast<std::size_t> (normals_->size()),
               static_cast<std::size_t> (input_->size()));
    return false;
  }
  return checkOptionalLength (radius_, getClassName(), "radius", "to choose it") &&
         checkMaxPoints (max_points_, radius_, getClassName());
}

template <typename PointInT, typename PointNT, typename PointOutT>
bool
TopologicalCovarianceEstimation<PointInT, PointNT, PointOutT>::computeSignature (
    float* values)
{
  // The points with a finite normal, in canonical order, and a sample of them.
  std::size_t skipped = 0;
  pcl::Indices usable;
  for (const pcl::index_t index : canonicalOrder (*input_, *indices_, skipped))
    if (pcl::isNormalFinite ((*normals_)[index]))
      usable.push_back (index);
  pcl::Indices used;
  for (const std::size_t i :
       hashedSample (usable.size(), max_points_ > 0 ? max_points_ : usable.size()))
    used.push_back (usable[i]);
  std::vector<Point3d> points;
  for (const pcl::index_t index : used) {
    const PointInT& p = (*input_)[index];
    points.push_back ({p.x, p.y, p.z});
  }
  const double spacing =
      radius_ > 0.0
          ? 0.0
          : surfaceSpacing (*toPointCloud (points), DEFAULT_SPACING_SAMPLES, threads_);
  if (points.size() < 2 || (radius_ == 0.0 && !(spacing > 0.0))) {
    PCL_ERROR ("[pcl::tda::%s::compute] The input has too few distinct points with a "
               "finite position and normal (%zu of %zu indexed) to describe: at "
               "least %zu are needed%s.\n",
               getClassName().c_str(),
               usable.size(),
               indices_->size(),
               radius_ > 0.0 ? std::size_t{2} : SURFACE_SPACING_NEIGHBORS + 1,
               radius_ > 0.0 ? "" : " for the radius from their spacing");
    return false;
  }
  used_radius_ = radius_ > 0.0 ? radius_ : AUTO_RADIUS_PER_SPACING * spacing;

  FilteredComplex complex;
  PersistenceResult result;
  if (!levelPersistence (points,
                         used_radius_,
                         STPPHomology::BETTI_0,
                         memory_limit_,
                         threads_,
                         complex,
                         result)) {
    PCL_ERROR ("[pcl::tda::%s::compute] Cannot build the complex of radius %g (see "
               "above).\n",
               getClassName().c_str(),
               used_radius_);
    return false;
  }
  const std::vector<double> deaths = vertexDeathValues (complex, result);
  CovarianceFeatures features (static_cast<Eigen::Index> (used.size()),
                               static_cast<Eigen::Index> (COVARIANCE_FEATURES));
  features.setZero();
  const pcl::Indices& vertex_points = complex.pointIndices();
  for (std::size_t v = 0; v < vertex_points.size(); ++v) {
    const auto row = static_cast<Eigen::Index> (vertex_points[v]);
    const pcl::index_t index = used[vertex_points[v]];
    const PointInT& p = (*input_)[index];
    const PointNT& n = (*normals_)[index];
    features.row (row).head<3>() << p.x, p.y, p.z;
    if constexpr (pcl::traits::has_color_v<PointInT>) {
      const LabColor lab = rgbToLab (p.r, p.g, p.b);
      features.row (row).segment<3> (3) << lab.l, lab.a, lab.b;
    }
    features.row (row).segment<3> (6) << n.normal_x, n.normal_y, n.normal_z;
    for (std::size_t s = 0; s < STEP_FRACTIONS.size(); ++s) {
      const double step = STEP_FRACTIONS[s] * used_radius_;
      features (row, static_cast<Eigen::Index> (9 + s)) =
          std::min (deaths[v], step) / step;
    }
  }
  logCovarianceVector (features, REGULARIZATION, values);
  return true;
}

template <typename PointInT, typename PointNT, typename PointOutT>
void
TopologicalCovarianceEstimation<PointInT, PointNT, PointOutT>::computeFeature (
    PointCloudOut& output)
{
  computeWholeCloudSignature (
      output, COVARIANCE_SIGNATURE_SIZE, [this] (float* values) {
        return computeSignature (values);
      });
}

} // namespace tda
} // namespace pcl

#define PCL_INSTANTIATE_TopologicalCovarianceEstimation(T, NT, OutT)                   \
  template class PCL_EXPORTS pcl::tda::TopologicalCovarianceEstimation<T, NT, OutT>;
