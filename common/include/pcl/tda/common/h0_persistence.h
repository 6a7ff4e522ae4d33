#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>

namespace pcl {
namespace tda {

/** \brief 0-dimensional persistence of a filtered complex by union-find and the
 * elder rule (thesis Sec 4.1.4).
 *
 * Edges are taken in filtration order; an edge joining two components is negative
 * and kills the younger component (the one whose oldest vertex has the larger
 * index), an edge inside a component is positive. Every component left at the end
 * is an essential class born by its oldest vertex. Fills the vertex and edge arrays
 * of the result (max_dimension 0): the killer of every vertex and the marks of the
 * edges, whose negative ones form the minimum spanning forest of the complex. The
 * pairing is exactly that of the standard reduction; triangles are ignored.
 */
PersistenceResult
computeH0Persistence (const FilteredComplex& complex);

} // namespace tda
} // namespace pcl
