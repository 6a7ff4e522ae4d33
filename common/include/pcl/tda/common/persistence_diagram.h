#pragma once

#include <pcl/tda/common/filtered_complex.h>

#include <limits>
#include <vector>

namespace pcl {
namespace tda {

/** \brief One interval of a persistence diagram: a homology class of dimension
 * \a dimension born at filtration value \a birth and dying at \a death (infinity
 * for an essential class). */
struct PersistenceInterval {
  int dimension;
  double birth;
  double death;

  bool
  isEssential () const
  {
    return death == std::numeric_limits<double>::infinity();
  }
};

/** \brief A persistence diagram: a multiset of intervals, in no particular order. */
using PersistenceDiagram = std::vector<PersistenceInterval>;

/** \brief A persistence pair: the positive simplex of dimension \a dimension that
 * creates a class and the negative simplex of dimension \a dimension + 1 that kills
 * it (INVALID_SIMPLEX for an essential class), with their filtration values. */
struct PersistencePair {
  int dimension;
  SimplexIndex birth_simplex;
  SimplexIndex death_simplex;
  double birth;
  double death;

  bool
  isEssential () const
  {
    return death_simplex == INVALID_SIMPLEX;
  }
};

/** \brief What a persistence engine computes on a FilteredComplex: every pair of
 * dimensions 0 and 1 (zero-length ones included), their essential classes, and the
 * positive/negative mark of every edge and triangle (vertices are all positive).
 * Negative edges form the spanning forest of the complex (thesis Sec 5.4); positive
 * triangles create the 2-cycles, which a complex without tetrahedra never kills:
 * they are counted by the marks (beta_2), not listed as pairs. Triangle marks are
 * empty when the engine computed H0 only. */
struct PersistenceResult {
  std::vector<PersistencePair> pairs;
  std::vector<bool> positive_edges;
  std::vector<bool> positive_triangles;

  /** \brief The diagram of dimensions <= \a max_dimension, without zero-length
   * intervals. */
  PersistenceDiagram
  diagram (int max_dimension = 2) const;
};

} // namespace tda
} // namespace pcl
