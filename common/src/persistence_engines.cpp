#include <pcl/tda/common/cohomology_persistence.h>
#include <pcl/tda/common/fast_incremental_persistence.h>
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/incremental_persistence.h>
#include <pcl/tda/common/persistence_engines.h>

namespace pcl {
namespace tda {

std::string
engineName (PersistenceEngine engine)
{
  switch (engine) {
  case PersistenceEngine::STANDARD:
    return "standard";
  case PersistenceEngine::INCREMENTAL:
    return "incremental";
  case PersistenceEngine::FAST_INCREMENTAL:
    return "fip";
  default:
    return "cohomology";
  }
}

std::vector<PersistenceEngine>
allEngines ()
{
  return {PersistenceEngine::STANDARD,
          PersistenceEngine::INCREMENTAL,
          PersistenceEngine::FAST_INCREMENTAL,
          PersistenceEngine::COHOMOLOGY};
}

bool
parseEngineName (const std::string& name, PersistenceEngine& engine)
{
  for (const PersistenceEngine candidate : allEngines())
    if (engineName (candidate) == name) {
      engine = candidate;
      return true;
    }
  return false;
}

void
addH1Persistence (const FilteredComplex& complex,
                  PersistenceEngine engine,
                  PersistenceResult& result,
                  const ProgressCallback& progress)
{
  switch (engine) {
  case PersistenceEngine::STANDARD:
    result = computeStandardReduction (complex, progress);
    break;
  case PersistenceEngine::INCREMENTAL:
    addIncrementalH1Persistence (complex, result);
    break;
  case PersistenceEngine::FAST_INCREMENTAL:
    addFastIncrementalH1Persistence (complex, result);
    break;
  default:
    addCohomologyH1Persistence (complex, result, progress);
  }
}

PersistenceResult
computePersistence (const FilteredComplex& complex,
                    PersistenceEngine engine,
                    const ProgressCallback& progress)
{
  if (engine == PersistenceEngine::STANDARD)
    return computeStandardReduction (complex, progress);
  PersistenceResult result = computeH0Persistence (complex);
  addH1Persistence (complex, engine, result, progress);
  return result;
}

} // namespace tda
} // namespace pcl
