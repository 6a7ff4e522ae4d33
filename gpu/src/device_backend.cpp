#include <pcl/tda/gpu/device_backend.h>

#include "device_phases.h"

namespace pcl {
namespace tda {
namespace gpu {

std::string
backendName (DeviceBackend backend)
{
  return backend == DeviceBackend::CUDA ? "CUDA" : "OpenMP";
}

bool
builtWithCUDA ()
{
#ifdef PCL_TDA_GPU_WITH_CUDA
  return true;
#else
  return false;
#endif
}

DeviceBackend
selectBackend (std::string& why)
{
  why.clear();
#ifdef PCL_TDA_GPU_WITH_CUDA
  if (detail::cuda_backend::findDevice (why))
    return DeviceBackend::CUDA;
#endif
  return DeviceBackend::OPENMP;
}

} // namespace gpu
} // namespace tda
} // namespace pcl
