#include <pcl/tda/common/cohomology_persistence.h>
#include <pcl/tda/common/fast_incremental_persistence.h>
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/incremental_persistence.h>
#include <pcl/tda/common/persistence_engines.h>
#include <pcl/tda/common/standard_reduction.h>

#include <cstddef>

namespace pcl {
namespace tda {

namespace {

void
recomputeByStandardReduction (const FilteredComplex& complex,
                              PersistenceResult& result,
                              const ProgressCallback& progress)
{
  result = computeStandardReduction (complex, progress);
}

constexpr std::array<PersistenceEngineEntry, 4> ENGINES{{
    {PersistenceEngine::STANDARD, "standard", recomputeByStandardReduction},
    {PersistenceEngine::INCREMENTAL, "incremental", addIncrementalH1Persistence},
    {PersistenceEngine::FAST_INCREMENTAL, "fip", addFastIncrementalH1Persistence},
    {PersistenceEngine::COHOMOLOGY, "cohomology", addCohomologyH1Persistence},
}};

constexpr bool
tableFollowsEnumeration ()
{
  for (std::size_t k = 0; k < ENGINES.size(); ++k)
    if (static_cast<std::size_t> (ENGINES[k].engine) != k)
      return false;
  return static_cast<std::size_t> (PersistenceEngine::COHOMOLOGY) + 1 == ENGINES.size();
}
static_assert (tableFollowsEnumeration(),
               "the engine table must list every engine once, in enumeration order");

} // namespace

const std::array<PersistenceEngineEntry, 4>&
persistenceEngines ()
{
  return ENGINES;
}

const PersistenceEngineEntry&
engineEntry (PersistenceEngine engine)
{
  return ENGINES[static_cast<std::size_t> (engine)];
}

std::string
engineName (PersistenceEngine engine)
{
  return engineEntry (engine).name;
}

bool
parseEngineName (const std::string& name, PersistenceEngine& engine)
{
  for (const PersistenceEngineEntry& entry : ENGINES)
    if (name == entry.name) {
      engine = entry.engine;
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
  engineEntry (engine).add_h1 (complex, result, progress);
}

PersistenceResult
computePersistence (const FilteredComplex& complex,
                    PersistenceEngine engine,
                    const ProgressCallback& progress)
{
  PersistenceResult result = computeH0Persistence (complex);
  addH1Persistence (complex, engine, result, progress);
  return result;
}

} // namespace tda
} // namespace pcl
