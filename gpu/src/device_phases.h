#pragma once

// The boundary between the host code of the gpu/ module (compiled by the host
// compiler, with PCL) and its Thrust code (compiled once per backend: by the host
// compiler on Thrust's OpenMP system, and by nvcc on CUDA). Only plain types cross
// it: float coordinates in, 32-bit ids and 64-bit words out.

#include <pcl/tda/common/progress.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace pcl {
namespace tda {
namespace gpu {
namespace detail {

/** \brief What the edge count pass finds: the number of edges, and the sum over the
 * vertices of (later neighbours choose 2), an upper bound on the triangles. */
struct DeviceEdgeCounts {
  std::uint64_t edges = 0;
  std::uint64_t triangle_bound = 0;
};

/** \brief Edges [first, first + count) of the sorted edge list, in host memory:
 * their ends (source < target) and the bits of their lengths (IEEE doubles). */
struct EdgeBlock {
  const std::uint32_t* source;
  const std::uint32_t* target;
  const std::uint64_t* value_bits;
  std::size_t first;
  std::size_t count;
};

/** \brief The triangles of the edges [first_edge, last_edge) of the sorted edge list,
 * in host memory: those of edge e are triangles offsets[e - first_edge] to
 * offsets[e - first_edge + 1] of the triangle list, whose youngest edge is e; the
 * two other edges of triangle t are middle_oldest[t - offsets[0]], as
 * (middle << 32 | oldest). */
struct TriangleBlock {
  const std::uint64_t* offsets; // last_edge - first_edge + 1 entries
  const std::uint64_t* middle_oldest;
  std::size_t first_edge;
  std::size_t last_edge;
};

/** \brief The phases of Ch. 3 on a device, in the order a build calls them, on the
 * points given to the factory (vertex v at x, y, z = xyz[3v], xyz[3v + 1],
 * xyz[3v + 2], in canonical order) and the radius r. The grid is built by the
 * factory; the count passes give exact sizes before the fill passes allocate.
 * \throws std::bad_alloc, thrust::system_error when the device runs out of memory */
class DevicePhases {
public:
  virtual ~DevicePhases() = default;

  /** \brief The pairs of points in the same or neighbouring cells of the grid of cell
   * size r: UniformGrid::numCandidatePairs() of the same points. */
  virtual std::uint64_t
  numCandidatePairs () const = 0;

  /** \brief Count pass of the edges (Alg 3.2): every vertex's later neighbours
   * within r. */
  virtual DeviceEdgeCounts
  countEdges () = 0;

  /** \brief Fill pass of the edges (Alg 3.3), each vertex's in increasing target
   * order. */
  virtual void
  fillEdges () = 0;

  /** \brief Sorts the edges into filtration order (by length, then source, target)
   * and hands them to \a sink, in one block or several. */
  virtual void
  sortEdges (const std::function<void (const EdgeBlock&)>& sink) = 0;

  /** \brief Count pass of the triangles (Alg 3.4): the triangles of every edge whose
   * youngest edge it is. \return the number of triangles */
  virtual std::uint64_t
  countTriangles () = 0;

  /** \brief Fill pass of the triangles (Alg 3.5), in filtration order, block by block
   * to \a sink, telling \a progress (when set) the edges done. */
  virtual void
  fillTriangles (const std::function<void (const TriangleBlock&)>& sink,
                 const ProgressCallback& progress) = 0;
};

namespace omp_backend {
/** \brief The phases on Thrust's OpenMP system, with OpenMP's current number of
 * threads. */
std::unique_ptr<DevicePhases>
makeDevicePhases (const std::vector<float>& xyz, double radius);
} // namespace omp_backend

namespace cuda_backend {
/** \brief The phases on the current CUDA device (built with CUDA only). */
std::unique_ptr<DevicePhases>
makeDevicePhases (const std::vector<float>& xyz, double radius);

/** \brief True when a CUDA device can run the phases; otherwise false, with \a why
 * set to the CUDA runtime's reason (built with CUDA only). */
bool
findDevice (std::string& why);
} // namespace cuda_backend

} // namespace detail
} // namespace gpu
} // namespace tda
} // namespace pcl
