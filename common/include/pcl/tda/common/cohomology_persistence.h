#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/common/progress.h>

namespace pcl {
namespace tda {

/** \brief H1 by persistent cohomology of the edges: the fastest engine of PCL-TDA,
 * and the default. Completes \a result, the H0 persistence of \a complex
 * (computeH0Persistence()), to the standard reduction's result.
 *
 * The coboundary of every positive edge (the triangles containing it, in filtration
 * order) is reduced over Z2, youngest edge first, with the oldest triangle as pivot;
 * negative edges need no column (clearing). A positive edge and the oldest triangle
 * of its coboundary form an apparent pair when the edge is that triangle's youngest
 * edge: in a Vietoris-Rips complex most pairs are such, and they cost no reduction.
 * Cohomology pairs the same simplices as homology.
 * \param[in] complex the filtered complex
 * \param[in,out] result H0 persistence in, H0 and H1 persistence out
 * \param[in] progress optional callback (edges processed, edges)
 */
void
addCohomologyH1Persistence (const FilteredComplex& complex,
                            PersistenceResult& result,
                            const ProgressCallback& progress = {});

} // namespace tda
} // namespace pcl
