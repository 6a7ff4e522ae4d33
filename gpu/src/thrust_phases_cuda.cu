// The gpu/ module's Thrust code on CUDA, compiled by nvcc from the same source as the
// OpenMP backend, and the search for a device.

#define PCL_TDA_GPU_BACKEND cuda_backend

#include "thrust_phases.inl"
#include <cuda_runtime_api.h>

namespace pcl {
namespace tda {
namespace gpu {
namespace detail {
namespace cuda_backend {

bool
findDevice (std::string& why)
{
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount (&count);
  if (status == cudaSuccess && count > 0)
    return true;
  why =
      status == cudaSuccess ? "no CUDA device is present" : cudaGetErrorString (status);
  return false;
}

} // namespace cuda_backend
} // namespace detail
} // namespace gpu
} // namespace tda
} // namespace pcl
