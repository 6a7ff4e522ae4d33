// The page faults of writing a new block: how the tests of the tools' malloc
// settings tell 4 KiB pages, huge pages and reused memory apart.

#pragma once

#include <sys/resource.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace pcl {
namespace tda {
namespace test {

/** The minor page faults of this process so far. */
inline long
pageFaults ()
{
  rusage usage;
  getrusage (RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

/** The block of faultsOfNewBlock(): through a volatile pointer, so that the compiler
 * keeps the writes to it. */
inline void* volatile new_block = nullptr;

/** The page faults of this process while it writes a new block of \a bytes, which it
 * frees after. */
inline long
faultsOfNewBlock (std::size_t bytes)
{
  const long before = pageFaults();
  new_block = std::malloc (bytes);
  std::memset (new_block, 1, bytes);
  const long faults = pageFaults() - before;
  std::free (new_block);
  return faults;
}

} // namespace test
} // namespace tda
} // namespace pcl
