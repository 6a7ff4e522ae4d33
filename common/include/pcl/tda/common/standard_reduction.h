#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_diagram.h>

#include <functional>

namespace pcl {
namespace tda {

/** \brief Called now and then by long computations with the units of work done so
 * far and the total, e.g. to drive a ProgressBar. */
using ProgressCallback = std::function<void (std::size_t done, std::size_t total)>;

/** \brief Persistence of a filtered complex by the standard reduction of its
 * boundary matrix over Z2 (thesis Alg 2.1): each column, in filtration order, is
 * added the earlier column with the same lowest one until its lowest one is new or
 * it is zero. Cubic in the worst case; it is the oracle every other engine is
 * tested against.
 * \param[in] complex the filtered complex (dimension <= 2)
 * \param[in] progress optional callback, given reduced columns and all columns
 * \return all pairs of dimensions 0 and 1, essential classes of dimensions 0 and 1,
 * and the positive/negative marks of all edges and triangles
 */
PersistenceResult
computeStandardReduction (const FilteredComplex& complex,
                          const ProgressCallback& progress = {});

} // namespace tda
} // namespace pcl
