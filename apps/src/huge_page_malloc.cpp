#include <pcl/tda/apps/huge_page_malloc.h>

#include <gnu/libc-version.h>
#include <malloc.h>
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace pcl {
namespace tda {

namespace {

/** Whether the kernel gives transparent huge pages to memory that asks for them
 * ("always" or "madvise" mode). */
bool
transparentHugePagesAvailable ()
{
  std::ifstream file ("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  return std::getline (file, modes) && modes.find ("[never]") == std::string::npos;
}

/** Whether glibc knows the tunable (2.35 and later). */
bool
glibcHasHugePageMalloc ()
{
  int major = 0, minor = 0;
  return std::sscanf (gnu_get_libc_version(), "%d.%d", &major, &minor) == 2 &&
         (major > 2 || (major == 2 && minor >= 35));
}

/** Whether GLIBC_TUNABLES names \a tunable: the user's (or the restart's) choice. */
bool
tunableChosen (const char* tunable)
{
  const char* tunables = std::getenv ("GLIBC_TUNABLES");
  return tunables != nullptr &&
         std::string (tunables).find (tunable) != std::string::npos;
}

} // namespace

bool
hugePageMallocAvailable ()
{
  return glibcHasHugePageMalloc() && transparentHugePagesAvailable();
}

void
restartWithHugePageMalloc (char** argv)
{
  const char* tunables = std::getenv ("GLIBC_TUNABLES");
  const bool had_tunables = tunables != nullptr;
  const std::string current = had_tunables ? tunables : "";
  if (tunableChosen ("glibc.malloc.hugetlb") || !hugePageMallocAvailable())
    return;
  const std::string wanted = current.empty() ? HUGE_PAGE_MALLOC_TUNABLE
                                             : current + ":" + HUGE_PAGE_MALLOC_TUNABLE;
  if (setenv ("GLIBC_TUNABLES", wanted.c_str(), 1) != 0)
    return;
  std::fflush (nullptr);
  execv ("/proc/self/exe", argv);
  // Not restarted: the tool goes on as it is, with the environment it was given.
  if (had_tunables)
    setenv ("GLIBC_TUNABLES", current.c_str(), 1);
  else
    unsetenv ("GLIBC_TUNABLES");
}

void
reuseFreedMemory ()
{
  // MALLOC_*_THRESHOLD_: glibc's older names of the same settings.
  if (!tunableChosen ("glibc.malloc.mmap_threshold") &&
      !std::getenv ("MALLOC_MMAP_THRESHOLD_"))
    mallopt (M_MMAP_THRESHOLD, static_cast<int> (HEAP_BLOCK_LIMIT));
  if (!tunableChosen ("glibc.malloc.trim_threshold") &&
      !std::getenv ("MALLOC_TRIM_THRESHOLD_"))
    mallopt (M_TRIM_THRESHOLD, INT_MAX);
}

} // namespace tda
} // namespace pcl
