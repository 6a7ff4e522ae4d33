#pragma once

#include <cstddef>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Asks the kernel to back the memory [\a data, \a data + \a bytes) with
 * transparent huge pages (2 MiB) when it is first touched, where the system allows it
 * (Linux with transparent huge pages in "madvise" or "always" mode); does nothing
 * elsewhere or for blocks under 4 MiB.
 *
 * The complex and the persistence arrays are written once, soon after they are
 * allocated: with 4 KiB pages, a 100k-point complex takes tens of thousands of page
 * faults, a third of the time of a first build in a new process. */
void
adviseHugePages (const void* data, std::size_t bytes);

/** \brief \a size copies of \a value, in storage given to adviseHugePages() before it
 * is written: for the large arrays of the builders and the engines. */
template <typename T>
std::vector<T>
largeVector (std::size_t size, const T& value = T())
{
  std::vector<T> vector;
  vector.reserve (size);
  adviseHugePages (vector.data(), size * sizeof (T));
  vector.assign (size, value);
  return vector;
}

} // namespace tda
} // namespace pcl
