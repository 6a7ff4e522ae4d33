#include <pcl/tda/common/system_memory.h>

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using pcl::tda::defaultMemoryLimit;
using pcl::tda::formatBytes;
using pcl::tda::physicalMemoryBytes;
using pcl::tda::usableMemoryBytes;

TEST (SystemMemory, UsableMemoryIsAtMostThePhysicalMemory)
{
  const std::size_t physical = physicalMemoryBytes();
  ASSERT_GT (physical, 0u); // Linux reports it
  EXPECT_GT (usableMemoryBytes(), 0u);
  EXPECT_LE (usableMemoryBytes(), physical);
  EXPECT_EQ (defaultMemoryLimit(), usableMemoryBytes() / 2);
}

// Under `ulimit -v` the default limit is half of it, not half of the physical memory
// (the tools aborted with std::bad_alloc under an address-space limit). Checked in a
// child process, whose limit goes with it.
TEST (SystemMemory, DefaultLimitFollowsTheAddressSpaceLimit)
{
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "the address sanitizer reserves more address space than the limit";
#endif
  constexpr std::size_t address_space = std::size_t{3} << 30;
  if (physicalMemoryBytes() <= address_space)
    GTEST_SKIP() << "this machine has at most 3 GiB of memory";
  const pid_t child = ::fork();
  ASSERT_GE (child, 0);
  if (child == 0) {
    const rlimit limit{address_space, address_space};
    const bool limited = ::setrlimit (RLIMIT_AS, &limit) == 0;
    ::_exit (limited && usableMemoryBytes() == address_space &&
                     defaultMemoryLimit() == address_space / 2
                 ? 0
                 : 1);
  }
  int status = 0;
  ASSERT_EQ (::waitpid (child, &status, 0), child);
  ASSERT_TRUE (WIFEXITED (status));
  EXPECT_EQ (WEXITSTATUS (status), 0);
}

TEST (SystemMemory, FormatBytes)
{
  EXPECT_EQ (formatBytes (512.0), "512 bytes");
  EXPECT_EQ (formatBytes (1536.0), "1.5 KiB");
  EXPECT_EQ (formatBytes (37.5 * 1048576.0), "37.5 MiB");
  EXPECT_EQ (formatBytes (4.2 * 1073741824.0), "4.2 GiB");
}

} // namespace
