#include <pcl/tda/common/phat_io.h>
#include <pcl/tda/common/standard_reduction.h>

#include <gtest/gtest.h>

#include "test_utils.h"
#include <phat/algorithms/standard_reduction.h>
#include <phat/algorithms/twist_reduction.h>
#include <phat/compute_persistence_pairs.h>
#include <phat/representations/default_representations.h>

#include <cstdio>
#include <limits>

using namespace pcl::tda;

namespace {

constexpr double INF = std::numeric_limits<double>::infinity();

std::size_t
countIntervals (const PersistenceDiagram& diagram,
                int dimension,
                double birth,
                double death)
{
  return std::count_if (
      diagram.begin(), diagram.end(), [&] (const PersistenceInterval& i) {
        return i.dimension == dimension && i.birth == birth && i.death == death;
      });
}

} // namespace

// Thesis Sec 2.5.2: three vertices and three edges: one component, one hole.
TEST (StandardReduction, HollowTriangleHasOneComponentAndOneHole)
{
  const auto complex =
      FilteredComplex::fromLists (3, {{0, 1, 1.0}, {0, 2, 1.0}, {1, 2, 1.0}}, {});
  const PersistenceResult result = computeStandardReduction (complex);
  const PersistenceDiagram diagram = result.diagram (complex);
  ASSERT_EQ (diagram.size(), 4u);
  EXPECT_EQ (countIntervals (diagram, 0, 0.0, 1.0), 2u);
  EXPECT_EQ (countIntervals (diagram, 0, 0.0, INF), 1u);
  EXPECT_EQ (countIntervals (diagram, 1, 1.0, INF), 1u);
  EXPECT_EQ (result.edge_positive, (std::vector<std::uint8_t>{0, 0, 1}));
  EXPECT_EQ (
      result.edge_killer,
      (std::vector<SimplexIndex>{INVALID_SIMPLEX, INVALID_SIMPLEX, INVALID_SIMPLEX}));
}

// Thesis Sec 2.8.2 (Fig 2.10-2.11): sigma_1..3 vertices, sigma_4 = 12, sigma_5 = 13,
// sigma_6 = 23, sigma_7 the triangle. Pairs (sigma_2, sigma_4), (sigma_3, sigma_5),
// (sigma_6, sigma_7); sigma_1 is essential.
TEST (StandardReduction, ThesisSevenSimplexFiltration)
{
  const auto complex = FilteredComplex::fromLists (
      3, {{0, 1, 1.0}, {0, 2, 3.0}, {1, 2, 3.0}}, {{0, 1, 2}});
  ASSERT_EQ (complex.numTriangles(), 1u);
  const PersistenceResult result = computeStandardReduction (complex);
  using Pair = std::pair<std::int64_t, std::int64_t>;
  EXPECT_EQ (test::globalPairs (complex, result),
             (std::vector<Pair>{{1, 3}, {2, 4}, {5, 6}}));
  const std::vector<PersistencePair> pairs = result.pairs (complex);
  ASSERT_EQ (pairs.size(), 4u);
  EXPECT_EQ (std::count_if (pairs.begin(),
                            pairs.end(),
                            [] (const PersistencePair& pair) {
                              return pair.isEssential() && pair.dimension == 0 &&
                                     pair.birth_simplex == 0u;
                            }),
             1);
  // The dense form: vertex 1 dies by edge 0, vertex 2 by edge 1, edge 2 by the
  // triangle.
  EXPECT_EQ (result.vertex_killer, (std::vector<SimplexIndex>{INVALID_SIMPLEX, 0, 1}));
  EXPECT_EQ (result.edge_killer,
             (std::vector<SimplexIndex>{INVALID_SIMPLEX, INVALID_SIMPLEX, 0}));
  EXPECT_EQ (result.triangle_positive, (std::vector<std::uint8_t>{0}));
  // With our vertex values (all 0) the intervals are [0,1), [0,3) in H0 and the
  // H1 pair (sigma_6, sigma_7) has length 0 here: both enter at 3.
  const PersistenceDiagram diagram = result.diagram (complex);
  EXPECT_EQ (countIntervals (diagram, 0, 0.0, 1.0), 1u);
  EXPECT_EQ (countIntervals (diagram, 0, 0.0, 3.0), 1u);
  EXPECT_EQ (countIntervals (diagram, 1, 3.0, 3.0), 0u);
  EXPECT_EQ (diagram.size(), 3u);
}

// The same pairs as PHAT's standard and twist reductions on the very matrix we write,
// read by PHAT's own loaders.
TEST (StandardReduction, EqualsPHATOnRandomComplexes)
{
  const std::string path = testing::TempDir() + "standard_reduction_phat.mat";
  for (unsigned int k = 0; k < test::RANDOM_CASES; ++k) {
    const FilteredComplex complex = test::randomComplexCase (k);
    const PersistenceResult result = computeStandardReduction (complex);

    const bool binary = k % 2 == 1;
    savePHATBoundaryMatrix (
        path, complex, binary ? PHATFormat::BINARY : PHATFormat::ASCII);
    // Not PHAT's default bit_tree_pivot_column: it negates INT64_MIN,
    // which UndefinedBehaviorSanitizer rejects.
    phat::boundary_matrix<phat::vector_vector> matrix;
    ASSERT_TRUE (binary ? matrix.load_binary (path) : matrix.load_ascii (path));
    phat::persistence_pairs standard_pairs, twist_pairs;
    phat::compute_persistence_pairs<phat::standard_reduction> (standard_pairs, matrix);
    phat::compute_persistence_pairs<phat::twist_reduction> (twist_pairs, matrix);
    standard_pairs.sort();
    twist_pairs.sort();
    const auto ours = test::globalPairs (complex, result);
    ASSERT_EQ (static_cast<std::size_t> (standard_pairs.get_num_pairs()), ours.size())
        << "case " << k;
    ASSERT_TRUE (standard_pairs == twist_pairs) << "case " << k;
    for (std::size_t p = 0; p < ours.size(); ++p)
      ASSERT_EQ (standard_pairs.get_pair (p), ours[p]) << "case " << k << " pair " << p;

    // Essential classes: every simplex that is neither a birth nor a death of a pair;
    // those of dimension 2 are the positive triangles.
    const std::vector<PersistencePair> pairs = result.pairs (complex);
    const std::size_t essential =
        std::count_if (pairs.begin(), pairs.end(), [] (const auto& pair) {
          return pair.isEssential();
        });
    const std::size_t positive_triangles = std::count (
        result.triangle_positive.begin(), result.triangle_positive.end(), 1);
    EXPECT_EQ (essential + positive_triangles, complex.numSimplices() - 2 * ours.size())
        << "case " << k;
  }
  std::remove (path.c_str());
}

TEST (StandardReduction, ReportsProgress)
{
  const FilteredComplex complex = test::randomComplexCase (4);
  std::size_t last_done = 0, calls = 0;
  computeStandardReduction (complex, [&] (std::size_t done, std::size_t total) {
    EXPECT_EQ (total, complex.numSimplices());
    EXPECT_GE (done, last_done);
    last_done = done;
    ++calls;
  });
  EXPECT_GT (calls, 0u);
  EXPECT_EQ (last_done, complex.numSimplices());
}
