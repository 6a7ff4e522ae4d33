// The gpu/ module's Thrust code: the phases of Ch. 3 (DevicePhases) written once
// with Thrust primitives. It is compiled once per backend, by a file that defines
// PCL_TDA_GPU_BACKEND (the namespace of that copy) and chooses Thrust's device
// system: thrust_phases_omp.cpp (host compiler, OpenMP) and thrust_phases_cuda.cu
// (nvcc). Device code sees plain arrays only.

#include <thrust/binary_search.h>
#include <thrust/for_each.h>
#include <thrust/reduce.h>
#include <thrust/scan.h>
#include <thrust/scatter.h>

#include "device_arrays.h"
#include "device_edges.h"
#include "device_grid.h"
#include "device_phases.h"
#include "device_triangles.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

namespace pcl {
namespace tda {
namespace gpu {
namespace detail {
namespace PCL_TDA_GPU_BACKEND {

namespace {

/** Triangles per block of the fill pass at most (unless one edge has more): the
 * device buffer of a block takes 8 bytes per triangle. */
constexpr std::uint64_t TRIANGLES_PER_BLOCK = std::uint64_t (1) << 22;

/** \brief The phases on Thrust's device system of this copy. */
class ThrustPhases : public DevicePhases {
public:
  ThrustPhases (const std::vector<float>& xyz, double radius)
  : radius_ (radius)
  , n_ (static_cast<Index> (xyz.size() / 3))
  , xyz_ (xyz.begin(), xyz.end())
  , grid_ (buildDeviceGrid (xyz_, n_, radius))
  {}

  std::uint64_t
  numCandidatePairs () const override
  {
    const auto num_cells = static_cast<Index> (grid_.cell_size.size());
    const thrust::counting_iterator<Index> first (0);
    return thrust::transform_reduce (
               thrust::device,
               first,
               first + num_cells,
               TwiceCandidatePairs{raw (grid_.runs), raw (grid_.cell_size)},
               std::uint64_t (0),
               Plus()) /
           2;
  }

  DeviceEdgeCounts
  countEdges () override
  {
    // The counts, then their exclusive prefix sum in place: the edge offsets.
    forward_offsets_.assign (std::size_t (n_) + 1, 0);
    const thrust::counting_iterator<Index> first (0);
    thrust::for_each (thrust::device,
                      first,
                      first + n_,
                      CountLaterNeighbors{laterNeighbors(), raw (forward_offsets_)});
    DeviceEdgeCounts counts;
    counts.triangle_bound = thrust::transform_reduce (thrust::device,
                                                      forward_offsets_.begin(),
                                                      forward_offsets_.end(),
                                                      PairsOf(),
                                                      std::uint64_t (0),
                                                      Plus());
    thrust::exclusive_scan (thrust::device,
                            forward_offsets_.begin(),
                            forward_offsets_.end(),
                            forward_offsets_.begin());
    counts.edges = forward_offsets_.back();
    return counts;
  }

  void
  fillEdges () override
  {
    num_edges_ = static_cast<Index> (forward_offsets_.back());
    const std::size_t m = num_edges_;
    source_.resize (m);
    forward_vertex_.resize (m);
    value_bits_.resize (m);
    const thrust::counting_iterator<Index> first (0);
    thrust::for_each (thrust::device,
                      first,
                      first + n_,
                      FillLaterNeighbors{laterNeighbors(),
                                         raw (xyz_),
                                         raw (forward_offsets_),
                                         raw (source_),
                                         raw (forward_vertex_),
                                         raw (value_bits_)});
  }

