// Tests of the way the tools prepare glibc's malloc: the heap backed with transparent
// huge pages (a choice of the user's left as it is), and freed blocks kept for the
// next.

#include <pcl/tda/apps/huge_page_malloc.h>

#include <gtest/gtest.h>

#include "tool_runner.h"
#include <sys/resource.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>

using pcl::tda::test::run;

namespace {

const std::string PROBE = std::string (PCL_TDA_BIN_DIR) + "/huge_page_malloc_probe";

/** The 4 KiB pages of the probe's block. */
constexpr long PROBE_PAGES = (24 << 20) / 4096;

/** Whether the probe's heap was advised, and the page faults of its write of 24 MiB,
 * run by sh with \a setup (e.g. "GLIBC_TUNABLES=x", "ulimit -v 8000000;") before it. */
std::pair<int, long>
probe (const std::string& setup)
{
  const auto result =
      run ("unset GLIBC_TUNABLES MALLOC_TOP_PAD_; " + setup + " " + PROBE);
  EXPECT_EQ (result.exit_code, 0) << result.output;
  int advised = -1;
  long faults = -1;
  EXPECT_EQ (
      std::sscanf (result.output.c_str(), "advised %d\nfaults %ld", &advised, &faults),
      2)
      << result.output;
  return {advised, faults};
}

/** The block of faultsOfNewBlock(): through a volatile pointer, so that the compiler
 * keeps the writes to it. */
void* volatile block = nullptr;

/** The page faults of this process while it writes a new block of \a bytes, which it
 * frees after. */
long
faultsOfNewBlock (std::size_t bytes)
{
  rusage usage;
  getrusage (RUSAGE_SELF, &usage);
  const long before = usage.ru_minflt;
  block = std::malloc (bytes);
  std::memset (block, 1, bytes);
  std::free (block);
  getrusage (RUSAGE_SELF, &usage);
  return usage.ru_minflt - before;
}

} // namespace

TEST (HugePageHeap, NewBlocksAreWrittenInHugePages)
{
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "the address sanitizer brings its own malloc";
#endif
  if (!pcl::tda::transparentHugePagesAvailable())
    GTEST_SKIP() << "transparent huge pages are off here";
  const auto [advised, faults] = probe ("");
  EXPECT_EQ (advised, 1);
  // 12 huge pages: 12 faults (median; at most 267) in 100 runs on a busy machine,
  // against 6,144 in 4 KiB pages.
  EXPECT_LE (faults, PROBE_PAGES / 8);
}

TEST (HugePageHeap, KeepsTheUsersChoiceAndLimits)
{
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "the address sanitizer brings its own malloc, and its shadow "
                  "memory does not fit the limits";
#endif
  for (const std::string setup : {"GLIBC_TUNABLES=glibc.malloc.hugetlb=0",
                                  "GLIBC_TUNABLES=glibc.malloc.top_pad=0",
                                  "MALLOC_TOP_PAD_=4096",
                                  "ulimit -v 8000000;",
                                  "ulimit -d 8000000;"}) {
    const auto [advised, faults] = probe (setup);
    EXPECT_EQ (advised, 0) << setup;
    EXPECT_GT (faults, 0) << setup;
  }
}

TEST (ReuseFreedMemory, AFreedBlockServesTheNextWithoutPageFaults)
{
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "the address sanitizer brings its own malloc";
#endif
  pcl::tda::reuseFreedMemory();
  // Larger than any block this program asked for before: new memory the first time.
  constexpr std::size_t BYTES = std::size_t{24} << 20;
  const long first = faultsOfNewBlock (BYTES);
  const long second = faultsOfNewBlock (BYTES);
  EXPECT_GT (first, 0);
  EXPECT_LE (second, first / 10) << "the freed block went back to the system";
}
