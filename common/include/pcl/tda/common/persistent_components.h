#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/types.h>

#include <limits>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Connected components of a complex's 1-skeleton at a cut value, read from
 * its H0 persistence (thesis Sec 4.1.5): the points joined, by negative edges of
 * value <= \a cut, to each essential class of the filtration cut there: the clusters
 * of PersistentEuclideanClusterExtraction.
 * \param[in] complex the complex (its edges and point indices; triangles are
 * ignored)
 * \param[in] h0 its persistence (computeH0Persistence() or any engine)
 * \param[in] cut the value at which the components are taken (edges above it are
 * left out; infinity takes every edge)
 * \return every component as sorted input point indices, largest first, equal
 * sizes by smallest index */
std::vector<pcl::Indices>
persistentComponents (const FilteredComplex& complex,
                      const PersistenceResult& h0,
                      double cut = std::numeric_limits<double>::infinity());

/** \brief The H0 diagram of the thesis' stepped filtration (Sec 4.4.2): every death
 * rounded up to a multiple of \a max_value / \a steps (0 steps: exact values), the
 * deaths beyond the last step at \a max_value, zero-length intervals dropped,
 * essential classes with death infinity. */
PersistenceDiagram
steppedH0Diagram (const FilteredComplex& complex,
                  const PersistenceResult& h0,
                  double max_value,
                  unsigned int steps);

} // namespace tda
} // namespace pcl
