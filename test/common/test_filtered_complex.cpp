#include <pcl/tda/common/filtered_complex.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include "test_utils.h"

using namespace pcl::tda;

TEST (FilteredComplex, FromListsSortsEdgesAndTriangles)
{
  const auto complex = FilteredComplex::fromLists (
      4, {{2, 1, 0.5}, {0, 1, 0.2}, {0, 2, 0.5}, {2, 3, 0.1}}, {{2, 0, 1}});
  ASSERT_EQ (complex.numEdges(), 4u);
  EXPECT_EQ (complex.edges()[0].source, 2u);
  EXPECT_EQ (complex.edges()[0].target, 3u);
  EXPECT_EQ (complex.edges()[1].value, 0.2);
  // Ties are broken by (source, target): (0, 2) before (1, 2).
  EXPECT_EQ (complex.edges()[2].source, 0u);
  EXPECT_EQ (complex.edges()[3].source, 1u);
  ASSERT_EQ (complex.numTriangles(), 1u);
  const std::array<SimplexIndex, 3> expected_edges{3, 2, 1};
  EXPECT_EQ (complex.triangles()[0].edges, expected_edges);
  EXPECT_EQ (complex.triangles()[0].value, 0.5);
  const std::array<SimplexIndex, 3> expected_vertices{0, 1, 2};
  EXPECT_EQ (complex.triangleVertices (0), expected_vertices);
  EXPECT_EQ (complex.numSimplices(), 9u);
}

TEST (FilteredComplex, FiltrationOrderPutsFacesFirst)
{
  for (unsigned int k = 0; k < test::RANDOM_CASES; ++k) {
    const FilteredComplex complex = test::randomComplexCase (k);
    const auto order = complex.filtrationOrder();
    ASSERT_EQ (order.size(), complex.numSimplices());
    std::vector<std::size_t> edge_position (complex.numEdges());
    double previous = 0.0;
    for (std::size_t g = 0; g < order.size(); ++g) {
      const double value = complex.value (order[g]);
      ASSERT_GE (value, previous) << "case " << k;
      previous = value;
      if (order[g].dimension == 0) {
        ASSERT_EQ (order[g].index, g);
      }
      if (order[g].dimension == 1) {
        edge_position[order[g].index] = g;
        if (order[g].index > 0) {
          ASSERT_GT (g, edge_position[order[g].index - 1]);
        }
      }
      if (order[g].dimension == 2) {
        for (const auto e : complex.triangles()[order[g].index].edges)
          ASSERT_LT (edge_position[e], g) << "case " << k;
      }
    }
  }
}

TEST (FilteredComplex, RejectsInvalidLists)
{
  EXPECT_THROW (FilteredComplex::fromLists (3, {{0, 0, 1.0}}, {}),
                pcl::BadArgumentException);
  EXPECT_THROW (FilteredComplex::fromLists (3, {{0, 3, 1.0}}, {}),
                pcl::BadArgumentException);
  EXPECT_THROW (FilteredComplex::fromLists (3, {{0, 1, 1.0}, {1, 0, 2.0}}, {}),
                pcl::BadArgumentException);
  EXPECT_THROW (FilteredComplex::fromLists (3, {{0, 1, -1.0}}, {}),
                pcl::BadArgumentException);
  EXPECT_THROW (FilteredComplex::fromLists (3, {{0, 1, std::nan ("")}}, {}),
                pcl::BadArgumentException);
  EXPECT_THROW (FilteredComplex::fromLists (3, {{0, 1, 1.0}, {1, 2, 1.0}}, {{0, 1, 2}}),
                pcl::BadArgumentException);
  EXPECT_THROW (FilteredComplex::fromLists (
                    3, {{0, 1, 1.0}, {1, 2, 1.0}, {0, 2, 1.0}}, {{0, 1, 2}, {2, 1, 0}}),
                pcl::BadArgumentException);
}

TEST (FilteredComplex, RejectsPartsOutOfOrder)
{
  EXPECT_THROW (FilteredComplex (3, {{1, 2, 0.5}, {0, 1, 0.2}}, {}),
                pcl::BadArgumentException);
  // A triangle whose edges do not close.
  EXPECT_THROW (
      FilteredComplex (4, {{0, 1, 0.1}, {1, 2, 0.2}, {2, 3, 0.3}}, {{{2, 1, 0}, 0.3}}),
      pcl::BadArgumentException);
  // A triangle entering before its youngest edge.
  EXPECT_THROW (
      FilteredComplex (3, {{0, 1, 0.1}, {1, 2, 0.2}, {0, 2, 0.3}}, {{{2, 1, 0}, 0.25}}),
      pcl::BadArgumentException);
  EXPECT_THROW (FilteredComplex (2, {{0, 1, 0.1}}, {}, {7}), pcl::BadArgumentException);
  EXPECT_NO_THROW (
      FilteredComplex (3, {{0, 1, 0.1}, {1, 2, 0.2}, {0, 2, 0.3}}, {{{2, 1, 0}, 0.3}}));
}
