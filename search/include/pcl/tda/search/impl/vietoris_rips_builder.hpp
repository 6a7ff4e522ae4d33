#pragma once

#include <pcl/common/time.h>
#include <pcl/console/print.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/index_check.h>
#include <pcl/tda/search/clique_complex.h>
#include <pcl/tda/search/complex_size.h>
#include <pcl/tda/search/radius_edges.h>
#include <pcl/tda/search/uniform_grid.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/tda/search/vietoris_rips_checks.h>
#include <pcl/tda/search/vietoris_rips_phases.h>
#include <pcl/exceptions.h>

#include <atomic>
#include <memory>
#include <vector>

namespace pcl {
namespace tda {

template <typename PointT>
MemoryBudget
VietorisRipsBuilder<PointT>::memoryBudget() const
{
  return vietorisRipsMemoryBudget (memory_limit_, getLimitedDimension());
}

template <typename PointT>
bool
VietorisRipsBuilder<PointT>::fitsMemory (const ComplexSize& size) const
{
  return complexFitsMemory (
      getClassName(), radius_, getLimitedDimension(), memoryBudget(), size);
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
  if (!checkVietorisRipsSettings (getClassName(), radius_, max_dimension_) ||
      !indicesAreValid (getClassName() + "::compute", input_->size(), *indices_))
    return fail();
  pcl::StopWatch watch;
  const VietorisRipsProgress progress (progress_, max_dimension_);

  pcl::Indices order =
      vietorisRipsVertices (getClassName(), *input_, *indices_, skipped_points_);
  if (order.empty())
    return fail();
  std::vector<Point3d> points (order.size());
  for (std::size_t v = 0; v < order.size(); ++v) {
    const PointT& point = (*input_)[order[v]];
    points[v] = {point.x, point.y, point.z};
  }

  // Phase 1: the edges, counted before they are listed. The grid lists them, or
  // with a search object bounds and samples the complex only: either way one far
  // over the limit is refused in bounded time (bounds, then a sample).
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
  ComplexSize size;
  std::vector<FilteredEdge> edges;
  if (search_) {
    // PCL searches compare squared float distances: widen the radius so that no
    // point within the exact radius is missed; the exact test comes afterwards.
    const double search_radius = radius_ * (1.0 + 1e-5);
    search_->setInputCloud (input_, indices_);
    std::vector<SimplexIndex> vertex_of_input (input_->size(), INVALID_SIMPLEX);
    for (std::size_t v = 0; v < order.size(); ++v)
      vertex_of_input[order[v]] = static_cast<SimplexIndex> (v);
    // A search that cannot search the cloud (an OrganizedNeighbor on a cloud without
    // rows and columns) finds nothing, not even a point near itself: every point
    // would be alone.
    std::atomic<bool> missed_itself{false};
    const CandidateSearch candidates = [&] (SimplexIndex vertex,
                                            std::vector<SimplexIndex>& out) {
      pcl::Indices found;
      std::vector<float> squared_distances;
      search_->radiusSearch (
          (*input_)[order[vertex]], search_radius, found, squared_distances);
      out.clear();
      bool itself = false;
      for (const auto index : found) {
        itself = itself || index == order[vertex];
        if (vertex_of_input[index] != INVALID_SIMPLEX)
          out.push_back (vertex_of_input[index]);
      }
      if (!itself)
        missed_itself.store (true, std::memory_order_relaxed);
    };
    std::vector<std::uint64_t> offsets;
    const auto count_edges = [&] () {
      offsets = countEdgesBySearch (points, radius_, candidates, threads_);
      std::uint64_t triangle_bound = 0; // (later neighbours choose 2) per vertex
      for (std::size_t v = 0; v + 1 < offsets.size(); ++v) {
        const std::uint64_t later = offsets[v + 1] - offsets[v];
        if (later > 1)
          triangle_bound += later * (later - 1) / 2;
      }
      return EdgeCountSummary{offsets.back(), triangle_bound};
    };
    const auto estimate = [&] () {
      return estimateComplexSize (*grid, points, radius_, AcceptAllPairs{}, threads_);
    };
    if (!countEdgesWithinBudget (
            memoryBudget(), grid->numCandidatePairs(), count_edges, estimate, size)) {
      fitsMemory (size);
      return fail();
    }
    if (!fitsMemory ({size.edges, 0.0, true})) // 32-bit edge ids
      return fail();
    progress.reach (VietorisRipsProgress::EDGES_COUNTED);
    edges = listEdgesBySearch (points, radius_, candidates, offsets, threads_);
    if (missed_itself) {
      PCL_ERROR ("[pcl::tda::%s::compute] The search method did not find some points "
                 "of the input near themselves: it cannot search this cloud (an "
                 "OrganizedNeighbor needs an organized cloud).\n",
                 getClassName().c_str());
      return fail();
    }
    progress.reach (VietorisRipsProgress::EDGES_LISTED);
  }
  else {
    RadiusEdgeCounts counts;
    if (!countRadiusEdgesWithinBudget (
            *grid,
            points,
            radius_,
            AcceptAllPairs{},
            threads_,
            memoryBudget(),
            counts,
            size,
            progress.between (VietorisRipsProgress::START,
                              VietorisRipsProgress::EDGES_COUNTED))) {
      fitsMemory (size);
      return fail();
    }
    edges = listRadiusEdges (*grid,
                             points,
                             radius_,
                             AcceptAllPairs{},
                             counts.offsets,
                             threads_,
                             progress.between (VietorisRipsProgress::EDGES_COUNTED,
                                               VietorisRipsProgress::EDGES_LISTED));
  }
  timings_.neighbor_search = watch.getTimeSeconds();
  watch.reset();
  sortEdges (edges, threads_);
  progress.reach (VietorisRipsProgress::EDGES_SORTED);
  timings_.edges = watch.getTimeSeconds();
  watch.reset();

  // Phase 2: the triangles, counted before they are listed.
  std::vector<FilteredTriangle> triangles;
  if (max_dimension_ == 2) {
    const EdgeAdjacency adjacency = buildEdgeAdjacency (points.size(), edges);
    const std::vector<std::uint64_t> offsets =
        countTriangles (edges,
                        adjacency,
                        threads_,
                        progress.between (VietorisRipsProgress::EDGES_SORTED,
                                          VietorisRipsProgress::TRIANGLES_COUNTED));
    if (!fitsMemory ({static_cast<double> (edges.size()),
                      static_cast<double> (offsets.back()),
                      true}))
      return fail();
    triangles =
        fillTriangles (edges,
                       adjacency,
                       offsets,
                       threads_,
                       progress.between (VietorisRipsProgress::TRIANGLES_COUNTED,
                                         VietorisRipsProgress::DONE));
  }
  progress.reach (VietorisRipsProgress::DONE);
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
