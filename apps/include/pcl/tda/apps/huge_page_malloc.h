#pragma once

#include <cstddef>

namespace pcl {
namespace tda {

/** \brief Whether the kernel gives transparent huge pages to memory that asks for
 * them ("always" or "madvise" mode). */
bool
transparentHugePagesAvailable ();

/** \brief How much of malloc's heap a tool backs with huge pages
 * (backHeapWithHugePages()): 1 GiB of address space, of which the process uses
 * (and the system gives it) only what it writes; more than any tool takes from the
 * heap on the inputs of doc/benchmarks_real_scans.md up to 1M points. */
constexpr std::size_t HUGE_PAGE_HEAP_BYTES = std::size_t{1} << 30;

/** \brief Grows glibc's malloc heap by \a bytes at once and asks the kernel to back
 * that part with transparent huge pages (madvise() with MADV_HUGEPAGE), so that the
 * blocks malloc takes from it next are written 2 MiB at a time; the part of the
 * heap before its first huge page (up to 3 MiB of address space, never written) is
 * kept out of malloc's reach, so that the first blocks are written in huge pages too.
 * Returns whether the heap was advised. Does nothing and returns false when transparent
 * huge pages are off, when the user chose how malloc takes huge pages or pads its heap
 * (glibc.malloc.hugetlb or glibc.malloc.top_pad in GLIBC_TUNABLES, or
 * MALLOC_TOP_PAD_), when the address space or data size of the process is limited
 * (setrlimit(), `ulimit -v` or `-d`), where the heap could not grow, or where
 * malloc is not glibc's heap (e.g. under the address sanitizer).
 *
 * Why: a tool writes its arrays once, into memory that is new to the process, and
 * each 4 KiB page of it costs a page fault the first time it is written; on a
 * virtual machine a fault can cost 10 microseconds, a 2 MiB huge page about the
 * same for 512 times the memory. Call it at the start of the program, after
 * reuseFreedMemory() (which keeps the blocks of up to HEAP_BLOCK_LIMIT on the heap).
 * glibc's own tunable for this (glibc.malloc.hugetlb=1) is read only when a program
 * starts. Measured on a 2-core virtual machine (doc/performance.md):
 * `pcl_tda_barcode` on the table scene after a 1 cm voxel grid took 0.055 s with it
 * and 0.087-0.116 s without; keeping the part before the first huge page took
 * car6.pcd (10k points) from 0.038-0.042 s to 0.029-0.034 s. */
bool
backHeapWithHugePages (std::size_t bytes = HUGE_PAGE_HEAP_BYTES);

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
