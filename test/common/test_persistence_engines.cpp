#include <pcl/tda/common/betti_numbers.h>
#include <pcl/tda/common/persistence_engines.h>

#include <gtest/gtest.h>

#include "test_utils.h"

using namespace pcl::tda;

namespace {

/** Essential classes per dimension. */
std::array<std::size_t, 3>
essentialCounts (const FilteredComplex& complex, const PersistenceResult& result)
{
  std::array<std::size_t, 3> counts{0, 0, 0};
  for (const auto& pair : result.pairs (complex))
    if (pair.isEssential())
      ++counts[pair.dimension];
  return counts;
}

void
expectSameResult (const FilteredComplex& complex,
                  const PersistenceResult& expected,
                  const PersistenceResult& actual,
                  const std::string& what)
{
  ASSERT_EQ (test::globalPairs (complex, actual), test::globalPairs (complex, expected))
      << what;
  ASSERT_EQ (actual.vertex_killer, expected.vertex_killer) << what;
  ASSERT_EQ (actual.edge_positive, expected.edge_positive) << what;
  ASSERT_EQ (actual.edge_killer, expected.edge_killer) << what;
  ASSERT_EQ (actual.triangle_positive, expected.triangle_positive) << what;
  ASSERT_EQ (actual.max_dimension, 1) << what;
  ASSERT_EQ (essentialCounts (complex, actual), essentialCounts (complex, expected))
      << what;
  ASSERT_EQ (computePrefixBettiNumbers (complex, actual),
             computePrefixBettiNumbers (complex, expected))
      << what;
}

/** Every engine's result on \a complex equals the standard reduction's. */
void
expectAllEnginesEqualStandard (const FilteredComplex& complex, const std::string& what)
{
  const PersistenceResult oracle =
      computePersistence (complex, PersistenceEngine::STANDARD);
  for (const PersistenceEngineEntry& entry : persistenceEngines())
    expectSameResult (
        complex, oracle, computePersistence (complex, entry.engine), entry.name + what);
}

} // namespace

// Every engine pairs exactly the simplices the standard reduction pairs, on random
// complexes with many ties of filtration values.
TEST (PersistenceEngines, EqualStandardReductionOnRandomComplexes)
{
  for (unsigned int k = 0; k < test::RANDOM_CASES; ++k) {
    expectAllEnginesEqualStandard (test::randomComplexCase (k),
                                   " case " + std::to_string (k));
  }
}

// Larger random complexes: longer cycles, longer update chains.
TEST (PersistenceEngines, EqualStandardReductionOnLargerRandomComplexes)
{
  std::mt19937 random (99);
  for (unsigned int k = 0; k < 60; ++k) {
    expectAllEnginesEqualStandard (test::randomComplex (random, k % 2 == 0, true, 60),
                                   " large case " + std::to_string (k));
  }
}

TEST (PersistenceEngines, NamesRoundTrip)
{
  for (const PersistenceEngineEntry& entry : persistenceEngines()) {
    PersistenceEngine parsed = PersistenceEngine::STANDARD;
    ASSERT_TRUE (parseEngineName (entry.name, parsed));
    EXPECT_EQ (parsed, entry.engine);
    EXPECT_EQ (&engineEntry (entry.engine), &entry);
  }
  PersistenceEngine unchanged = PersistenceEngine::INCREMENTAL;
  EXPECT_FALSE (parseEngineName ("ripser", unchanged));
  EXPECT_EQ (unchanged, PersistenceEngine::INCREMENTAL);
  EXPECT_EQ (engineName (PersistenceEngine::FAST_INCREMENTAL), "fip");
}

// Every engine reports its H1 progress, ending at the total.
TEST (PersistenceEngines, ReportProgress)
{
  std::mt19937 random (5);
  const FilteredComplex complex = test::randomComplex (random, false, true, 40);
  ASSERT_GT (complex.numTriangles(), 0u);
  for (const PersistenceEngineEntry& entry : persistenceEngines()) {
    std::size_t last_done = 0, last_total = 0, calls = 0;
    computePersistence (
        complex, entry.engine, [&] (std::size_t done, std::size_t total) {
          EXPECT_GE (done, last_done) << entry.name;
          last_done = done;
          last_total = total;
          ++calls;
        });
    EXPECT_GT (calls, 0u) << entry.name;
    EXPECT_EQ (last_done, last_total) << entry.name;
  }
}
