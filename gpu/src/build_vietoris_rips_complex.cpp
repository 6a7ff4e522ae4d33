#include <pcl/common/time.h>
#include <pcl/console/print.h>
#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/gpu/vietoris_rips_builder.h>
#include <pcl/tda/search/complex_size.h>
#include <pcl/tda/search/radius_edges.h>
#include <pcl/tda/search/uniform_grid.h>
#include <pcl/tda/search/vietoris_rips_checks.h>

#include "device_phases.h"
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <memory>

namespace pcl {
namespace tda {
namespace gpu {

namespace {

/** Sets OpenMP's thread count of this thread for its lifetime (0: leaves it), and
 * puts the previous one back: the OpenMP backend and the host loops follow it, and
 * the caller's setting is unchanged afterwards. */
class ScopedOpenMPThreads {
public:
  explicit ScopedOpenMPThreads (unsigned int threads)
  : previous_ (omp_get_max_threads())
  {
    if (threads > 0)
      omp_set_num_threads (static_cast<int> (threads));
  }

  ~ScopedOpenMPThreads() { omp_set_num_threads (previous_); }

  ScopedOpenMPThreads (const ScopedOpenMPThreads&) = delete;
  ScopedOpenMPThreads&
  operator= (const ScopedOpenMPThreads&) = delete;

private:
  int previous_;
};

/** The phases on \a backend (on OpenMP when the library has no CUDA build). */
std::unique_ptr<detail::DevicePhases>
makeDevicePhases ([[maybe_unused]] DeviceBackend backend,
                  const std::vector<float>& xyz,
                  double radius)
{
#ifdef PCL_TDA_GPU_WITH_CUDA
  if (backend == DeviceBackend::CUDA)
    return detail::cuda_backend::makeDevicePhases (xyz, radius);
#endif
  return detail::omp_backend::makeDevicePhases (xyz, radius);
}

/** The CPU builder's sampled estimate of the complex (estimateComplexSize() on a
 * UniformGrid), for the memory guard: made on the host, and only when a bound is
 * over the limit, so that a refusal names the same numbers as the CPU builder's. */
class SampledEstimate {
public:
  SampledEstimate (const std::vector<float>& xyz, double radius, unsigned int threads)
  : xyz_ (xyz), radius_ (radius), threads_ (threads)
  {}

