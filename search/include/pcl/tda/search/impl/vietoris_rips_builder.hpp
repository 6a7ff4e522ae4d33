#pragma once

#include <pcl/common/time.h>
#include <pcl/console/print.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/search/canonical_order.h>
#include <pcl/tda/search/clique_complex.h>
#include <pcl/tda/search/complex_size.h>
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
: memory_limit_ (defaultMemoryLimit())
{}

template <typename PointT>
MemoryBudget
VietorisRipsBuilder<PointT>::memoryBudget() const
{
  return {memory_limit_, BYTES_PER_EDGE, max_dimension_ == 2 ? BYTES_PER_TRIANGLE : 0};
}

template <typename PointT>
std::size_t
VietorisRipsBuilder<PointT>::permilleAt (BuildPhase phase) const
{
  // Where each phase ends, in thousandths of the build: the triangle passes are the
  // long ones when there are triangles.
  constexpr std::size_t WITH_TRIANGLES[] = {0, 150, 300, 400, 700, 1000};
  constexpr std::size_t EDGES_ONLY[] = {0, 350, 700, 1000, 1000, 1000};
  return (max_dimension_ == 2 ? WITH_TRIANGLES : EDGES_ONLY)[phase];
}

template <typename PointT>
ProgressCallback
VietorisRipsBuilder<PointT>::phaseProgress (BuildPhase first, BuildPhase last) const
{
  if (!progress_)
    return {};
  const std::size_t begin = permilleAt (first), end = permilleAt (last);
  return [this, begin, end] (std::size_t done, std::size_t total) {
    progress_ (begin + (end - begin) * done / std::max<std::size_t> (total, 1), 1000);
  };
}

template <typename PointT>
void
VietorisRipsBuilder<PointT>::reportPhase (BuildPhase phase) const
{
  if (progress_)
    progress_ (permilleAt (phase), 1000);
}

template <typename PointT>
bool
VietorisRipsBuilder<PointT>::fitsMemory (const ComplexSize& size) const
{
  const bool ids_fit = size.edges < INVALID_SIMPLEX && size.triangles < INVALID_SIMPLEX;
  if (memoryBudget().fits (size.edges, size.triangles) && ids_fit)
    return true;
  const char* about = size.exact ? "" : "about ";
  std::string sizes = about + std::to_string (std::llround (size.edges)) + " edges";
  if (max_dimension_ == 2 && size.triangles > 0.0)
    sizes += std::string (" and ") + about +
             std::to_string (std::llround (size.triangles)) + " triangles";
  if (!size.exact)
    sizes += " (estimated from a sample)";
  if (!memoryBudget().fits (size.edges, size.triangles))
    PCL_ERROR ("[pcl::tda::%s::compute] The complex of radius %g would have %s, "
               "%s%s, over the memory limit of %s. Use a smaller radius, a voxel grid, "
               "or a larger limit (setMemoryLimit()).\n",
               getClassName().c_str(),
               radius_,
               sizes.c_str(),
               about,
               formatBytes (memoryBudget().bytes (size.edges, size.triangles)).c_str(),
               formatBytes (static_cast<double> (memory_limit_)).c_str());
  else
    PCL_ERROR ("[pcl::tda::%s::compute] The complex of radius %g would have %s: more "
               "than 2^32 - 1 simplices of one dimension. Use a smaller radius or a "
               "voxel grid.\n",
               getClassName().c_str(),
               radius_,
               sizes.c_str());
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
    reportPhase (EDGES_COUNTED);
    if (!fitsMemory ({static_cast<double> (offsets.back()), 0.0, true}))
      return fail();
    edges = listEdgesBySearch (points, radius_, candidates, offsets, threads_);
    reportPhase (EDGES_LISTED);
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
    // Refused in bounded time when far over the limit (bounds, then a sample).
    RadiusEdgeCounts counts;
    ComplexSize size;
    if (!countRadiusEdgesWithinBudget (*grid,
                                       points,
                                       radius_,
                                       AcceptAllPairs{},
                                       threads_,
                                       memoryBudget(),
                                       counts,
                                       size,
                                       phaseProgress (START, EDGES_COUNTED))) {
      fitsMemory (size);
      return fail();
    }
    edges = listRadiusEdges (*grid,
                             points,
                             radius_,
                             AcceptAllPairs{},
                             counts.offsets,
                             threads_,
                             phaseProgress (EDGES_COUNTED, EDGES_LISTED));
  }
  timings_.neighbor_search = watch.getTimeSeconds();
  watch.reset();
  sortEdges (edges, threads_);
  reportPhase (EDGES_SORTED);
  timings_.edges = watch.getTimeSeconds();
  watch.reset();

  // Phase 2: the triangles, counted before they are listed.
  std::vector<FilteredTriangle> triangles;
  if (max_dimension_ == 2) {
    const EdgeAdjacency adjacency = buildEdgeAdjacency (points.size(), edges);
    const std::vector<std::uint64_t> offsets = countTriangles (
        edges, adjacency, threads_, phaseProgress (EDGES_SORTED, TRIANGLES_COUNTED));
    if (!fitsMemory ({static_cast<double> (edges.size()),
                      static_cast<double> (offsets.back()),
                      true}))
      return fail();
    triangles = fillTriangles (
        edges, adjacency, offsets, threads_, phaseProgress (TRIANGLES_COUNTED, DONE));
  }
  reportPhase (DONE);
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
