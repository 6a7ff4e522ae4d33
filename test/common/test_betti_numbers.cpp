#include <pcl/tda/common/betti_numbers.h>
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/standard_reduction.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include "test_utils.h"

#include <bitset>
#include <limits>

using namespace pcl::tda;

namespace {

/** Rank over Z2 of a matrix given by its columns (bitsets of row indices), by
 * Gaussian elimination: an oracle independent of any persistence algorithm. */
std::int64_t
rankOverZ2 (std::vector<std::bitset<256>> columns)
{
  std::int64_t rank = 0;
  for (std::size_t row = 0; row < 256; ++row) {
    auto pivot = std::find_if (
        columns.begin(), columns.end(), [&] (const auto& c) { return c.test (row); });
    if (pivot == columns.end())
      continue;
    const auto pivot_column = *pivot;
    columns.erase (pivot);
    for (auto& column : columns)
      if (column.test (row))
        column ^= pivot_column;
    ++rank;
  }
  return rank;
}

/** Betti numbers of the first \a length simplices of the filtration, from the ranks
 * of the boundary matrices: beta_k = n_k - rank d_k - rank d_(k+1). */
BettiNumbers
bettiNumbersByRanks (const FilteredComplex& complex, std::size_t length)
{
  const auto order = complex.filtrationOrder();
  std::int64_t count[3] = {0, 0, 0};
  std::vector<std::bitset<256>> boundary1, boundary2;
  for (std::size_t g = 0; g < length; ++g) {
    const SimplexRef s = order[g];
    ++count[s.dimension];
    std::bitset<256> column;
    if (s.dimension == 1) {
      column.set (complex.edges()[s.index].source);
      column.set (complex.edges()[s.index].target);
      boundary1.push_back (column);
    }
    else if (s.dimension == 2) {
      for (const auto e : complex.triangles()[s.index].edges)
        column.set (e);
      boundary2.push_back (column);
    }
  }
  const std::int64_t rank1 = rankOverZ2 (boundary1), rank2 = rankOverZ2 (boundary2);
  return {count[0] - rank1, count[1] - rank1 - rank2, count[2] - rank2};
}

} // namespace

TEST (BettiNumbers, PrefixesEqualRanksOfBoundaryMatrices)
{
  for (unsigned int k = 0; k < test::RANDOM_CASES; ++k) {
    const FilteredComplex complex = test::randomComplexCase (k);
    ASSERT_LE (complex.numEdges(), 256u);
    const auto prefixes =
        computePrefixBettiNumbers (complex, computeStandardReduction (complex));
    ASSERT_EQ (prefixes.size(), complex.numSimplices());
    // Check a spread of prefixes: every 7th, and the whole complex.
    for (std::size_t length = 1; length <= prefixes.size(); length += 7)
      ASSERT_EQ (prefixes[length - 1], bettiNumbersByRanks (complex, length))
          << "case " << k << " prefix " << length;
    ASSERT_EQ (prefixes.back(), bettiNumbersByRanks (complex, prefixes.size()));
  }
}

TEST (BettiNumbers, AtRadiusEqualsPrefixEndingThere)
{
  for (unsigned int k = 0; k < 200; ++k) {
    const FilteredComplex complex = test::randomComplexCase (k);
    const PersistenceResult result = computeStandardReduction (complex);
    const auto prefixes = computePrefixBettiNumbers (complex, result);
    const auto order = complex.filtrationOrder();
    for (std::size_t g = 0; g < order.size(); ++g) {
      const double radius = complex.value (order[g]);
      if (g + 1 < order.size() && complex.value (order[g + 1]) == radius)
        continue; // the subcomplex at a radius ends after its last simplex of that
                  // value
      ASSERT_EQ (computeBettiNumbersAt (complex, result, radius), prefixes[g]);
    }
  }
}

// Thesis Sec 5.2.3: on the filter of Fig 5.2, edges be, ac, ce, bc are positive,
// triangles bce, ace, abc, acd negative (abe closes a 2-cycle) and beta_1 = 4 - 4 = 0.
TEST (BettiNumbers, ThesisFigure52Filter)
{
  const FilteredComplex complex = test::figure52Filter();
  const PersistenceResult result = computeStandardReduction (complex);
  EXPECT_EQ (result.edge_positive, (std::vector<std::uint8_t>{0, 0, 1, 0, 0, 1, 1, 1}));
  EXPECT_EQ (result.triangle_positive, (std::vector<std::uint8_t>{0, 0, 0, 0, 1}));
  const auto prefixes = computePrefixBettiNumbers (complex, result);
  EXPECT_EQ (prefixes.back(), (BettiNumbers{1, 0, 1}));
  EXPECT_EQ (prefixes[12], (BettiNumbers{1, 4, 0})); // all edges in: four holes
  // The pairs of Sec 5.2.3: (bc, bce), (ce, ace), (be, abc), (ac, acd).
  using Pair = std::pair<std::int64_t, std::int64_t>;
  const auto pairs = test::globalPairs (complex, result);
  for (const Pair& expected : {Pair{12, 13}, Pair{11, 14}, Pair{7, 15}, Pair{10, 16}})
    EXPECT_NE (std::find (pairs.begin(), pairs.end(), expected), pairs.end())
        << expected.first << " " << expected.second;
}

TEST (BettiNumbers, RefusesResultWithoutTriangleMarks)
{
  EXPECT_THROW (
      computePrefixBettiNumbers (test::figure52Filter(),
                                 computeH0Persistence (test::figure52Filter())),
      pcl::BadArgumentException);
  const FilteredComplex complex = test::figure52Filter();
  PersistenceResult h0_only = computeStandardReduction (complex);
  h0_only.triangle_positive.clear();
  EXPECT_THROW (computePrefixBettiNumbers (complex, h0_only),
                pcl::BadArgumentException);
  EXPECT_THROW (computeBettiNumbersAt (complex, h0_only, 1.0),
                pcl::BadArgumentException);
  // A NaN radius is no radius (it gave the vertices alone).
  EXPECT_THROW (computeBettiNumbersAt (complex,
                                       computeStandardReduction (complex),
                                       std::numeric_limits<double>::quiet_NaN()),
                pcl::BadArgumentException);
}
