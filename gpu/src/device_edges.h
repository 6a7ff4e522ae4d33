#pragma once

// Part of the gpu/ module's Thrust code (thrust_phases.inl), compiled once per backend.

#include <pcl/tda/common/host_device.h>
#include <pcl/tda/common/point3d.h>

#include "device_grid.h"
#include "small_sort.h"

#include <cstdint>
#include <cstring>

namespace pcl {
namespace tda {
namespace gpu {
namespace detail {
namespace PCL_TDA_GPU_BACKEND {

/** \brief The bits of a double (for a non-negative one, in the same order). */
PCL_TDA_HOST_DEVICE inline std::uint64_t
doubleBits (double value)
{
  std::uint64_t bits;
  memcpy (&bits, &value, sizeof bits);
  return bits;
}

/** \brief The later neighbours of the point at a grid position (Alg 3.2): the
 * vertices w > v within the radius of its vertex v (withinRadius(), as the CPU
 * builder tests), found in the six runs of its cell. */
struct LaterNeighbors {
  const float* x; // the points in grid order
  const float* y;
  const float* z;
  const Index* vertex;
  const Index* cell_of;
  const Index* runs;
  double radius;

  PCL_TDA_HOST_DEVICE Point3d
  point (Index position) const
  {
    return {x[position], y[position], z[position]};
  }

  /** Calls \a visit(w) for every later neighbour w of the point at \a position. */
  template <typename Visit>
  PCL_TDA_HOST_DEVICE void
  forEach (Index position, Visit& visit) const
  {
    const Index v = vertex[position];
    const Point3d p = point (position);
    const Index* run =
        runs + static_cast<std::size_t> (cell_of[position]) * 2 * RUNS_PER_CELL;
    for (int r = 0; r < RUNS_PER_CELL; ++r)
      for (Index j = run[2 * r]; j < run[2 * r + 1]; ++j) {
        const Index w = vertex[j];
        if (w > v && withinRadius (p, point (j), radius))
          visit (w);
      }
  }
};

/** \brief Counts one neighbour. */
struct CountVisit {
  std::uint64_t count = 0;

  PCL_TDA_HOST_DEVICE void
  operator() (Index)
  {
    ++count;
  }
};

/** \brief Count pass of the edges: the number of later neighbours of every vertex. */
struct CountLaterNeighbors {
  LaterNeighbors neighbors;
  std::uint64_t* counts; // per vertex

  PCL_TDA_HOST_DEVICE void
  operator() (Index position) const
  {
    CountVisit visit;
    neighbors.forEach (position, visit);
    counts[neighbors.vertex[position]] = visit.count;
  }
};

/** \brief Pairs among k later neighbours, k (k - 1) / 2: the triangle bound. */
struct PairsOf {
  PCL_TDA_HOST_DEVICE std::uint64_t
  operator() (std::uint64_t k) const
  {
    return k * (k - 1) / 2;
  }
};

/** \brief Writes one neighbour at the next slot of a vertex's edges. */
struct WriteVisit {
  Index* out;

  PCL_TDA_HOST_DEVICE void
  operator() (Index w)
  {
    *out++ = w;
  }
};

/** \brief Fill pass of the edges (Alg 3.3): every vertex v writes its edges (v, w) at
 * its offset, w increasing, with their lengths (distance(), as bits). The edge list
 * is then sorted by (source, target). */
struct FillLaterNeighbors {
  LaterNeighbors neighbors;
  const float* xyz; // the points in vertex order, interleaved
  const std::uint64_t* offsets;
  Index* source;
  Index* target;
  std::uint64_t* value_bits;

  PCL_TDA_HOST_DEVICE void
  operator() (Index position) const
  {
    const Index v = neighbors.vertex[position];
    const std::uint64_t begin = offsets[v], end = offsets[v + 1];
    WriteVisit visit{target + begin};
    neighbors.forEach (position, visit);
    sortInPlace (target + begin, target + end);
    const Point3d p = neighbors.point (position);
    for (std::uint64_t k = begin; k < end; ++k) {
      const float* q = xyz + 3 * static_cast<std::size_t> (target[k]);
      source[k] = v;
      value_bits[k] = doubleBits (distance (p, Point3d{q[0], q[1], q[2]}));
    }
  }
};

} // namespace PCL_TDA_GPU_BACKEND
} // namespace detail
} // namespace gpu
} // namespace tda
} // namespace pcl
