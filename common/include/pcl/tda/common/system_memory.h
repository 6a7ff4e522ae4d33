#pragma once

#include <cstddef>
#include <string>

namespace pcl {
namespace tda {

/** \brief The physical memory of this machine in bytes (0 when unknown). */
std::size_t
physicalMemoryBytes ();

/** \brief The memory this process may use in bytes: the least of the physical
 * memory, the process's address-space limit (`ulimit -v`) and its control group's
 * memory limit (a container's); 0 when none of them can be read. The base of the
 * default memory limits of the complex builders. */
std::size_t
usableMemoryBytes ();

/** \brief The default memory limit of the complex builders: half of the usable
 * memory (usableMemoryBytes()), or no limit (the largest size) where it cannot be
 * read. */
std::size_t
defaultMemoryLimit ();

/** \brief A size in bytes as people read it: "512 KiB", "37.5 MiB", "4.2 GiB". */
std::string
formatBytes (double bytes);

} // namespace tda
} // namespace pcl
