#pragma once

// Part of the gpu/ module's Thrust code (thrust_phases.inl), compiled once per backend.

#include <pcl/tda/common/host_device.h>

#include <thrust/copy.h>
#include <thrust/execution_policy.h>
#include <thrust/for_each.h>
#include <thrust/gather.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/iterator/zip_iterator.h>
#include <thrust/scan.h>
#include <thrust/sequence.h>
#include <thrust/sort.h>
#include <thrust/transform.h>
#include <thrust/transform_reduce.h>
#include <thrust/tuple.h>

#include "device_arrays.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace pcl {
namespace tda {
namespace gpu {
namespace detail {
namespace PCL_TDA_GPU_BACKEND {

/** \brief Runs of candidate positions per cell: the columns (x + dx, y + dy,
 * z - 1 .. z + 1) of the cell's own layer (dx = 0, runs 0-2) and of the next layer
 * (dx = 1, runs 3-5), dy = -1, 0, 1; each column is consecutive in the grid order. */
constexpr int RUNS_PER_CELL = 6;

/** \brief The device mirror of UniformGrid: the same cells (cubes of side r, cell
 * coordinates floor((p - low) / r), clamped at 2^62), sorted by (x, y, z), the
 * points grouped by cell in vertex order. Since the vertices are in canonical order
 * (sorted by x first), the later vertices within r of a point lie in its own layer
 * of cells or in the next one: the six runs of its cell. */
struct DeviceGrid {
  DeviceVector<float> x, y, z;   // the points in grid order
  DeviceVector<Index> vertex;    // the vertex at each grid position
  DeviceVector<Index> cell_of;   // the cell of each grid position
  DeviceVector<Index> runs;      // per cell, RUNS_PER_CELL [begin, end) of positions
  DeviceVector<Index> cell_size; // the number of points of each cell
};

/** \brief Coordinate \a axis of every point (interleaved x, y, z). */
struct Coordinate {
  const float* xyz;
  int axis;

  PCL_TDA_HOST_DEVICE float
  operator() (Index vertex) const
  {
    return xyz[3 * static_cast<std::size_t> (vertex) + axis];
  }
};

/** \brief The cell coordinate along one axis, computed as UniformGrid does. */
struct CellCoordinate {
  const float* xyz;
  int axis;
  double low;
  double cell_size;

  PCL_TDA_HOST_DEVICE std::int64_t
  operator() (Index vertex) const
  {
    constexpr double LAST_CELL = 4611686018427387904.0; // 2^62
    const double cell =
        (static_cast<double> (xyz[3 * static_cast<std::size_t> (vertex) + axis]) -
         low) /
        cell_size;
    return static_cast<std::int64_t> (std::floor (LAST_CELL < cell ? LAST_CELL : cell));
  }
};

/** \brief Cell keys (x, y, z) sorted lexicographically, searched by binary search. */
struct CellKeys {
  const std::int64_t* x;
  const std::int64_t* y;
  const std::int64_t* z;
  Index size;

  /** Negative, 0 or positive as the key of \a cell is less than, equal to or greater
   * than (kx, ky, kz). */
  PCL_TDA_HOST_DEVICE int
  compare (Index cell, std::int64_t kx, std::int64_t ky, std::int64_t kz) const
  {
    if (x[cell] != kx)
      return x[cell] < kx ? -1 : 1;
    if (y[cell] != ky)
      return y[cell] < ky ? -1 : 1;
    return z[cell] < kz ? -1 : z[cell] == kz ? 0 : 1;
  }

  /** The first cell whose key is not less than (kx, ky, kz) or, with \a after,
   * greater than it; size when there is none. */
  PCL_TDA_HOST_DEVICE Index
  bound (std::int64_t kx, std::int64_t ky, std::int64_t kz, bool after) const
  {
    Index first = 0, count = size;
    while (count > 0) {
      const Index half = count / 2;
      const int order = compare (first + half, kx, ky, kz);
      if (order < 0 || (after && order == 0)) {
        first += half + 1;
        count -= half + 1;
      }
      else
        count = half;
    }
    return first;
  }
};

/** \brief True at the first grid position of every cell. */
struct IsCellStart {
  const std::int64_t* x;
  const std::int64_t* y;
  const std::int64_t* z;

  PCL_TDA_HOST_DEVICE bool
  operator() (Index position) const
  {
    return position == 0 || x[position] != x[position - 1] ||
           y[position] != y[position - 1] || z[position] != z[position - 1];
  }
};

/** \brief The runs of every cell (RUNS_PER_CELL [begin, end) pairs of positions) and
 * its size. */
struct CellRuns {
  CellKeys keys;
  const Index* cell_begin; // keys.size + 1 entries
  Index* runs;
  Index* cell_size;

