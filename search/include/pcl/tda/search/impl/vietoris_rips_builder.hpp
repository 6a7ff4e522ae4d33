#pragma once

#include <pcl/common/time.h>
#include <pcl/console/print.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/search/canonical_order.h>
#include <pcl/tda/search/clique_complex.h>
#include <pcl/tda/search/neighbor_graph.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/exceptions.h>

#include <omp.h>
#include <unistd.h>

#include <cmath>
#include <limits>

namespace pcl {
namespace tda {

namespace detail {

/** Sets the OpenMP thread count for the lifetime of the object (0: unchanged). */
class OpenMPThreadScope {
public:
  explicit OpenMPThreadScope (unsigned int threads) : previous_ (omp_get_max_threads())
  {
    if (threads > 0)
      omp_set_num_threads (static_cast<int> (threads));
  }
  ~OpenMPThreadScope() { omp_set_num_threads (previous_); }

private:
  int previous_;
};

inline std::size_t
halfOfPhysicalMemory ()
{
  return static_cast<std::size_t> (::sysconf (_SC_PHYS_PAGES)) *
         static_cast<std::size_t> (::sysconf (_SC_PAGE_SIZE)) / 2;
}

} // namespace detail

template <typename PointT>
VietorisRipsBuilder<PointT>::VietorisRipsBuilder()
: memory_limit_ (detail::halfOfPhysicalMemory())
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
  const detail::OpenMPThreadScope thread_scope (threads_);
  pcl::StopWatch watch;

  std::vector<int> order = canonicalOrder (*input_, *indices_, skipped_points_);
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

  // PCL searches compare squared float distances: widen the radius so that no
  // point within the exact radius is missed; the exact test comes afterwards.
  const double search_radius = radius_ * (1.0 + 1e-5);
  CandidateSearch candidates;
  std::unique_ptr<UniformGridSearch> grid;
  std::vector<SimplexIndex> vertex_of_input;
  if (search_) {
    search_->setInputCloud (input_, indices_);
    vertex_of_input.assign (input_->size(), INVALID_SIMPLEX);
    for (std::size_t v = 0; v < order.size(); ++v)
      vertex_of_input[order[v]] = static_cast<SimplexIndex> (v);
    candidates = [&] (SimplexIndex vertex, std::vector<SimplexIndex>& out) {
      pcl::Indices found;
      std::vector<float> squared_distances;
      search_->radiusSearch (
          (*input_)[order[vertex]], search_radius, found, squared_distances);
      out.clear();
      for (const auto index : found)
        if (vertex_of_input[index] != INVALID_SIMPLEX)
          out.push_back (vertex_of_input[index]);
    };
  }
  else {
    try {
      grid = std::make_unique<UniformGridSearch> (points, radius_);
    }
    catch (const pcl::PCLException& error) {
      PCL_ERROR ("[pcl::tda::%s::compute] %s\n",
                 getClassName().c_str(),
                 errorMessage (error).c_str());
      return fail();
    }
    candidates = [&grid] (SimplexIndex vertex, std::vector<SimplexIndex>& out) {
      (*grid) (vertex, out);
    };
  }

  const std::vector<std::uint32_t> neighbor_counts =
      countNeighbors (points, radius_, candidates);
  std::size_t num_edges = 0;
  for (const auto count : neighbor_counts)
    num_edges += count;
  if (!fitsMemory (num_edges, 0, false))
    return fail();
  std::vector<FilteredEdge> edges;
  {
    const NeighborGraph graph =
        fillNeighborGraph (points, radius_, candidates, neighbor_counts);
    timings_.neighbor_search = watch.getTimeSeconds();
    watch.reset();
    edges = sortedEdges (graph);
  }
  timings_.edges = watch.getTimeSeconds();
  watch.reset();

  std::vector<FilteredTriangle> triangles;
  if (max_dimension_ == 2) {
    const EdgeAdjacency adjacency = buildEdgeAdjacency (points.size(), edges);
    const std::vector<std::uint32_t> triangle_counts =
        countTriangles (edges, adjacency);
    std::size_t num_triangles = 0;
    for (const auto count : triangle_counts)
      num_triangles += count;
    if (!fitsMemory (num_edges, num_triangles, true))
      return fail();
    triangles = fillTriangles (edges, adjacency, triangle_counts);
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
