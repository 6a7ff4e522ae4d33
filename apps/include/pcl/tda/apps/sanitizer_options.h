#pragma once

// Include in exactly one source file of each program that runs PCL's GRSD, CVFH or
// OUR-CVFH (pcl_tda_classify and its tests); it defines nothing unless the program
// is built with AddressSanitizer (PCL_TDA_SANITIZE).

#if defined(__SANITIZE_ADDRESS__)
/** \brief AddressSanitizer's default options for a program that runs PCL's GRSD,
 * CVFH or OUR-CVFH: its alloc-dealloc-mismatch check off, every other check on
 * (ASAN_OPTIONS still override them).
 *
 * PCL's libraries are built as C++14, where Eigen's aligned operator new of PCL's
 * classes (PCL_MAKE_ALIGNED_OPERATOR_NEW) allocates with malloc; in our C++17 code
 * that macro is empty (C++17 aligns by itself). Those descriptors release clouds they
 * allocated through the std::shared_ptr code of the program, which our code also
 * instantiates and which the dynamic linker therefore takes from the program: a
 * malloc'ed cloud goes to the standard operator delete. glibc's free takes both
 * (malloc's alignment is what Eigen asks for on x86-64), but AddressSanitizer
 * reports the pair as a mismatch and stops the program. */
extern "C" const char*
__asan_default_options ()
{
  return "alloc_dealloc_mismatch=0";
}
#endif
