// Tests of the way the tools prepare glibc's malloc: the heap backed with transparent
// huge pages (a choice of the user's left as it is), and freed blocks kept for the
// next.

#include <pcl/tda/apps/huge_page_malloc.h>

#include <gtest/gtest.h>

#include "new_block_faults.h"
#include "tool_runner.h"

#include <cstddef>
#include <cstdio>
#include <string>

using pcl::tda::test::faultsOfNewBlock;
using pcl::tda::test::run;

namespace {

const std::string PROBE = std::string (PCL_TDA_BIN_DIR) + "/huge_page_malloc_probe";

/** The 4 KiB pages of the probe's first block and of its second. */
constexpr long FIRST_PROBE_PAGES = (1 << 20) / 4096;
constexpr long PROBE_PAGES = (24 << 20) / 4096;

/** What the probe printed. */
struct ProbeResult {
  int advised = -1;
  long first_faults = -1;
  long faults = -1;
};

/** Whether the probe's heap was advised, and the page faults of its writes of 1 MiB
 * and of 24 MiB, run by sh with \a setup (e.g. "GLIBC_TUNABLES=x",
 * "ulimit -v 8000000;") before it. */
ProbeResult
probe (const std::string& setup)
{
  const auto output =
      run ("unset GLIBC_TUNABLES MALLOC_TOP_PAD_; " + setup + " " + PROBE);
  EXPECT_EQ (output.exit_code, 0) << output.output;
  ProbeResult result;
  EXPECT_EQ (std::sscanf (output.output.c_str(),
                          "advised %d\nfirst faults %ld\nfaults %ld",
                          &result.advised,
                          &result.first_faults,
                          &result.faults),
             3)
      << output.output;
  return result;
}

} // namespace

TEST (HugePageHeap, NewBlocksAreWrittenInHugePages)
{
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "the address sanitizer brings its own malloc";
#endif
  if (!pcl::tda::transparentHugePagesAvailable())
    GTEST_SKIP() << "transparent huge pages are off here";
  const ProbeResult result = probe ("");
  EXPECT_EQ (result.advised, 1);
  // The first block lies on the heap's first huge page, not on the 4 KiB pages before
  // it: 0 faults in each of 100 runs, against 255 before the heap kept that part.
  EXPECT_LE (result.first_faults, FIRST_PROBE_PAGES / 8);
  // 12 huge pages: 12 faults in each of 100 runs (median 12, at most 267, before the
  // heap kept its first part), against 6,144 in 4 KiB pages.
  EXPECT_LE (result.faults, PROBE_PAGES / 8);
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
    const ProbeResult result = probe (setup);
    EXPECT_EQ (result.advised, 0) << setup;
    EXPECT_GT (result.faults, 0) << setup;
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
