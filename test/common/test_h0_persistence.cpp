#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/standard_reduction.h>

#include <gtest/gtest.h>

#include "test_utils.h"

#include <tuple>

using namespace pcl::tda;

namespace {

std::vector<std::tuple<SimplexIndex, SimplexIndex, double>>
dimensionZeroPairs (const PersistenceResult& result)
{
  std::vector<std::tuple<SimplexIndex, SimplexIndex, double>> pairs;
  for (const auto& pair : result.pairs)
    if (pair.dimension == 0)
      pairs.emplace_back (pair.birth_simplex, pair.death_simplex, pair.death);
  std::sort (pairs.begin(), pairs.end());
  return pairs;
}

} // namespace

// The elder rule gives exactly the pairs (simplex ids and values) and the edge marks
// of the standard reduction.
TEST (H0Persistence, EqualsStandardReductionOnRandomComplexes)
{
  for (unsigned int k = 0; k < test::RANDOM_CASES; ++k) {
    const FilteredComplex complex = test::randomComplexCase (k);
    const PersistenceResult h0 = computeH0Persistence (complex);
    const PersistenceResult oracle = computeStandardReduction (complex);
    ASSERT_EQ (dimensionZeroPairs (h0), dimensionZeroPairs (oracle)) << "case " << k;
    ASSERT_EQ (h0.positive_edges, oracle.positive_edges) << "case " << k;
    EXPECT_TRUE (h0.positive_triangles.empty());
  }
}

// Points on a line at gaps 1, 3, 2: components die at the gap lengths, the
// negative edges form a spanning tree.
TEST (H0Persistence, PathGraphDiesAtGapLengths)
{
  const auto complex = FilteredComplex::fromLists (
      4, {{0, 1, 1.0}, {1, 2, 3.0}, {2, 3, 2.0}, {0, 2, 4.0}, {0, 3, 6.0}}, {});
  const PersistenceResult result = computeH0Persistence (complex);
  const PersistenceDiagram diagram = result.diagram();
  std::vector<double> deaths;
  for (const auto& interval : diagram)
    deaths.push_back (interval.death);
  std::sort (deaths.begin(), deaths.end());
  EXPECT_EQ (
      deaths,
      (std::vector<double>{1.0, 2.0, 3.0, std::numeric_limits<double>::infinity()}));
  EXPECT_EQ (
      std::count (result.positive_edges.begin(), result.positive_edges.end(), false),
      3);
  EXPECT_EQ (result.positive_edges,
             (std::vector<bool>{false, false, false, true, true}));
}

TEST (H0Persistence, IsolatedVerticesAreEssential)
{
  const auto complex = FilteredComplex::fromLists (5, {{1, 3, 0.5}}, {});
  const PersistenceDiagram diagram = computeH0Persistence (complex).diagram();
  EXPECT_EQ (
      std::count_if (diagram.begin(),
                     diagram.end(),
                     [] (const PersistenceInterval& i) { return i.isEssential(); }),
      4);
  EXPECT_EQ (diagram.size(), 5u);
}
