#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/standard_reduction.h>

#include <gtest/gtest.h>

#include "test_utils.h"

#include <tuple>

using namespace pcl::tda;

namespace {

std::vector<std::tuple<SimplexIndex, SimplexIndex, double>>
dimensionZeroPairs (const FilteredComplex& complex, const PersistenceResult& result)
{
  std::vector<std::tuple<SimplexIndex, SimplexIndex, double>> pairs;
  for (const auto& pair : result.pairs (complex))
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
    ASSERT_EQ (dimensionZeroPairs (complex, h0), dimensionZeroPairs (complex, oracle))
        << "case " << k;
    ASSERT_EQ (h0.vertex_killer, oracle.vertex_killer) << "case " << k;
    ASSERT_EQ (h0.edge_positive, oracle.edge_positive) << "case " << k;
    EXPECT_EQ (h0.max_dimension, 0);
    EXPECT_TRUE (h0.edge_killer.empty());
    EXPECT_TRUE (h0.triangle_positive.empty());
  }
}

// Points on a line at gaps 1, 3, 2: components die at the gap lengths, the
// negative edges form a spanning tree.
TEST (H0Persistence, PathGraphDiesAtGapLengths)
{
  const auto complex = FilteredComplex::fromLists (
      4, {{0, 1, 1.0}, {1, 2, 3.0}, {2, 3, 2.0}, {0, 2, 4.0}, {0, 3, 6.0}}, {});
  const PersistenceResult result = computeH0Persistence (complex);
  const PersistenceDiagram diagram = result.diagram (complex);
  std::vector<double> deaths;
  for (const auto& interval : diagram)
    deaths.push_back (interval.death);
  std::sort (deaths.begin(), deaths.end());
  EXPECT_EQ (
      deaths,
      (std::vector<double>{1.0, 2.0, 3.0, std::numeric_limits<double>::infinity()}));
  EXPECT_EQ (std::count (result.edge_positive.begin(), result.edge_positive.end(), 0),
             3);
  EXPECT_EQ (result.negativeEdges(), (std::vector<SimplexIndex>{0, 1, 2}));
  // Edges in filtration order: 01, 23, 12, 02, 03. Vertex 1 dies by 01 (length 1),
  // 3 by 23 (2), 2 by 12 (3), the younger oldest vertex of {2, 3}; 0 lives on.
  EXPECT_EQ (result.vertex_killer,
             (std::vector<SimplexIndex>{INVALID_SIMPLEX, 0, 2, 1}));
  EXPECT_EQ (result.edge_positive, (std::vector<std::uint8_t>{0, 0, 0, 1, 1}));
}

TEST (H0Persistence, IsolatedVerticesAreEssential)
{
  const auto complex = FilteredComplex::fromLists (5, {{1, 3, 0.5}}, {});
  const PersistenceDiagram diagram = computeH0Persistence (complex).diagram (complex);
  EXPECT_EQ (
      std::count_if (diagram.begin(),
                     diagram.end(),
                     [] (const PersistenceInterval& i) { return i.isEssential(); }),
      4);
  EXPECT_EQ (diagram.size(), 5u);
}
