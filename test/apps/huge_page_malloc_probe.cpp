// A program for test_huge_page_malloc: prepares malloc as the tools do
// (reuseFreedMemory(), backHeapWithHugePages()), writes a new block of 24 MiB, and
// prints whether the heap was advised and the page faults of that write.

#include <pcl/tda/apps/huge_page_malloc.h>

#include <sys/resource.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

/** The minor page faults of this process so far. */
long
pageFaults ()
{
  rusage usage;
  getrusage (RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

/** The blocks, through volatile pointers, so that the compiler keeps the writes. */
void* volatile first_block = nullptr;
void* volatile block = nullptr;

} // namespace

int
main ()
{
  pcl::tda::reuseFreedMemory();
  const bool advised = pcl::tda::backHeapWithHugePages();
  // The heap's first 2 MiB boundary may lie up to 2 MiB into the advised part: its
  // 4 KiB pages before it go to a first block.
  constexpr std::size_t HUGE_PAGE = std::size_t{2} << 20;
  first_block = std::malloc (HUGE_PAGE);
  constexpr std::size_t BYTES = std::size_t{24} << 20;
  const long before = pageFaults();
  block = std::malloc (BYTES);
  std::memset (block, 1, BYTES);
  const long faults = pageFaults() - before;
  std::free (block);
  std::free (first_block);
  std::printf ("advised %d\nfaults %ld\n", advised ? 1 : 0, faults);
  return 0;
}
