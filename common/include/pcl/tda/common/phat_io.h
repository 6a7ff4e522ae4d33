#pragma once

#include <pcl/tda/common/filtered_complex.h>

#include <istream>
#include <ostream>
#include <string>

namespace pcl {
namespace tda {

/** \brief The two boundary matrix file formats of PHAT: ASCII (one column per line,
 * its dimension then its row indices) and BINARY (64-bit integers: the number of
 * columns, then per column its dimension, its size and its row indices). */
enum class PHATFormat { ASCII, BINARY };

/** \brief Writes the boundary matrix of \a complex in global filtration order, so
 * that PHAT (or any tool reading its formats) reduces the very same complex. */
void
writePHATBoundaryMatrix (std::ostream& out,
                         const FilteredComplex& complex,
                         PHATFormat format);

/** \brief writePHATBoundaryMatrix() to a file, written atomically.
 * \throws pcl::IOException when the file cannot be written */
void
savePHATBoundaryMatrix (const std::string& path,
                        const FilteredComplex& complex,
                        PHATFormat format);

/** \brief Reads a PHAT boundary matrix of a complex of dimension <= 2 whose vertex
 * columns come first. PHAT files carry no filtration values: edges and triangles
 * get their column index as value, which keeps the file's order.
 * \throws pcl::IOException on a malformed matrix (wrong sizes or dimensions, faces
 * after cofaces, truncated input) */
FilteredComplex
readPHATBoundaryMatrix (std::istream& in, PHATFormat format);

/** \brief readPHATBoundaryMatrix() from a file.
 * \throws pcl::IOException when the file cannot be read or is malformed */
FilteredComplex
loadPHATBoundaryMatrix (const std::string& path, PHATFormat format);

} // namespace tda
} // namespace pcl
