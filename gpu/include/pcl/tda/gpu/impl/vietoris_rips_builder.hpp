#pragma once

#include <pcl/common/time.h>
#include <pcl/console/print.h>
#include <pcl/tda/common/index_check.h>
#include <pcl/tda/gpu/vietoris_rips_builder.h>
#include <pcl/tda/search/vietoris_rips_checks.h>

#include <utility>
#include <vector>

namespace pcl {
namespace tda {
namespace gpu {

template <typename PointT>
bool
VietorisRipsBuilder<PointT>::compute (FilteredComplex& complex)
{
  complex = FilteredComplex();
  timings_ = {};
  skipped_points_ = 0;
  if (!initCompute())
    return false;
  const auto fail = [this] () {
    deinitCompute();
    return false;
  };
  if (!checkVietorisRipsSettings (getClassName(), radius_, max_dimension_) ||
      !indicesAreValid (getClassName() + "::compute", input_->size(), *indices_))
    return fail();
  pcl::StopWatch watch;

  pcl::Indices order =
      vietorisRipsVertices (getClassName(), *input_, *indices_, skipped_points_);
  if (order.empty())
    return fail();
  // Plain floats cross to the device: the coordinates in canonical order.
  std::vector<float> xyz (3 * order.size());
  for (std::size_t v = 0; v < order.size(); ++v) {
    const PointT& point = (*input_)[order[v]];
    xyz[3 * v] = point.x;
    xyz[3 * v + 1] = point.y;
    xyz[3 * v + 2] = point.z;
  }
  const double preparation = watch.getTimeSeconds();

  std::string why;
  backend_ = selectBackend (why);
  if (!why.empty() && !fallback_reported_) {
    PCL_WARN ("[pcl::tda::%s::compute] No CUDA device (%s): running on the OpenMP "
              "backend.\n",
              getClassName().c_str(),
              why.c_str());
    fallback_reported_ = true;
  }
  DeviceBuildSettings settings;
  settings.class_name = getClassName();
  settings.radius = radius_;
  settings.max_dimension = max_dimension_;
  settings.limited_dimension = getLimitedDimension();
  settings.memory_limit = memory_limit_;
  settings.threads = threads_;
  settings.progress = progress_;
  std::vector<FilteredEdge> edges;
  std::vector<FilteredTriangle> triangles;
  if (!buildVietorisRipsComplex (xyz, settings, backend_, edges, triangles, timings_))
    return fail();
  timings_.neighbor_search += preparation;

  const std::size_t num_vertices = order.size();
  complex = FilteredComplex::adoptValidParts (
      num_vertices, std::move (edges), std::move (triangles), std::move (order));
  deinitCompute();
  return true;
}

} // namespace gpu
} // namespace tda
} // namespace pcl

#define PCL_INSTANTIATE_GPUVietorisRipsBuilder(T)                                      \
  template class PCL_EXPORTS pcl::tda::gpu::VietorisRipsBuilder<T>;
