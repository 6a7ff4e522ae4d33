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

} // namespace tda
} // namespace pcl
