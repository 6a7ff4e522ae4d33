#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/common/progress.h>

namespace pcl {
namespace tda {

/** \brief Persistence of a filtered complex by the standard reduction of its
 * boundary matrix over Z2 (thesis Alg 2.1): each column, in filtration order, is
 * added the earlier column with the same lowest one until its lowest one is new or
 * it is zero. Cubic in the worst case; it is the oracle every other engine is
 * tested against.
 * \param[in] complex the filtered complex (dimension <= 2)
 * \param[in] progress optional callback, given reduced columns and all columns
 * \return the whole result (max_dimension 1): the killer and mark of every simplex
 */
PersistenceResult
computeStandardReduction (const FilteredComplex& complex,
                          const ProgressCallback& progress = {});

} // namespace tda
} // namespace pcl
