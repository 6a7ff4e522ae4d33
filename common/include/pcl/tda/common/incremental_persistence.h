#pragma once

#include <pcl/tda/common/cycle_set.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/common/progress.h>

#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The table T of the incremental persistence algorithm (thesis Sec 5.2.3,
 * Alg 5.9-5.11): one slot per edge; the slot of a positive edge, once occupied,
 * holds the set Lambda of positive edges of a cycle that the edge created and a
 * triangle killed, and that triangle.
 *
 * Triangles are added in filtration order. For each, the cycle search starts from
 * the positive edges of its boundary and adds the stored cycle of the youngest edge
 * while that edge's slot is occupied; it ends at a free slot (the triangle kills
 * that edge's class) or with an empty set (the triangle is positive).
 */
class IncrementalCycleTable {
public:
  /** \param[in] complex the filtered complex (kept by reference)
   * \param[in] edge_positive the edge marks of H0 persistence (kept by reference) */
  IncrementalCycleTable (const FilteredComplex& complex,
                         const std::vector<std::uint8_t>& edge_positive);

  /** \brief Alg 5.11 for the next triangle in filtration order.
   * \return the positive edge whose class \a triangle kills, or INVALID_SIMPLEX when
   * \a triangle is positive */
  SimplexIndex
  addTriangle (SimplexIndex triangle);

  bool
  isOccupied (SimplexIndex edge) const
  {
    return deaths_[edge] != INVALID_SIMPLEX;
  }

  /** \brief The set Lambda stored in the slot of \a edge (sorted; empty when free). */
  const CycleSet&
  cycle (SimplexIndex edge) const
  {
    return cycles_[edge];
  }

  /** \brief The triangle stored in the slot of \a edge (INVALID_SIMPLEX when free). */
  SimplexIndex
  death (SimplexIndex edge) const
  {
    return deaths_[edge];
  }

private:
  const FilteredComplex& complex_;
  const std::vector<std::uint8_t>& edge_positive_;
  std::vector<CycleSet> cycles_;
  std::vector<SimplexIndex> deaths_;
  CycleSet buffer_;
};

/** \brief H1 by the incremental algorithm (thesis Alg 5.11) with an
 * IncrementalCycleTable: completes \a result, the H0 persistence of \a complex
 * (computeH0Persistence()), to the standard reduction's result. */
void
addIncrementalH1Persistence (const FilteredComplex& complex,
                             PersistenceResult& result,
                             const ProgressCallback& progress = {});

} // namespace tda
} // namespace pcl
