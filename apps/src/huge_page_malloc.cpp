#include <pcl/tda/apps/huge_page_malloc.h>

#include <malloc.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <climits>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

namespace pcl {
namespace tda {

namespace {

/** glibc's padding of its heap when it grows (M_TOP_PAD), 128 KiB. */
constexpr int DEFAULT_TOP_PAD = 128 << 10;

/** The block backHeapWithHugePages() asks for to have the heap grow. */
constexpr std::size_t GROWTH_BLOCK = std::size_t{1} << 20;

/** The size of a transparent huge page, and the alignment the kernel needs for one. */
constexpr std::uintptr_t HUGE_PAGE_BYTES = std::uintptr_t{2} << 20;

/** Whether the user chose a malloc setting: \a tunable in GLIBC_TUNABLES, or its
 * older environment variable \a variable (MALLOC_*_, where glibc has one). */
bool
userChose (const char* tunable, const char* variable = nullptr)
{
  const char* tunables = std::getenv ("GLIBC_TUNABLES");
  return (tunables != nullptr &&
          std::string (tunables).find (tunable) != std::string::npos) ||
         (variable != nullptr && std::getenv (variable) != nullptr);
}

/** Whether the process has a limit on its address space or its data size. */
bool
memoryLimited ()
{
  for (const int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    rlimit limit;
    if (getrlimit (resource, &limit) != 0 || limit.rlim_cur != RLIM_INFINITY)
      return true;
  }
  return false;
}

/** The block that keeps the heap up to its first usable huge page out of malloc's
 * reach (keepHeapBelowHugePages()); never written, it costs address space only. */
void* heap_below_huge_pages = nullptr;

/** Has \a block, the block of \a bytes at the top of the heap, reach the huge page
 * boundary after it and keeps it, so that the blocks malloc takes from the heap next
 * start at that boundary. Else the first of them would lie on the part of the heap
 * that the kernel backs with 4 KiB pages: before the heap's first boundary (the heap
 * rarely starts at one), and the 2 MiB around the end of \a block, where malloc wrote
 * the header of the rest of the heap before the advice (a 4 KiB page there, so no
 * huge page): up to 4 MiB that a tool would write first, a page fault per 4 KiB.
 * Frees \a block where it could not grow in place. */
void
keepHeapBelowHugePages (char* block, std::size_t bytes)
{
  // malloc's header of the rest of the heap: 16 bytes after the block.
  constexpr std::size_t HEADER_BYTES = 16;
  const auto address = reinterpret_cast<std::uintptr_t> (block);
  const std::uintptr_t boundary =
      (address + bytes + HEADER_BYTES + HUGE_PAGE_BYTES - 1) & ~(HUGE_PAGE_BYTES - 1);
  void* const kept = std::realloc (block, boundary - address);
  if (kept == block)
    heap_below_huge_pages = kept;
  else
    std::free (kept != nullptr ? kept : block);
}

} // namespace

bool
transparentHugePagesAvailable ()
{
  std::ifstream file ("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  return std::getline (file, modes) && modes.find ("[never]") == std::string::npos;
}

bool
backHeapWithHugePages (std::size_t bytes)
{
  if (bytes > INT_MAX || userChose ("glibc.malloc.hugetlb") ||
      userChose ("glibc.malloc.top_pad", "MALLOC_TOP_PAD_") ||
      !transparentHugePagesAvailable() || memoryLimited())
    return false;
  // The heap grows by the block and the padding at once, in address space only.
  mallopt (M_TOP_PAD, static_cast<int> (bytes));
  char* const block = static_cast<char*> (std::malloc (GROWTH_BLOCK));
  mallopt (M_TOP_PAD, DEFAULT_TOP_PAD);
  if (block == nullptr)
    return false;
  char* const heap_end = static_cast<char*> (sbrk (0));
  const auto page = static_cast<std::uintptr_t> (sysconf (_SC_PAGESIZE));
  char* const begin =
      reinterpret_cast<char*> (reinterpret_cast<std::uintptr_t> (block) & ~(page - 1));
  // Anywhere else, the block is not on the heap that grew.
  const bool on_grown_heap =
      begin < heap_end &&
      static_cast<std::size_t> (heap_end - begin) <= bytes + GROWTH_BLOCK + page;
  const bool advised =
      on_grown_heap && madvise (begin, heap_end - begin, MADV_HUGEPAGE) == 0;
  if (advised)
    keepHeapBelowHugePages (block, GROWTH_BLOCK);
  else
    std::free (block);
  return advised;
}

void
reuseFreedMemory ()
{
  if (!userChose ("glibc.malloc.mmap_threshold", "MALLOC_MMAP_THRESHOLD_"))
    mallopt (M_MMAP_THRESHOLD, static_cast<int> (HEAP_BLOCK_LIMIT));
  if (!userChose ("glibc.malloc.trim_threshold", "MALLOC_TRIM_THRESHOLD_"))
    mallopt (M_TRIM_THRESHOLD, INT_MAX);
}

} // namespace tda
} // namespace pcl
