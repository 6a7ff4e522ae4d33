#pragma once

// Part of the gpu/ module's Thrust code (thrust_phases.inl), compiled once per backend:
// the device arrays of the phases, their host views and the reductions over them.

#include <pcl/tda/common/host_device.h>
#include <pcl/tda/common/large_vector.h>

#include <thrust/copy.h>
#include <thrust/device_malloc_allocator.h>
#include <thrust/device_vector.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace pcl {
namespace tda {
namespace gpu {
namespace detail {
namespace PCL_TDA_GPU_BACKEND {

/** \brief A vertex id, grid position, cell or edge id: 32 bits, as the complex's. */
using Index = std::uint32_t;

#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_CUDA
template <typename T>
using DeviceVector = thrust::device_vector<T>;
#else
/** \brief The allocator of a host system's device memory, which is host memory:
 * large blocks go to adviseHugePages() before they are first touched (a fresh block
 * costs a page fault per 4 KiB page otherwise, as much as a phase on a virtual
 * machine). */
template <typename T>
class HugePageAllocator : public thrust::device_malloc_allocator<T> {
public:
  using Base = thrust::device_malloc_allocator<T>;

  template <typename U>
  struct rebind {
    using other = HugePageAllocator<U>;
  };

  HugePageAllocator() = default;

  template <typename U>
  HugePageAllocator (const HugePageAllocator<U>&)
  {}

  typename Base::pointer
  allocate (typename Base::size_type count)
  {
    T* block = std::allocator<T>().allocate (count);
    adviseHugePages (block, count * sizeof (T));
    return thrust::device_pointer_cast (block);
  }

  void
  deallocate (typename Base::pointer block, typename Base::size_type count)
  {
    std::allocator<T>().deallocate (thrust::raw_pointer_cast (block), count);
  }
};

template <typename T>
using DeviceVector = thrust::device_vector<T, HugePageAllocator<T>>;
#endif

template <typename T>
T*
raw (DeviceVector<T>& vector)
{
  return thrust::raw_pointer_cast (vector.data());
}

template <typename T>
const T*
raw (const DeviceVector<T>& vector)
{
  return thrust::raw_pointer_cast (vector.data());
}

/** \brief Frees the memory of \a vector. */
template <typename T>
void
release (DeviceVector<T>& vector)
{
  DeviceVector<T>().swap (vector);
}

/** \brief Elements [first, first + count) of \a vector in host memory: the device
 * memory itself on a host system, else a copy in \a staging. */
template <typename T>
const T*
hostView (const DeviceVector<T>& vector,
          std::size_t first,
          [[maybe_unused]] std::size_t count,
          [[maybe_unused]] std::vector<T>& staging)
{
#if THRUST_DEVICE_SYSTEM == THRUST_DEVICE_SYSTEM_CUDA
  staging.resize (count);
  thrust::copy (
      vector.begin() + first, vector.begin() + first + count, staging.begin());
  return staging.data();
#else
  return raw (vector) + first;
#endif
}

/** \brief The smaller of two coordinates: the grid's origin. */
struct Minimum {
  PCL_TDA_HOST_DEVICE float
  operator() (float a, float b) const
  {
    return b < a ? b : a;
  }
};

/** \brief The larger of two counts: the most triangles of one edge. */
struct Maximum {
  PCL_TDA_HOST_DEVICE Index
  operator() (Index a, Index b) const
  {
    return a < b ? b : a;
  }
};

/** \brief The sum of two counts or offsets. */
struct Plus {
  PCL_TDA_HOST_DEVICE std::uint64_t
  operator() (std::uint64_t a, std::uint64_t b) const
  {
    return a + b;
  }
};

} // namespace PCL_TDA_GPU_BACKEND
} // namespace detail
} // namespace gpu
} // namespace tda
} // namespace pcl
