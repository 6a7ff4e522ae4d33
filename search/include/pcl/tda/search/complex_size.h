#pragma once

#include <pcl/tda/common/point3d.h>
#include <pcl/tda/search/radius_edges.h>
#include <pcl/tda/search/uniform_grid.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Sizes of the Vietoris-Rips complex VR_r of a point set, or of its radius
 * graph, before it is built. */
struct ComplexSize {
  double edges = 0.0;
  double triangles = 0.0;
  /** True when no sampling was needed: the numbers are the exact counts. */
  bool exact = true;
};

/** \brief Estimates the numbers of edges and triangles of VR_r (edges: pairs within
 * \a radius that pass \a accept) from a deterministic sample, in time bounded
 * whatever the size of the complex: at most \a max_points points (every k-th in
 * the grid's order), at most \a max_candidates later candidates of each (every
 * j-th), and at most \a max_pairs pairs of its later neighbours (drawn with a
 * generator seeded by the point), each scaled up by its sampling ratio.
 *
 * Triangles are counted from their first vertex in the grid's order: the other two
 * are later neighbours of it (thesis Alg 3.4's ownership, by vertex instead of by
 * edge). The memory guards refuse on these numbers only when they are far over the
 * limit, and count exactly otherwise.
 * \param[in] grid a grid of cell size >= \a radius over \a points */
template <typename Accept>
ComplexSize
estimateComplexSize (const UniformGrid& grid,
                     const std::vector<Point3d>& points,
                     double radius,
                     const Accept& accept,
                     unsigned int threads,
                     std::size_t max_points = 4096,
                     std::size_t max_candidates = 4096,
                     std::size_t max_pairs = 4096)
{
  const std::size_t n = points.size();
  const std::size_t point_stride =
      std::max<std::size_t> (1, (n + max_points - 1) / max_points);
  const auto num_samples =
      static_cast<std::int64_t> ((n + point_stride - 1) / point_stride);
  // Per sample, summed in order afterwards: the same numbers for any thread count.
  std::vector<ComplexSize> samples (num_samples);
#pragma omp parallel for schedule(dynamic, 16) num_threads(resolveThreads(threads))
  for (std::int64_t s = 0; s < num_samples; ++s) {
    const auto position = static_cast<std::uint32_t> (s * point_stride);
    std::size_t cell = 0, last = grid.numCells();
    while (last - cell > 1) { // the cell holding the position
      const std::size_t middle = (cell + last) / 2;
      (grid.cellBegin (middle) <= position ? cell : last) = middle;
    }
    const std::uint32_t a = grid.pointAt (position);
    const UniformGrid::Runs runs = grid.laterCandidates (cell, position);
    std::size_t num_candidates = 0;
    for (const auto& [begin, end] : runs)
      num_candidates += end > begin ? end - begin : 0;
    const std::size_t candidate_stride = std::max<std::size_t> (
        1, (num_candidates + max_candidates - 1) / max_candidates);
    std::vector<std::uint32_t> neighbors;
    std::size_t k = 0;
    for (const auto& [begin, end] : runs)
      for (std::uint32_t j = begin; j < end; ++j, ++k)
        if (k % candidate_stride == 0) {
          const std::uint32_t b = grid.pointAt (j);
          if (withinRadius (points[a], points[b], radius) && accept (a, b))
            neighbors.push_back (b);
        }
    const double f = static_cast<double> (neighbors.size());
    ComplexSize& sample = samples[s];
    sample.edges = f * candidate_stride * point_stride;

    // Pairs of later neighbours within the radius: the triangles a comes first in.
    const double all_pairs = f * (f - 1.0) / 2.0;
    double within = 0.0, tested = 0.0;
    if (all_pairs <= static_cast<double> (max_pairs)) {
      for (std::size_t i = 0; i < neighbors.size(); ++i)
        for (std::size_t j = i + 1; j < neighbors.size(); ++j)
          within += withinRadius (points[neighbors[i]], points[neighbors[j]], radius) &&
                    accept (neighbors[i], neighbors[j]);
      tested = all_pairs;
    }
    else {
      std::mt19937 random (position);
      std::uniform_int_distribution<std::size_t> pick (0, neighbors.size() - 1);
      while (tested < static_cast<double> (max_pairs)) {
        const std::size_t i = pick (random), j = pick (random);
        if (i == j)
          continue;
        within += withinRadius (points[neighbors[i]], points[neighbors[j]], radius) &&
                  accept (neighbors[i], neighbors[j]);
        tested += 1.0;
      }
      sample.exact = false;
    }
    if (tested > 0.0) {
      const double true_neighbors = f * candidate_stride;
      sample.triangles = within / tested * true_neighbors * (true_neighbors - 1.0) /
                         2.0 * point_stride;
    }
    sample.exact = sample.exact && candidate_stride == 1;
  }
  ComplexSize total;
  total.exact = point_stride == 1;
  for (const ComplexSize& sample : samples) {
    total.edges += sample.edges;
    total.triangles += sample.triangles;
    total.exact = total.exact && sample.exact;
  }
  return total;
}

