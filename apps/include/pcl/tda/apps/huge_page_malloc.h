#pragma once

#include <cstddef>

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

/** \brief The largest block that reuseFreedMemory() has glibc's malloc take from its
 * heap: 32 MiB, the most glibc accepts on 64-bit systems. */
constexpr std::size_t HEAP_BLOCK_LIMIT = std::size_t{32} << 20;

/** \brief Has glibc's malloc keep the memory a tool frees for the blocks it asks for
 * next: blocks of up to HEAP_BLOCK_LIMIT come from malloc's heap, and the heap is not
 * given back to the system while the tool runs. Leaves a threshold that the user
 * set (glibc.malloc.mmap_threshold or glibc.malloc.trim_threshold in GLIBC_TUNABLES,
 * or MALLOC_MMAP_THRESHOLD_ or MALLOC_TRIM_THRESHOLD_) as it is.
 *
 * Why: by default glibc maps every block of 128 KiB or more (up to 32 MiB as blocks
 * are freed) on its own and unmaps it when it is freed, and gives the top of its heap
 * back; the next array, often of the same size, is written into memory new to the
 * process again, a page fault per page. Measured on a 2-core virtual machine, where
 * a first write costs 1-3 ms per MiB: `pcl_tda_barcode` took 0.165-0.175 s instead
 * of 0.208-0.215 s on a 100k-point subsample of kinect_frame.pcd, 0.054-0.069 s
 * instead of 0.076-0.084 s on the table scene after a 1 cm voxel grid, with the same
 * peak memory (doc/performance.md). */
void
reuseFreedMemory ();

} // namespace tda
} // namespace pcl