  PCL_TDA_HOST_DEVICE void
  operator() (Index cell) const
  {
    const std::int64_t x = keys.x[cell], y = keys.y[cell], z = keys.z[cell];
    Index* out = runs + static_cast<std::size_t> (cell) * 2 * RUNS_PER_CELL;
    for (int dx = 0; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        *out++ = cell_begin[keys.bound (x + dx, y + dy, z - 1, false)];
        *out++ = cell_begin[keys.bound (x + dx, y + dy, z + 1, true)];
      }
    cell_size[cell] = cell_begin[cell + 1] - cell_begin[cell];
  }
};

/** \brief Twice the candidate pairs counted from a cell: with its own layer (each
 * pair seen from both cells, hence twice) and, twice, with the next layer. */
struct TwiceCandidatePairs {
  const Index* runs;
  const Index* cell_size;

  PCL_TDA_HOST_DEVICE std::uint64_t
  operator() (Index cell) const
  {
    const Index* run = runs + static_cast<std::size_t> (cell) * 2 * RUNS_PER_CELL;
    std::uint64_t own_layer = 0, next_layer = 0;
    for (int r = 0; r < RUNS_PER_CELL; ++r)
      (r < RUNS_PER_CELL / 2 ? own_layer : next_layer) += run[2 * r + 1] - run[2 * r];
    const std::uint64_t size = cell_size[cell];
    return size * (own_layer - 1) + 2 * size * next_layer;
  }
};

/** \brief The cell of a grid position from the inclusive scan of the cell starts. */
struct MinusOne {
  PCL_TDA_HOST_DEVICE Index
  operator() (Index value) const
  {
    return value - 1;
  }
};

/** \brief Builds the grid of cell size \a cell_size over the \a n points \a xyz
 * (interleaved, in canonical order). */
inline DeviceGrid
buildDeviceGrid (const DeviceVector<float>& xyz, Index n, double cell_size)
{
  DeviceGrid grid;
  const thrust::counting_iterator<Index> first (0), last (n);
  DeviceVector<std::int64_t> key[3];
  for (int axis = 0; axis < 3; ++axis) {
    const Coordinate coordinate{raw (xyz), axis};
    const double low = thrust::transform_reduce (thrust::device,
                                                 first,
                                                 last,
                                                 coordinate,
                                                 std::numeric_limits<float>::infinity(),
                                                 Minimum());
    key[axis].resize (n);
    thrust::transform (thrust::device,
                       first,
                       last,
                       key[axis].begin(),
                       CellCoordinate{raw (xyz), axis, low, cell_size});
  }
  grid.vertex.resize (n);
  thrust::sequence (thrust::device, grid.vertex.begin(), grid.vertex.end());
  const auto keys = thrust::make_zip_iterator (
      thrust::make_tuple (key[0].begin(), key[1].begin(), key[2].begin()));
  thrust::stable_sort_by_key (thrust::device, keys, keys + n, grid.vertex.begin());
  DeviceVector<float>* coordinates[3] = {&grid.x, &grid.y, &grid.z};
  for (int axis = 0; axis < 3; ++axis) {
    coordinates[axis]->resize (n);
    const Coordinate coordinate{raw (xyz), axis};
    thrust::transform (thrust::device,
                       grid.vertex.begin(),
                       grid.vertex.end(),
                       coordinates[axis]->begin(),
                       coordinate);
  }

  // Cells: their first positions, the cell of every position, their keys.
  const IsCellStart is_start{raw (key[0]), raw (key[1]), raw (key[2])};
  DeviceVector<Index> cell_begin (n + 1);
  const auto begin_end =
      thrust::copy_if (thrust::device, first, last, cell_begin.begin(), is_start);
  const auto num_cells = static_cast<Index> (begin_end - cell_begin.begin());
  cell_begin[num_cells] = n;
  grid.cell_of.resize (n);
  thrust::transform (thrust::device, first, last, grid.cell_of.begin(), is_start);
  thrust::inclusive_scan (
      thrust::device, grid.cell_of.begin(), grid.cell_of.end(), grid.cell_of.begin());
  thrust::transform (thrust::device,
                     grid.cell_of.begin(),
                     grid.cell_of.end(),
                     grid.cell_of.begin(),
                     MinusOne());
  DeviceVector<std::int64_t> cell_key[3];
  for (int axis = 0; axis < 3; ++axis) {
    cell_key[axis].resize (num_cells);
    thrust::gather (thrust::device,
                    cell_begin.begin(),
                    cell_begin.begin() + num_cells,
                    key[axis].begin(),
                    cell_key[axis].begin());
    release (key[axis]);
  }
  grid.runs.resize (static_cast<std::size_t> (num_cells) * 2 * RUNS_PER_CELL);
  grid.cell_size.resize (num_cells);
  thrust::for_each (
      thrust::device,
      first,
      first + num_cells,
      CellRuns{
          CellKeys{raw (cell_key[0]), raw (cell_key[1]), raw (cell_key[2]), num_cells},
          raw (cell_begin),
          raw (grid.runs),
          raw (grid.cell_size)});
  return grid;
}

} // namespace PCL_TDA_GPU_BACKEND
} // namespace detail
} // namespace gpu
} // namespace tda
} // namespace pcl
