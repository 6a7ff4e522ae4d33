#pragma once

#include <pcl/tda/common/cycle_set.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/common/progress.h>

#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The table T of the fast incremental persistence algorithm for 1-cycles
 * (thesis Sec 5.3, Alg 5.12-5.14).
 *
 * The slot of a positive edge i, once occupied by the triangle that kills its
 * class, stores a cycle set Lambda^c of other positive edges, all older than i and
 * all still free, such that i + Lambda^c is homologous to a boundary, and an update
 * list: the slots that stored a cycle built with i. Cycle storage (Alg 5.13) replaces
 * every occupied edge of a triangle's boundary by its stored cycle, so that at most
 * one more addition finds the free slot; cycle update (Alg 5.14) replaces a newly
 * occupied edge by its cycle in the stored cycles that hold it, keeping every
 * stored cycle made of free edges.
 *
 * Cycle update differs from the thesis' text in one point (see
 * doc/fast_incremental_persistence.md): it visits each slot reachable through the
 * update lists once and changes only the cycles that hold the edge, where the text
 * adds the new cycle to every slot reached, once per path.
 */
class FastIncrementalCycleTable {
public:
  /** \param[in] complex the filtered complex (kept by reference)
   * \param[in] edge_positive the edge marks of H0 persistence (kept by reference) */
  FastIncrementalCycleTable (const FilteredComplex& complex,
                             const std::vector<std::uint8_t>& edge_positive);

  /** \brief Cycle storage (Alg 5.13) for the next triangle in filtration order.
   * \return the positive edge whose class \a triangle kills, or INVALID_SIMPLEX when
   * \a triangle is positive */
  SimplexIndex
  addTriangle (SimplexIndex triangle);

  bool
  isOccupied (SimplexIndex edge) const
  {
    return deaths_[edge] != INVALID_SIMPLEX;
  }

  /** \brief The cycle set stored in the slot of \a edge, without \a edge itself. */
  const CycleSet&
  cycle (SimplexIndex edge) const
  {
    return cycles_[edge];
  }

  /** \brief The slots whose stored cycles were built with \a edge. */
  const std::vector<SimplexIndex>&
  updateList (SimplexIndex edge) const
  {
    return updates_[edge];
  }

  /** \brief The triangle stored in the slot of \a edge (INVALID_SIMPLEX when free). */
  SimplexIndex
  death (SimplexIndex edge) const
  {
    return deaths_[edge];
  }

private:
  /** Stores \a cycle and \a triangle in the free slot of \a edge, registers \a edge
   * in the update lists of \a built_from, and updates the cycles holding \a edge. */
  void
  store (SimplexIndex edge,
         CycleSet cycle,
         SimplexIndex triangle,
         const std::vector<SimplexIndex>& built_from);

  /** Cycle update (Alg 5.14) after the slot of \a edge was filled. */
  void
  updateCycles (SimplexIndex edge);

  const FilteredComplex& complex_;
  const std::vector<std::uint8_t>& edge_positive_;
  std::vector<CycleSet> cycles_;
  std::vector<std::vector<SimplexIndex>> updates_;
  std::vector<SimplexIndex> deaths_;
  std::vector<SimplexIndex> visited_; // generation stamp of the last update visit
  SimplexIndex generation_ = 0;
  CycleSet buffer_, substitute_;
  std::vector<SimplexIndex> stack_, built_from_;
};

/** \brief H1 by the fast incremental algorithm (thesis Alg 5.12) with a
 * FastIncrementalCycleTable: completes \a result, the H0 persistence of \a complex
 * (computeH0Persistence()), to the standard reduction's result. */
void
addFastIncrementalH1Persistence (const FilteredComplex& complex,
                                 PersistenceResult& result,
                                 const ProgressCallback& progress = {});

} // namespace tda
} // namespace pcl
