#include <pcl/tda/common/large_vector.h>

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

namespace pcl {
namespace tda {

void
adviseHugePages ([[maybe_unused]] const void* data, [[maybe_unused]] std::size_t bytes)
{
#ifdef MADV_HUGEPAGE
  constexpr std::size_t MIN_BYTES = std::size_t{4} << 20;
  if (bytes < MIN_BYTES)
    return;
  // madvise() takes whole pages: the pages that lie inside the block.
  const auto page = static_cast<std::uintptr_t> (sysconf (_SC_PAGESIZE));
  const auto begin = (reinterpret_cast<std::uintptr_t> (data) + page - 1) / page * page;
  const auto end = (reinterpret_cast<std::uintptr_t> (data) + bytes) / page * page;
  if (begin < end)
    madvise (reinterpret_cast<void*> (begin), end - begin, MADV_HUGEPAGE);
#endif
}

} // namespace tda
} // namespace pcl