  void
  sortEdges (const std::function<void (const EdgeBlock&)>& sink) override
  {
    // Stable by length over an edge list in (source, target) order: filtration order.
    const std::size_t m = value_bits_.size();
    order_.resize (m);
    thrust::sequence (thrust::device, order_.begin(), order_.end());
    thrust::stable_sort_by_key (
        thrust::device, value_bits_.begin(), value_bits_.end(), order_.begin());
    sorted_source_.resize (m);
    sorted_target_.resize (m);
    thrust::gather (thrust::device,
                    order_.begin(),
                    order_.end(),
                    source_.begin(),
                    sorted_source_.begin());
    thrust::gather (thrust::device,
                    order_.begin(),
                    order_.end(),
                    forward_vertex_.begin(),
                    sorted_target_.begin());
    std::vector<Index> sources, targets;
    std::vector<std::uint64_t> values;
    sink ({hostView (sorted_source_, 0, m, sources),
           hostView (sorted_target_, 0, m, targets),
           hostView (value_bits_, 0, m, values),
           0,
           m});
    release (value_bits_);
    release (sorted_source_);
    release (sorted_target_);
  }

  std::uint64_t
  countTriangles () override
  {
    buildAdjacency();
    // Counted by (source, target) position, then put in filtration order and
    // summed: the offsets of the triangles of every edge, and of every position.
    triangle_counts_.resize (num_edges_);
    const thrust::counting_iterator<Index> first (0);
    thrust::for_each (thrust::device,
                      first,
                      first + n_,
                      CountOlderTriangles{adjacency(), raw (triangle_counts_)});
    max_triangles_per_edge_ = thrust::reduce (thrust::device,
                                              triangle_counts_.begin(),
                                              triangle_counts_.end(),
                                              Index (0),
                                              Maximum());
    triangle_offsets_.assign (std::size_t (num_edges_) + 1, 0);
    thrust::gather (thrust::device,
                    order_.begin(),
                    order_.end(),
                    triangle_counts_.begin(),
                    triangle_offsets_.begin());
    release (order_);
    thrust::exclusive_scan (thrust::device,
                            triangle_offsets_.begin(),
                            triangle_offsets_.end(),
                            triangle_offsets_.begin());
    position_offsets_.resize (num_edges_);
    thrust::gather (thrust::device,
                    forward_edge_.begin(),
                    forward_edge_.end(),
                    triangle_offsets_.begin(),
                    position_offsets_.begin());
    release (forward_edge_);
    return triangle_offsets_.back();
  }

  void
  fillTriangles (const std::function<void (const TriangleBlock&)>& sink,
                 const ProgressCallback& progress) override
  {
    const std::uint64_t total = triangle_offsets_.back();
    if (total == 0)
      return;
    const std::uint64_t capacity = std::max<std::uint64_t> (
        max_triangles_per_edge_, std::min (total, TRIANGLES_PER_BLOCK));
    DeviceVector<std::uint64_t> middle_oldest (capacity);
    std::vector<std::uint64_t> offsets_host, middle_oldest_host;
    const thrust::counting_iterator<Index> first_vertex (0);
    for (Index first_edge = 0; first_edge < num_edges_;) {
      // The edges whose triangles fit in the block: at least one.
      const std::uint64_t first = triangle_offsets_[first_edge];
      const auto after = thrust::upper_bound (thrust::device,
                                              triangle_offsets_.begin() + first_edge,
                                              triangle_offsets_.end(),
                                              first + capacity);
      const auto last_edge = static_cast<Index> (after - triangle_offsets_.begin()) - 1;
      const std::uint64_t count = triangle_offsets_[last_edge] - first;
      thrust::for_each (thrust::device,
                        first_vertex,
                        first_vertex + n_,
                        FillOlderTriangles{adjacency(),
                                           raw (position_offsets_),
                                           raw (triangle_counts_),
                                           first_edge,
                                           last_edge,
                                           first,
                                           raw (middle_oldest)});
      sink (
          {hostView (
               triangle_offsets_, first_edge, last_edge - first_edge + 1, offsets_host),
           hostView (middle_oldest, 0, count, middle_oldest_host),
           first_edge,
           last_edge});
      first_edge = last_edge;
      if (progress)
        progress (first_edge, num_edges_);
    }
  }

private:
  LaterNeighbors
  laterNeighbors () const
  {
    return {raw (grid_.x),
            raw (grid_.y),
            raw (grid_.z),
            raw (grid_.vertex),
            raw (grid_.cell_of),
            raw (grid_.runs),
            radius_};
  }

