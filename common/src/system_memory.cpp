#include <pcl/tda/common/system_memory.h>

#include <unistd.h>

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

} // namespace tda
} // namespace pcl