/** \brief What a complex may cost: a memory limit and the bytes per simplex that
 * a builder needs at its peak. */
struct MemoryBudget {
  std::size_t limit = 0;
  std::size_t bytes_per_edge = 0;
  std::size_t bytes_per_triangle = 0;

  double
  bytes (double edges, double triangles) const
  {
    return edges * static_cast<double> (bytes_per_edge) +
           triangles * static_cast<double> (bytes_per_triangle);
  }

  bool
  fits (double edges, double triangles) const
  {
    return bytes (edges, triangles) <= static_cast<double> (limit);
  }
};

/** \brief What the count pass of a radius graph's edges tells the memory guard: the
 * exact number of edges and an upper bound on the triangles of its clique complex. */
struct EdgeCountSummary {
  std::uint64_t edges = 0;
  std::uint64_t triangle_bound = 0;
};

/** \brief The memory guard around the count pass of a radius graph's edges: refuses
 * in bounded time a complex far over \a budget, and counts exactly otherwise. Cheap
 * bounds first: \a candidate_pairs bounds the edges and the count pass bounds the
 * triangles; only when a bound is over the limit is the complex estimated
 * (\a estimate, e.g. estimateComplexSize()), and refused when the estimate is over
 * twice the limit. Then the exact edge count decides. The CPU builder runs it around
 * countRadiusEdges(), the gpu/ mirror around its device count pass.
 * \param[in] count_edges the count pass: returns an EdgeCountSummary
 * \param[in] estimate returns the ComplexSize estimated from a sample
 * \param[out] size the sizes that decided: the exact edge count with the triangle
 * bound (or the estimate, when it was needed); the estimate or exact count that is
 * over the budget on refusal
 * \return false when the complex is over the budget */
template <typename CountEdges, typename Estimate>
bool
countEdgesWithinBudget (const MemoryBudget& budget,
                        std::uint64_t candidate_pairs,
                        const CountEdges& count_edges,
                        const Estimate& estimate,
                        ComplexSize& size)
{
  const auto far_over = [&budget] (double edges, double triangles) {
    return budget.bytes (edges, triangles) > 2.0 * static_cast<double> (budget.limit);
  };
  if (!budget.fits (static_cast<double> (candidate_pairs), 0.0)) {
    size = estimate();
    if (far_over (size.edges, size.triangles))
      return false;
  }
  const EdgeCountSummary counts = count_edges();
  const auto edges = static_cast<double> (counts.edges);
  size = {edges, static_cast<double> (counts.triangle_bound), false};
  if (!budget.fits (edges, 0.0)) {
    size.exact = true;
    size.triangles = 0.0;
    return false;
  }
  if (!budget.fits (edges, size.triangles)) {
    const ComplexSize estimated = estimate();
    size.triangles = estimated.triangles;
    size.exact = false;
    if (far_over (edges, size.triangles))
      return false;
  }
  return true;
}

/** \brief The count pass of the radius edges (countRadiusEdges()) behind the
 * memory guard countEdgesWithinBudget(), with the grid's candidate pairs as the
 * bound on the edges and estimateComplexSize() as the estimate.
 * \param[out] counts the count pass, when it ran (it tells \a progress, when set, the
 * points done)
 * \param[out] size as countEdgesWithinBudget()
 * \return false when the complex is over the budget */
template <typename Accept>
bool
countRadiusEdgesWithinBudget (const UniformGrid& grid,
                              const std::vector<Point3d>& points,
                              double radius,
                              const Accept& accept,
                              unsigned int threads,
                              const MemoryBudget& budget,
                              RadiusEdgeCounts& counts,
                              ComplexSize& size,
                              const ProgressCallback& progress = {})
{
  const auto count_edges = [&] () {
    counts = countRadiusEdges (grid, points, radius, accept, threads, progress);
    return EdgeCountSummary{counts.offsets.back(), counts.triangle_bound};
  };
  const auto estimate = [&] () {
    return estimateComplexSize (grid, points, radius, accept, threads);
  };
  return countEdgesWithinBudget (
      budget, grid.numCandidatePairs(), count_edges, estimate, size);
}

} // namespace tda
} // namespace pcl
