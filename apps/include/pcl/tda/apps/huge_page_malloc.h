#pragma once

namespace pcl {
namespace tda {

/** \brief The tunable that has glibc's malloc back the memory it takes from the
 * system with transparent huge pages (glibc 2.35 and later). */
constexpr const char* HUGE_PAGE_MALLOC_TUNABLE = "glibc.malloc.hugetlb=1";

/** \brief The fewest points of a tool's input for which a tool restarts with huge
 * pages for malloc (see runTool()). The restart costs 5-7 ms, the start of a tool;
 * measured on a 2-core virtual machine, `pcl_tda_barcode` took 9.8 ms without it
 * and 17.1 ms with it on bunny.pcd (397 points), 21.4 and 26.7 ms on a 3,782-point
 * scan, and was within 2 ms either way at 10,000-14,000 points, while tools that do
 * more per point (`pcl_tda_holes`, `pcl_tda_regions`) gained 8 ms at 13,704 points
 * and every tool gains more on larger inputs. */
constexpr unsigned HUGE_PAGE_MALLOC_MIN_POINTS = 5000;

/** \brief Whether malloc can be given huge pages here: glibc 2.35 or later (which
 * knows HUGE_PAGE_MALLOC_TUNABLE) and transparent huge pages not off ("always" or
 * "madvise" mode). */
bool
hugePageMallocAvailable ();

/** \brief Starts the tool again, as the same program with the same arguments
 * (execv() of /proc/self/exe), with HUGE_PAGE_MALLOC_TUNABLE added to GLIBC_TUNABLES;
 * returns, and the tool goes on as it is, when !hugePageMallocAvailable(),
 * GLIBC_TUNABLES already says how malloc takes huge pages (also after the restart), or
 * the restart fails.
 *
 * Why: a tool writes its arrays once, into memory that is new to the process, and
 * each 4 KiB page of it costs a page fault the first time it is written; on a
 * virtual machine a fault can cost 10 microseconds, a 2 MiB huge page about the
 * same for 512 times the memory. glibc reads its tunables only when a program
 * starts, hence the restart, before the tool prints anything; it takes about as long
 * as the start of a tool (a few milliseconds). */
void
restartWithHugePageMalloc (char** argv);

} // namespace tda
} // namespace pcl
