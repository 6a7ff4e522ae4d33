// A program for test_huge_page_malloc: counts its starts in PROBE_STARTS, calls
// restartWithHugePageMalloc(), then prints the starts, GLIBC_TUNABLES ("-" when
// unset) and its arguments, one per line between brackets.

#include <pcl/tda/apps/huge_page_malloc.h>

#include <cstdio>
#include <cstdlib>
#include <string>

int
main (int argc, char** argv)
{
  const char* starts = std::getenv ("PROBE_STARTS");
  const std::string count = std::to_string ((starts ? std::atoi (starts) : 0) + 1);
  setenv ("PROBE_STARTS", count.c_str(), 1);
  pcl::tda::restartWithHugePageMalloc (argv);
  const char* tunables = std::getenv ("GLIBC_TUNABLES");
  std::printf ("starts %s\ntunables %s\n", count.c_str(), tunables ? tunables : "-");
  for (int i = 1; i < argc; ++i)
    std::printf ("[%s]\n", argv[i]);
  return 0;
}