  ComplexSize
  operator()()
  {
    if (!grid_) {
      points_.resize (xyz_.size() / 3);
      for (std::size_t v = 0; v < points_.size(); ++v)
        points_[v] = {xyz_[3 * v], xyz_[3 * v + 1], xyz_[3 * v + 2]};
      grid_ = std::make_unique<UniformGrid> (points_, radius_, threads_);
    }
    return estimateComplexSize (*grid_, points_, radius_, AcceptAllPairs{}, threads_);
  }

private:
  const std::vector<float>& xyz_;
  double radius_;
  unsigned int threads_;
  std::vector<Point3d> points_;
  std::unique_ptr<UniformGrid> grid_;
};

double
bitsToDouble (std::uint64_t bits)
{
  double value;
  std::memcpy (&value, &bits, sizeof value);
  return value;
}

} // namespace

bool
buildVietorisRipsComplex (const std::vector<float>& xyz,
                          const DeviceBuildSettings& settings,
                          DeviceBackend backend,
                          std::vector<FilteredEdge>& edges,
                          std::vector<FilteredTriangle>& triangles,
                          VietorisRipsTimings& timings)
{
  edges.clear();
  triangles.clear();
  timings = {};
  const char* name = settings.class_name.c_str();
  const std::size_t n = xyz.size() / 3;
  if (n >= INVALID_SIMPLEX) {
    PCL_ERROR ("[pcl::tda::%s::compute] The input has %zu finite points; 32-bit "
               "vertex ids allow fewer than 2^32 - 1.\n",
               name,
               n);
    return false;
  }
  const double radius = settings.radius;
  const int dimension = settings.max_dimension;
  const int limited = std::max (dimension, settings.limited_dimension);
  const MemoryBudget budget = vietorisRipsMemoryBudget (settings.memory_limit, limited);
  // The caller's callback may throw to cancel the build: that is no failure of the
  // backend, and its exception reaches the caller.
  std::exception_ptr cancelled;
  const VietorisRipsProgress progress (
      settings.progress ? ProgressCallback ([&] (std::size_t done, std::size_t total) {
        try {
          settings.progress (done, total);
        }
        catch (...) {
          cancelled = std::current_exception();
          throw;
        }
      })
                        : ProgressCallback(),
      dimension);
  const ScopedOpenMPThreads threads (settings.threads);
  try {
    pcl::StopWatch watch;
    const std::unique_ptr<detail::DevicePhases> phases =
        makeDevicePhases (backend, xyz, radius);

    // Phase 1: the edges, counted behind the CPU builder's memory guard.
    SampledEstimate estimate (xyz, radius, settings.threads);
    const auto count_edges = [&phases] () {
      const detail::DeviceEdgeCounts counts = phases->countEdges();
      return EdgeCountSummary{counts.edges, counts.triangle_bound};
    };
    ComplexSize size;
    if (!countEdgesWithinBudget (
            budget,
            phases->numCandidatePairs(),
            count_edges,
            [&estimate] () { return estimate(); },
            size)) {
      complexFitsMemory (settings.class_name, radius, limited, budget, size);
      return false;
    }
    // The edges fit the budget; this refuses more than 2^32 - 2 of them only.
    if (!complexFitsMemory (
            settings.class_name, radius, dimension, budget, {size.edges, 0.0, true}))
      return false;
    progress.reach (VietorisRipsProgress::EDGES_COUNTED);
    phases->fillEdges();
    progress.reach (VietorisRipsProgress::EDGES_LISTED);
    timings.neighbor_search = watch.getTimeSeconds();
    watch.reset();

    edges = largeVector<FilteredEdge> (static_cast<std::size_t> (size.edges));
    phases->sortEdges ([&edges] (const detail::EdgeBlock& block) {
      const auto count = static_cast<std::int64_t> (block.count);
#pragma omp parallel for schedule(static)
      for (std::int64_t i = 0; i < count; ++i)
        edges[block.first + i] = {
            block.source[i], block.target[i], bitsToDouble (block.value_bits[i])};
    });
    progress.reach (VietorisRipsProgress::EDGES_SORTED);
    timings.edges = watch.getTimeSeconds();
    watch.reset();

    // Phase 2: the triangles, counted before they are listed.
    if (dimension == 2) {
      const std::uint64_t num_triangles = phases->countTriangles();
      if (!complexFitsMemory (settings.class_name,
                              radius,
                              dimension,
                              budget,
                              {static_cast<double> (edges.size()),
                               static_cast<double> (num_triangles),
                               true})) {
        edges.clear();
        return false;
      }
      progress.reach (VietorisRipsProgress::TRIANGLES_COUNTED);
      triangles = largeVector<FilteredTriangle> (num_triangles);
      phases->fillTriangles (
          [&edges, &triangles] (const detail::TriangleBlock& block) {
            const auto num_edges =
                static_cast<std::int64_t> (block.last_edge - block.first_edge);
#pragma omp parallel for schedule(static)
            for (std::int64_t i = 0; i < num_edges; ++i) {
              const auto youngest = static_cast<SimplexIndex> (block.first_edge + i);
              for (std::uint64_t t = block.offsets[i]; t < block.offsets[i + 1]; ++t) {
                const std::uint64_t older = block.middle_oldest[t - block.offsets[0]];
                triangles[t] = {{youngest,
                                 static_cast<SimplexIndex> (older >> 32),
                                 static_cast<SimplexIndex> (older)},
                                edges[youngest].value};
              }
            }
          },
          progress.between (VietorisRipsProgress::TRIANGLES_COUNTED,
                            VietorisRipsProgress::DONE));
    }
    progress.reach (VietorisRipsProgress::DONE);
    timings.triangles = watch.getTimeSeconds();
  }
  catch (const std::exception& error) {
    if (cancelled) {
      edges.clear();
      triangles.clear();
      std::rethrow_exception (cancelled);
    }
    PCL_ERROR ("[pcl::tda::%s::compute] The %s backend failed: %s\n",
               name,
               backendName (backend).c_str(),
               error.what());
    edges.clear();
    triangles.clear();
    return false;
  }
  return true;
}

} // namespace gpu
} // namespace tda
} // namespace pcl
