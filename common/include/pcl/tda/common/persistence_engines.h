#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_diagram.h>
#include <pcl/tda/common/standard_reduction.h>

#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The persistence engines of PCL-TDA. All compute the same pairs on the
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

/** \brief The engine's name on command lines: "standard", "incremental", "fip" or
 * "cohomology". */
std::string
engineName (PersistenceEngine engine);

/** \brief All engines, in the order of the enumeration. */
std::vector<PersistenceEngine>
allEngines ();

/** \brief Parses an engine name of engineName().
 * \return false when \a name is none of them */
bool
parseEngineName (const std::string& name, PersistenceEngine& engine);

/** \brief Persistence pairs of dimensions 0 and 1, essential classes of dimensions
 * 0 and 1 and positive/negative marks of all edges and triangles, by \a engine.
 * \param[in] complex the filtered complex
 * \param[in] engine the engine (default: the fastest)
 * \param[in] progress optional callback (units of work done, total)
 */
PersistenceResult
computePersistence (const FilteredComplex& complex,
                    PersistenceEngine engine = PersistenceEngine::COHOMOLOGY,
                    const ProgressCallback& progress = {});

/** \brief Completes \a result, the H0 persistence of \a complex from
 * computeH0Persistence(), with H1 by \a engine (the STANDARD engine recomputes
 * everything), so that a caller can time or use H0 on its own first. */
void
addH1Persistence (const FilteredComplex& complex,
                  PersistenceEngine engine,
                  PersistenceResult& result,
                  const ProgressCallback& progress = {});

} // namespace tda
} // namespace pcl
