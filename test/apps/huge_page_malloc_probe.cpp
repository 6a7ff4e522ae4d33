// A program for test_huge_page_malloc: prepares malloc as the tools do
// (reuseFreedMemory(), backHeapWithHugePages()), writes a new block of 1 MiB, then one
// of 24 MiB, and prints whether the heap was advised and the page faults of each
// write.

#include <pcl/tda/apps/huge_page_malloc.h>

#include "new_block_faults.h"

#include <cstddef>
#include <cstdio>

using pcl::tda::test::faultsOfNewBlock;

int
main ()
{
  pcl::tda::reuseFreedMemory();
  const bool advised = pcl::tda::backHeapWithHugePages();
  // Unless the heap keeps its part before the first usable huge page, this first
  // block lies there, on 4 KiB pages.
  const long first_faults = faultsOfNewBlock (std::size_t{1} << 20);
  const long faults = faultsOfNewBlock (std::size_t{24} << 20);
  std::printf ("advised %d\nfirst faults %ld\nfaults %ld\n",
               advised ? 1 : 0,
               first_faults,
               faults);
  return 0;
}
