#include <pcl/tda/common/incremental_persistence.h>

#include "triangle_deaths.h"

namespace pcl {
namespace tda {

IncrementalCycleTable::IncrementalCycleTable (
    const FilteredComplex& complex, const std::vector<std::uint8_t>& edge_positive)
: complex_ (complex)
, edge_positive_ (edge_positive)
, cycles_ (complex.numEdges())
, deaths_ (complex.numEdges(), INVALID_SIMPLEX)
{}

SimplexIndex
IncrementalCycleTable::addTriangle (SimplexIndex triangle)
{
  CycleSet lambda = positiveBoundary (complex_, edge_positive_, triangle);
  while (!lambda.empty()) {
    const SimplexIndex youngest = lambda.back();
    if (!isOccupied (youngest)) {
      cycles_[youngest] = std::move (lambda);
      deaths_[youngest] = triangle;
      return youngest;
    }
    addCycle (lambda, cycles_[youngest], buffer_);
  }
  return INVALID_SIMPLEX;
}

void
addIncrementalH1Persistence (const FilteredComplex& complex,
                             PersistenceResult& result,
                             const ProgressCallback& progress)
{
  addH1ByCycleTable<IncrementalCycleTable> (complex, result, progress);
}

} // namespace tda
} // namespace pcl
