#include <pcl/tda/common/betti_numbers.h>
#include <pcl/tda/common/persistence_engines.h>

#include <gtest/gtest.h>

#include "test_utils.h"

using namespace pcl::tda;

namespace {

/** Essential classes per dimension. */
std::array<std::size_t, 3>
essentialCounts (const PersistenceResult& result)
{
  std::array<std::size_t, 3> counts{0, 0, 0};
  for (const auto& pair : result.pairs)
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
  ASSERT_EQ (actual.positive_edges, expected.positive_edges) << what;
  ASSERT_EQ (actual.positive_triangles, expected.positive_triangles) << what;
  ASSERT_EQ (essentialCounts (actual), essentialCounts (expected)) << what;
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
  for (const PersistenceEngine engine : allEngines())
    expectSameResult (complex,
                      oracle,
                      computePersistence (complex, engine),
                      engineName (engine) + what);
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
  for (const PersistenceEngine engine : allEngines()) {
    PersistenceEngine parsed = PersistenceEngine::STANDARD;
    ASSERT_TRUE (parseEngineName (engineName (engine), parsed));
    EXPECT_EQ (parsed, engine);
  }
  PersistenceEngine unchanged = PersistenceEngine::INCREMENTAL;
  EXPECT_FALSE (parseEngineName ("ripser", unchanged));
  EXPECT_EQ (unchanged, PersistenceEngine::INCREMENTAL);
  EXPECT_EQ (engineName (PersistenceEngine::FAST_INCREMENTAL), "fip");
}
