// Tests of restartWithHugePageMalloc(): the tools start once more with glibc's malloc
// on transparent huge pages, with the same arguments, and leave a GLIBC_TUNABLES
// that already chooses otherwise as it is.

#include <pcl/tda/apps/huge_page_malloc.h>

#include <gtest/gtest.h>

#include "tool_runner.h"
#include <sys/resource.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <string>

using pcl::tda::test::run;

namespace {

const std::string PROBE = std::string (PCL_TDA_BIN_DIR) + "/huge_page_malloc_probe";

/** The probe's output with \a environment (e.g. "GLIBC_TUNABLES=x") and its
 * arguments 'a b', '' and 'c'. */
std::string
probe (const std::string& environment)
{
  const auto result = run ("env -u GLIBC_TUNABLES -u PROBE_STARTS " + environment +
                           " " + PROBE + " 'a b' '' c");
  EXPECT_EQ (result.exit_code, 0) << result.output;
  return result.output;
}

const std::string ARGUMENTS = "[a b]\n[]\n[c]\n";

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

TEST (HugePageMalloc, RestartsOnceWithTheTunableAndTheSameArguments)
{
  if (!pcl::tda::hugePageMallocAvailable())
    GTEST_SKIP() << "no transparent huge pages or glibc older than 2.35 here";
  EXPECT_EQ (probe (""), "starts 2\ntunables glibc.malloc.hugetlb=1\n" + ARGUMENTS);
}

TEST (HugePageMalloc, AddsTheTunableToOtherTunables)
{
  if (!pcl::tda::hugePageMallocAvailable())
    GTEST_SKIP() << "no transparent huge pages or glibc older than 2.35 here";
  EXPECT_EQ (probe ("GLIBC_TUNABLES=glibc.malloc.arena_max=2"),
             "starts 2\ntunables glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1\n" +
                 ARGUMENTS);
}

TEST (HugePageMalloc, KeepsTheUsersChoice)
{
  EXPECT_EQ (probe ("GLIBC_TUNABLES=glibc.malloc.hugetlb=0"),
             "starts 1\ntunables glibc.malloc.hugetlb=0\n" + ARGUMENTS);
  EXPECT_EQ (probe ("GLIBC_TUNABLES=glibc.malloc.arena_max=2:glibc.malloc.hugetlb=2"),
             "starts 1\ntunables glibc.malloc.arena_max=2:glibc.malloc.hugetlb=2\n" +
                 ARGUMENTS);
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
