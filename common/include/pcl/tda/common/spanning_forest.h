#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/union_find.h>

#include <cstddef>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The minimum spanning forest of a weighted graph by Kruskal with filtering
 * (Osipov, Sanders, Singler 2009): split the edges at the median value, take the
 * forest of the lighter half, drop the heavier edges that no longer join two
 * components, recurse on the rest. Only edges that can still join two components
 * get sorted, which on radius graphs of point clouds is a small fraction.
 *
 * Its edges are the negative edges of the elder rule, so the H0 persistence of the
 * graph's filtration equals that of the forest (thesis Sec 4.1.4): clustering keeps
 * only the forest of its radius graph, never the sorted graph or a complex.
 * \param[in] num_vertices number of vertices (edge ends are below it)
 * \param[in] edges the graph's edges, in any order (reordered)
 * \return the forest's edges in filtration order (edgeFiltrationLess()); of equal
 * values, those of the filtration order win, so the forest is that of the elder rule
 */
std::vector<FilteredEdge>
minimumSpanningForest (std::size_t num_vertices, std::vector<FilteredEdge>& edges);

/** \brief Kruskal with filtering, as minimumSpanningForest(), from components already
 * joined by lighter edges: appends to \a forest, in filtration order, the edges of
 * \a edges that join two of \a components, and joins them. Called on the edges of
 * increasing length classes in turn (every edge of a call at least as heavy as every
 * edge of the calls before), it gives the minimum spanning forest of all of them.
 * \param[in] edges edges in any order (reordered)
 * \param[in,out] components the components joined so far
 * \param[in,out] forest the forest so far */
void
extendSpanningForest (std::vector<FilteredEdge>& edges,
                      UnionFind& components,
                      std::vector<FilteredEdge>& forest);

} // namespace tda
} // namespace pcl
