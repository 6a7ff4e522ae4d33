#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_diagram.h>

#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief What every persistence engine computes on a FilteredComplex, as dense
 * per-simplex arrays: the language the application classes read.
 *
 * A simplex is positive when it creates a homology class and negative when it kills
 * one (thesis Sec 2.6). Vertices are all positive. For every positive simplex the
 * result holds the simplex that kills its class, or INVALID_SIMPLEX for an essential
 * class; that is the persistence pairing itself: "index = birth simplex, entry =
 * death simplex", the matrix of STPP (thesis Fig 6.2).
 *
 * - The negative edges form the minimum spanning forest of the complex (Sec 4.1.4);
 *   clustering cuts it (persistentComponents()), hole detection (Alg 5.15) walks it.
 * - A positive edge creates a 1-cycle; the triangle in \a edge_killer kills it.
 * - Positive triangles create the 2-cycles, which a complex without tetrahedra never
 *   kills: they are counted by the marks (beta_2), not listed as pairs.
 *
 * Pairs, diagrams and Betti numbers are derived from these arrays; the arrays are
 * plain bytes and ids, so they can be written in parallel and copied to a device.
 * \a max_dimension tells which homology was computed: 0 (computeH0Persistence(),
 * the edge and vertex arrays only) or 1 (all arrays). */
struct PersistenceResult {
  /** \brief Per vertex: the edge that merges its component into an older one (the
   * elder rule), or INVALID_SIMPLEX for the oldest vertex of a component left at the
   * end (an essential class of dimension 0). */
  std::vector<SimplexIndex> vertex_killer;
  /** \brief Per edge: 1 when the edge is positive (creates a 1-cycle), 0 when it is
   * negative (joins two components). */
  std::vector<std::uint8_t> edge_positive;
  /** \brief Per edge, with H1: the triangle that kills the 1-cycle a positive edge
   * creates, or INVALID_SIMPLEX (a negative edge, or an essential 1-cycle). */
  std::vector<SimplexIndex> edge_killer;
  /** \brief Per triangle, with H1: 1 when the triangle is positive (creates a
   * 2-cycle), 0 when it kills a 1-cycle. */
  std::vector<std::uint8_t> triangle_positive;
  /** \brief The largest homology dimension computed: 0 or 1. */
  int max_dimension = 0;

  /** \brief Every pair of dimension <= min(\a max_dimension, this->max_dimension)
   * with its simplices and values, zero-length ones included: finite pairs of
   * dimension 0 in the order of their killing edges, then essential ones by vertex,
   * then finite pairs of dimension 1 by killing triangle and essential ones by edge.
   */
  std::vector<PersistencePair>
  pairs (const FilteredComplex& complex, int max_dimension = 1) const;

  /** \brief The diagram of dimensions <= \a max_dimension, without zero-length
   * intervals. */
  PersistenceDiagram
  diagram (const FilteredComplex& complex, int max_dimension = 1) const;

  /** \brief The negative edges in filtration order: the minimum spanning forest of
   * the complex. */
  std::vector<SimplexIndex>
  negativeEdges () const;

  /** \brief Per edge, the vertex whose class it kills (INVALID_SIMPLEX for a
   * positive edge): the inverse of \a vertex_killer. */
  std::vector<SimplexIndex>
  killedVertices () const;
};

} // namespace tda
} // namespace pcl
