#pragma once

#include <cstddef>

namespace pcl {
namespace tda {

/** \brief The physical memory of this machine in bytes (0 when unknown): the base of
 * the default memory limits of the complex builders. */
std::size_t
physicalMemoryBytes ();

} // namespace tda
} // namespace pcl
