#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/common/progress.h>

#include <array>
#include <string>

namespace pcl {
namespace tda {

/** \brief The persistence engines of PCL-TDA. All compute the same result on the
 * same FilteredComplex (H0 by union-find in all but STANDARD) and are swappable. */
enum class PersistenceEngine {
  /** Reduction of the whole boundary matrix (thesis Alg 2.1): the oracle. */
  STANDARD,
  /** Incremental persistence with a table of stored cycles (Alg 5.9-5.11). */
  INCREMENTAL,
  /** Fast incremental persistence for 1-cycles: cycle storage and cycle update
   * (Alg 5.12-5.14). */
  FAST_INCREMENTAL,
  /** Persistent cohomology of the edges with clearing and apparent pairs: the
   * fastest, and the default. */
  COHOMOLOGY
};

/** \brief The signature of every engine: completes \a result, the H0 persistence of
 * \a complex (computeH0Persistence()), with H1 (the standard engine recomputes
 * everything), reporting progress to \a progress when set. */
using H1PersistenceFunction = void (*) (const FilteredComplex& complex,
                                        PersistenceResult& result,
                                        const ProgressCallback& progress);

/** \brief One row of the engine table. */
struct PersistenceEngineEntry {
  PersistenceEngine engine;
  /** The engine's name on command lines. */
  const char* name;
  H1PersistenceFunction add_h1;
};

/** \brief The engine table, in the order of the enumeration (checked at compile
 * time): the one place that binds an engine to its name and its function. */
const std::array<PersistenceEngineEntry, 4>&
persistenceEngines ();

/** \brief The table's row of \a engine. */
const PersistenceEngineEntry&
engineEntry (PersistenceEngine engine);

/** \brief The engine's name on command lines: "standard", "incremental", "fip" or
 * "cohomology". */
std::string
engineName (PersistenceEngine engine);

/** \brief Parses an engine name of engineName().
 * \return false when \a name is none of them */
bool
parseEngineName (const std::string& name, PersistenceEngine& engine);

/** \brief Persistence of dimensions 0 and 1 (the whole result, max_dimension 1) by
 * \a engine.
 * \param[in] complex the filtered complex
 * \param[in] engine the engine (default: the fastest)
 * \param[in] progress optional callback (units of work done, total) of the H1 part
 */
PersistenceResult
computePersistence (const FilteredComplex& complex,
                    PersistenceEngine engine = PersistenceEngine::COHOMOLOGY,
                    const ProgressCallback& progress = {});

/** \brief Completes \a result, the H0 persistence of \a complex from
 * computeH0Persistence(), with H1 by \a engine, so that a caller can time or use H0
 * on its own first. */
void
addH1Persistence (const FilteredComplex& complex,
                  PersistenceEngine engine,
                  PersistenceResult& result,
                  const ProgressCallback& progress = {});

} // namespace tda
} // namespace pcl
