#pragma once

// Part of the gpu/ module's Thrust code (thrust_phases.inl), compiled once per backend.

#include <pcl/tda/common/host_device.h>

#include <cstddef>

namespace pcl {
namespace tda {
namespace gpu {
namespace detail {
namespace PCL_TDA_GPU_BACKEND {

/** \brief Moves the largest of the heap [first, first + size) rooted at \a root down
 * to its place. */
template <typename T>
PCL_TDA_HOST_DEVICE inline void
siftDown (T* first, std::size_t root, std::size_t size)
{
  for (std::size_t child = 2 * root + 1; child < size; child = 2 * root + 1) {
    if (child + 1 < size && first[child] < first[child + 1])
      ++child;
    if (!(first[root] < first[child]))
      return;
    const T moved = first[root];
    first[root] = first[child];
    first[child] = moved;
    root = child;
  }
}

/** \brief Sorts [first, last) in increasing order within one thread, without extra
 * memory: the fill passes sort each vertex's neighbours and each edge's triangles
 * this way, on the host and in a GPU thread alike. Insertion sort for short ranges
 * (the usual case), heapsort beyond, so that a dense spot costs O(k log k). */
template <typename T>
PCL_TDA_HOST_DEVICE inline void
sortInPlace (T* first, T* last)
{
  const auto size = static_cast<std::size_t> (last - first);
  constexpr std::size_t INSERTION_SORT_SIZE = 24;
  if (size <= INSERTION_SORT_SIZE) {
    for (std::size_t i = 1; i < size; ++i) {
      const T moved = first[i];
      std::size_t j = i;
      for (; j > 0 && moved < first[j - 1]; --j)
        first[j] = first[j - 1];
      first[j] = moved;
    }
    return;
  }
  for (std::size_t root = size / 2; root-- > 0;)
    siftDown (first, root, size);
  for (std::size_t end = size; end-- > 1;) {
    const T largest = first[0];
    first[0] = first[end];
    first[end] = largest;
    siftDown (first, 0, end);
  }
}

} // namespace PCL_TDA_GPU_BACKEND
} // namespace detail
} // namespace gpu
} // namespace tda
} // namespace pcl
