#pragma once

#include <pcl/tda/common/betti_numbers.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_diagram.h>
#include <pcl/tda/common/persistence_result.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The sizes of a Vietoris-Rips complex cut at a radius and its Betti
 * numbers there: what the viewer's -barcode mode shows as the radius is stepped. */
struct RadiusCounts {
  std::size_t edges = 0;
  std::size_t triangles = 0;
  std::int64_t beta_0 = 0;
  std::int64_t beta_1 = 0;
};

/** \brief A filtered complex and its H0 and H1 persistence, read at any radius up to
 * the one it was built with (thesis Fig 6.1: components merging and 1-cycles
 * appearing and dying as the radius grows). */
class FiltrationAtRadius {
public:
  /** \brief Keeps \a complex and \a result, the persistence of both dimensions of
   * it (computePersistence()). */
  FiltrationAtRadius (FilteredComplex complex, PersistenceResult result);

  /** \brief The edges and triangles of value <= \a radius and the Betti numbers of
   * that subcomplex. */
  RadiusCounts
  countsAt (double radius) const;

  /** \brief A label per input point (\a num_points of them) for the components of
   * the 1-skeleton at \a radius: 1, 2, ... by decreasing size, 0 for points alone
   * (and for points not in the complex, e.g. non-finite ones). */
  std::vector<std::uint32_t>
  componentLabels (double radius, std::size_t num_points) const;

  /** \brief The H0 and H1 intervals of non-zero length. */
  const PersistenceDiagram&
  diagram () const
  {
    return diagram_;
  }

  const FilteredComplex&
  complex () const
  {
    return complex_;
  }

private:
  FilteredComplex complex_;
  PersistenceResult result_;
  PersistenceDiagram diagram_;
};

} // namespace tda
} // namespace pcl
