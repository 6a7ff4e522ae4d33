#pragma once

#include <string>

namespace pcl {
namespace tda {
namespace gpu {

/** \brief Where the Thrust code of the gpu/ module runs: on a CUDA device, or on the
 * host's cores through Thrust's OpenMP system. The same source is compiled for both,
 * and both give the same complex. */
enum class DeviceBackend { OPENMP, CUDA };

/** \brief The name of \a backend for messages: "OpenMP" or "CUDA". */
std::string
backendName (DeviceBackend backend);

/** \brief True when this library was built with CUDA (CMake option
 * PCL_TDA_WITH_CUDA); it then runs on a CUDA device when there is one. */
bool
builtWithCUDA ();

/** \brief The backend the builds of this process run on: CUDA when the library was
 * built with it and a CUDA device is present, OpenMP otherwise.
 * \param[out] why empty, or why a library built with CUDA falls back to OpenMP (the
 * CUDA runtime's reason, e.g. no device or no driver) */
DeviceBackend
selectBackend (std::string& why);

} // namespace gpu
} // namespace tda
} // namespace pcl
