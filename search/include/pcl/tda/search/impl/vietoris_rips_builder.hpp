#pragma once

#include <pcl/common/time.h>
#include <pcl/console/print.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/search/canonical_order.h>
#include <pcl/tda/search/clique_complex.h>
#include <pcl/tda/search/radius_edges.h>
#include <pcl/tda/search/uniform_grid.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/exceptions.h>

#include <cmath>
#include <limits>

namespace pcl {
namespace tda {

template <typename PointT>
VietorisRipsBuilder<PointT>::VietorisRipsBuilder()
: memory_limit_ (physicalMemoryBytes() > 0 ? physicalMemoryBytes() / 2
                                           : std::numeric_limits<std::size_t>::max())
{}

template <typename PointT>
bool
VietorisRipsBuilder<PointT>::fitsMemory (std::size_t edges,
                                         std::size_t triangles,
                                         bool triangles_known) const
{
  const std::size_t bytes = edges * BYTES_PER_EDGE + triangles * BYTES_PER_TRIANGLE;
  const bool ids_fit = edges < INVALID_SIMPLEX && triangles < INVALID_SIMPLEX;
  if (bytes <= memory_limit_ && ids_fit)
    return true;
  const std::string size =
      std::to_string (edges) + " edges" +
      (triangles_known ? " and " + std::to_string (triangles) + " triangles"
                       : " (triangles not counted yet)");
  if (!ids_fit)
    PCL_ERROR ("[pcl::tda::%s::compute] The complex of radius %g would have %s: more "
               "than 2^32 - 1 simplices of one dimension. Use a smaller radius or a "
               "voxel grid.\n",
               getClassName().c_str(),
               radius_,
               size.c_str());
  else
    PCL_ERROR ("[pcl::tda::%s::compute] The complex of radius %g would have %s, "
               "about %.1f MiB, over the memory limit of %.1f MiB. Use a smaller "
               "radius, a voxel grid, or setMemoryLimit().\n",
               getClassName().c_str(),
               radius_,
               size.c_str(),
               bytes / 1048576.0,
               memory_limit_ / 1048576.0);
  return false;
}

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
  if (!(radius_ > 0.0) || !std::isfinite (radius_)) {
    PCL_ERROR ("[pcl::tda::%s::compute] The radius must be positive and finite, not "
               "%g.\n",
               getClassName().c_str(),
               radius_);
    return fail();
  }
  if (max_dimension_ != 1 && max_dimension_ != 2) {
    PCL_ERROR (
        "[pcl::tda::%s::compute] The maximum dimension must be 1 or 2, not %d.\n",
        getClassName().c_str(),
        max_dimension_);
    return fail();
  }
  pcl::StopWatch watch;

  pcl::Indices order = canonicalOrder (*input_, *indices_, skipped_points_);
  if (skipped_points_ > 0)
    PCL_WARN ("[pcl::tda::%s::compute] Skipped %zu non-finite points.\n",
              getClassName().c_str(),
              skipped_points_);
  if (order.empty()) {
    PCL_ERROR ("[pcl::tda::%s::compute] The input has no finite point.\n",
               getClassName().c_str());
    return fail();
  }
  std::vector<Point3d> points (order.size());
  for (std::size_t v = 0; v < order.size(); ++v) {
    const PointT& point = (*input_)[order[v]];
    points[v] = {point.x, point.y, point.z};
  }

  // Phase 1: the edges, counted before they are listed.
  std::vector<FilteredEdge> edges;
  if (search_) {
    // PCL searches compare squared float distances: widen the radius so that no
    // point within the exact radius is missed; the exact test comes afterwards.
    const double search_radius = radius_ * (1.0 + 1e-5);
    search_->setInputCloud (input_, indices_);
    std::vector<SimplexIndex> vertex_of_input (input_->size(), INVALID_SIMPLEX);
    for (std::size_t v = 0; v < order.size(); ++v)
      vertex_of_input[order[v]] = static_cast<SimplexIndex> (v);
    const CandidateSearch candidates = [&] (SimplexIndex vertex,
                                            std::vector<SimplexIndex>& out) {
      pcl::Indices found;
      std::vector<float> squared_distances;
      search_->radiusSearch (
          (*input_)[order[vertex]], search_radius, found, squared_distances);
      out.clear();
      for (const auto index : found)
        if (vertex_of_input[index] != INVALID_SIMPLEX)
          out.push_back (vertex_of_input[index]);
    };
    const std::vector<std::uint64_t> offsets =
        countEdgesBySearch (points, radius_, candidates, threads_);
    if (!fitsMemory (offsets.back(), 0, false))
      return fail();
    edges = listEdgesBySearch (points, radius_, candidates, offsets, threads_);
  }
  else {
    std::unique_ptr<UniformGrid> grid;
    try {
      grid = std::make_unique<UniformGrid> (points, radius_, threads_);
    }
    catch (const pcl::PCLException& error) {
      PCL_ERROR ("[pcl::tda::%s::compute] %s\n",
                 getClassName().c_str(),
                 errorMessage (error).c_str());
      return fail();
    }
    const std::vector<std::uint64_t> offsets =
        countRadiusEdges (*grid, points, radius_, AcceptAllPairs{}, threads_);
    if (!fitsMemory (offsets.back(), 0, false))
      return fail();
    edges =
        listRadiusEdges (*grid, points, radius_, AcceptAllPairs{}, offsets, threads_);
  }
  timings_.neighbor_search = watch.getTimeSeconds();
  watch.reset();
  sortEdges (edges, threads_);
  timings_.edges = watch.getTimeSeconds();
  watch.reset();

  // Phase 2: the triangles, counted before they are listed.
  std::vector<FilteredTriangle> triangles;
  if (max_dimension_ == 2) {
    const EdgeAdjacency adjacency = buildEdgeAdjacency (points.size(), edges);
    const std::vector<std::uint64_t> offsets =
        countTriangles (edges, adjacency, threads_);
    if (!fitsMemory (edges.size(), offsets.back(), true))
      return fail();
    triangles = fillTriangles (edges, adjacency, offsets, threads_);
  }
  timings_.triangles = watch.getTimeSeconds();

  complex = FilteredComplex::adoptValidParts (
      points.size(), std::move (edges), std::move (triangles), std::move (order));
  deinitCompute();
  return true;
}

} // namespace tda
} // namespace pcl

#define PCL_INSTANTIATE_VietorisRipsBuilder(T)                                         \
  template class PCL_EXPORTS pcl::tda::VietorisRipsBuilder<T>;
