#include <pcl/tda/common/fast_incremental_persistence.h>

#include "triangle_deaths.h"

#include <stdexcept>

namespace pcl {
namespace tda {

FastIncrementalCycleTable::FastIncrementalCycleTable (
    const FilteredComplex& complex, const std::vector<std::uint8_t>& edge_positive)
: complex_ (complex)
, edge_positive_ (edge_positive)
, cycles_ (complex.numEdges())
, updates_ (complex.numEdges())
, deaths_ (complex.numEdges(), INVALID_SIMPLEX)
, visited_ (complex.numEdges(), 0)
{}

SimplexIndex
FastIncrementalCycleTable::addTriangle (SimplexIndex triangle)
{
  const CycleSet lambda = positiveBoundary (complex_, edge_positive_, triangle);
  if (lambda.empty())
    return INVALID_SIMPLEX;
  const SimplexIndex youngest = lambda.back();

  // Lambda^c: every element but the youngest, an occupied one replaced by its cycle.
  CycleSet lambda_c;
  built_from_.clear();
  for (std::size_t n = 0; n + 1 < lambda.size(); ++n) {
    const SimplexIndex edge = lambda[n];
    if (!isOccupied (edge))
      addCycle (lambda_c, {edge}, buffer_);
    else if (!cycles_[edge].empty())
      addCycle (lambda_c, cycles_[edge], buffer_);
    else
      continue;
    built_from_.push_back (edge);
  }

  if (!isOccupied (youngest)) { // case 1
    store (youngest, std::move (lambda_c), triangle, built_from_);
    return youngest;
  }
  // Case 2: one more addition, with the cycle stored at the youngest edge.
  addCycle (lambda_c, cycles_[youngest], buffer_);
  if (lambda_c.empty())
    return INVALID_SIMPLEX;
  const SimplexIndex killed = lambda_c.back();
  if (isOccupied (killed)) // the Cycle Storage-Update Lemma says it is free
    throw std::logic_error ("fast incremental persistence: a stored cycle holds an "
                            "occupied edge");
  lambda_c.pop_back();
  built_from_.assign (lambda_c.begin(), lambda_c.end());
  store (killed, std::move (lambda_c), triangle, built_from_);
  return killed;
}

void
FastIncrementalCycleTable::store (SimplexIndex edge,
                                  CycleSet cycle,
                                  SimplexIndex triangle,
                                  const std::vector<SimplexIndex>& built_from)
{
  for (const SimplexIndex source : built_from)
    updates_[source].push_back (edge);
  cycles_[edge] = std::move (cycle);
  deaths_[edge] = triangle;
  updateCycles (edge);
}

void
FastIncrementalCycleTable::updateCycles (SimplexIndex edge)
{
  // The substitute of edge: edge + its cycle, both sides of a boundary.
  substitute_ = cycles_[edge];
  substitute_.push_back (edge);
  ++generation_;
  stack_.assign (updates_[edge].begin(), updates_[edge].end());
  while (!stack_.empty()) {
    const SimplexIndex slot = stack_.back();
    stack_.pop_back();
    if (visited_[slot] == generation_)
      continue;
    visited_[slot] = generation_;
    if (containsSimplex (cycles_[slot], edge))
      addCycle (cycles_[slot], substitute_, buffer_);
    stack_.insert (stack_.end(), updates_[slot].begin(), updates_[slot].end());
  }
}

void
addFastIncrementalH1Persistence (const FilteredComplex& complex,
                                 PersistenceResult& result,
                                 const ProgressCallback& progress)
{
  addH1ByCycleTable<FastIncrementalCycleTable> (complex, result, progress);
}

} // namespace tda
} // namespace pcl