  DeviceAdjacency
  adjacency () const
  {
    return {raw (adjacency_offsets_),
            raw (forward_begin_),
            raw (adjacency_),
            raw (forward_offsets_)};
  }

  /** The adjacency of the triangle passes: the forward lists (the edge list in
   * (source, target) order) with the edge id of every entry, and the backward lists,
   * their transpose by a stable sort on the target (which keeps the sources of a
   * target in increasing order), merged into one list per vertex. */
  void
  buildAdjacency ()
  {
    forward_edge_.resize (num_edges_);
    const thrust::counting_iterator<Index> first (0);
    thrust::scatter (thrust::device,
                     first,
                     first + num_edges_,
                     order_.begin(),
                     forward_edge_.begin());
    DeviceVector<Index> targets (forward_vertex_);
    DeviceVector<Index> backward_edge (forward_edge_);
    thrust::stable_sort_by_key (thrust::device,
                                targets.begin(),
                                targets.end(),
                                thrust::make_zip_iterator (thrust::make_tuple (
                                    source_.begin(), backward_edge.begin())));
    DeviceVector<std::uint64_t> backward_offsets (std::size_t (n_) + 1);
    thrust::lower_bound (thrust::device,
                         targets.begin(),
                         targets.end(),
                         first,
                         first + n_ + 1,
                         backward_offsets.begin());
    release (targets);

    adjacency_.resize (2 * std::size_t (num_edges_));
    thrust::for_each (thrust::device,
                      first,
                      first + n_,
                      FillAdjacency{raw (forward_offsets_),
                                    raw (forward_vertex_),
                                    raw (forward_edge_),
                                    raw (backward_offsets),
                                    raw (source_),
                                    raw (backward_edge),
                                    raw (adjacency_)});
    adjacency_offsets_.resize (std::size_t (n_) + 1);
    thrust::transform (thrust::device,
                       forward_offsets_.begin(),
                       forward_offsets_.end(),
                       backward_offsets.begin(),
                       adjacency_offsets_.begin(),
                       Plus());
    forward_begin_.resize (n_);
    thrust::transform (thrust::device,
                       forward_offsets_.begin(),
                       forward_offsets_.end() - 1,
                       backward_offsets.begin() + 1,
                       forward_begin_.begin(),
                       Plus());
    release (forward_vertex_);
    release (source_);
  }

  double radius_;
  Index n_;
  Index num_edges_ = 0;
  DeviceVector<float> xyz_; // the points in vertex order, interleaved
  DeviceGrid grid_;
  // Edges in (source, target) order, as the fill pass writes them.
  DeviceVector<std::uint64_t> forward_offsets_;
  DeviceVector<Index> forward_vertex_;
  DeviceVector<Index> source_;
  DeviceVector<std::uint64_t> value_bits_;
  // Edges in filtration order.
  DeviceVector<Index> order_; // the (source, target) position of each
  DeviceVector<Index> sorted_source_;
  DeviceVector<Index> sorted_target_;
  // The adjacency and the triangle counts and offsets of the triangle passes.
  DeviceVector<Index> forward_edge_; // the edge id at each (source, target) position
  DeviceVector<std::uint64_t> adjacency_offsets_;
  DeviceVector<std::uint64_t> forward_begin_;
  DeviceVector<std::uint64_t> adjacency_;
  DeviceVector<Index> triangle_counts_;          // per position
  DeviceVector<std::uint64_t> triangle_offsets_; // per edge, and the end
  DeviceVector<std::uint64_t> position_offsets_; // per position
  Index max_triangles_per_edge_ = 0;
};

} // namespace

std::unique_ptr<DevicePhases>
makeDevicePhases (const std::vector<float>& xyz, double radius)
{
  return std::make_unique<ThrustPhases> (xyz, radius);
}

} // namespace PCL_TDA_GPU_BACKEND
} // namespace detail
} // namespace gpu
} // namespace tda
} // namespace pcl
