#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_diagram.h>

namespace pcl {
namespace tda {

/** \brief 0-dimensional persistence of a filtered complex by union-find and the
 * elder rule (thesis Sec 4.1.4).
 *
 * Edges are taken in filtration order; an edge joining two components is negative
 * and kills the younger component (the one whose oldest vertex has the larger
 * index), an edge inside a component is positive. Every component left at the end
 * is an essential class born by its oldest vertex. The negative edges, marked in
 * PersistenceResult::positive_edges, form the spanning forest of the complex.
 * The pairs are exactly those of the standard reduction; triangles are ignored.
 */
PersistenceResult
computeH0Persistence (const FilteredComplex& complex);

} // namespace tda
} // namespace pcl
