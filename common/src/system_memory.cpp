#include <pcl/tda/common/system_memory.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>

namespace pcl {
namespace tda {

std::size_t
physicalMemoryBytes ()
{
  const long pages = ::sysconf (_SC_PHYS_PAGES);
  const long page_size = ::sysconf (_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0)
    return 0;
  return static_cast<std::size_t> (pages) * static_cast<std::size_t> (page_size);
}

namespace {

/** The number in the file \a path (a control group's limit), 0 when there is none
 * (no such file, or "max": no limit). */
std::size_t
limitInFile (const char* path)
{
  std::ifstream file (path);
  unsigned long long bytes = 0;
  return file >> bytes ? static_cast<std::size_t> (bytes) : 0;
}

} // namespace

std::size_t
usableMemoryBytes ()
{
  std::size_t usable = physicalMemoryBytes();
  const auto bound = [&usable] (std::size_t limit) {
    if (limit > 0)
      usable = usable > 0 ? std::min (usable, limit) : limit;
  };
  rlimit address_space{};
  if (::getrlimit (RLIMIT_AS, &address_space) == 0 &&
      address_space.rlim_cur != RLIM_INFINITY)
    bound (static_cast<std::size_t> (address_space.rlim_cur));
  bound (limitInFile ("/sys/fs/cgroup/memory.max"));                   // cgroup v2
  bound (limitInFile ("/sys/fs/cgroup/memory/memory.limit_in_bytes")); // cgroup v1
  return usable;
}

std::size_t
defaultMemoryLimit ()
{
  const std::size_t usable = usableMemoryBytes();
  return usable > 0 ? usable / 2 : std::numeric_limits<std::size_t>::max();
}

std::string
formatBytes (double bytes)
{
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB"};
  std::size_t unit = 0;
  while (bytes >= 1024.0 && unit + 1 < sizeof (units) / sizeof (units[0])) {
    bytes /= 1024.0;
    ++unit;
  }
  char text[64];
  std::snprintf (
      text, sizeof (text), unit == 0 ? "%.0f %s" : "%.1f %s", bytes, units[unit]);
  return text;
}

} // namespace tda
} // namespace pcl
