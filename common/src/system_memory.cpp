#include <pcl/tda/common/system_memory.h>

#include <unistd.h>

#include <cstdio>
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

std::size_t
defaultMemoryLimit ()
{
  const std::size_t physical = physicalMemoryBytes();
  return physical > 0 ? physical / 2 : std::numeric_limits<std::size_t>::max();
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
