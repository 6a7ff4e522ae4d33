#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/spanning_forest.h>

#include <gtest/gtest.h>

#include "test_utils.h"

#include <algorithm>
#include <random>

using namespace pcl::tda;

namespace {

/** A random graph with many equal edge values, and more edges than Filter-Kruskal's
 * base case, so that the filtering recursion runs. */
std::vector<FilteredEdge>
randomGraph (std::mt19937& random, std::size_t num_vertices, std::size_t num_edges)
{
  std::uniform_int_distribution<SimplexIndex> vertex (0, num_vertices - 1);
  std::uniform_int_distribution<int> value (0, 50);
  std::vector<FilteredEdge> edges;
  std::vector<std::uint64_t> seen;
  while (edges.size() < num_edges) {
    SimplexIndex a = vertex (random), b = vertex (random);
    if (a == b)
      continue;
    if (a > b)
      std::swap (a, b);
    const std::uint64_t key = (std::uint64_t{a} << 32) | b;
    if (std::find (seen.begin(), seen.end(), key) != seen.end())
      continue;
    seen.push_back (key);
    edges.push_back ({a, b, value (random) / 10.0});
  }
  return edges;
}

} // namespace

// The forest is exactly the set of negative edges of the elder rule on the graph's
// filtration (ties broken by the filtration order), in filtration order.
TEST (SpanningForest, EqualsNegativeEdgesOfH0)
{
  std::mt19937 random (7);
  for (unsigned int k = 0; k < 40; ++k) {
    const std::size_t n = 20 + k * 40;
    std::vector<FilteredEdge> edges =
        randomGraph (random, n, std::min<std::size_t> (n * (n - 1) / 2, 6 * n));
    std::vector<FilteredEdge> sorted = edges;
    std::sort (sorted.begin(), sorted.end(), edgeFiltrationLess);
    const FilteredComplex complex (n, sorted, {});
    const PersistenceResult h0 = computeH0Persistence (complex);
    std::vector<FilteredEdge> expected;
    for (const SimplexIndex e : h0.negativeEdges())
      expected.push_back (sorted[e]);

    std::shuffle (edges.begin(), edges.end(), random);
    const std::vector<FilteredEdge> forest = minimumSpanningForest (n, edges);
    ASSERT_EQ (forest.size(), expected.size()) << "case " << k;
    for (std::size_t i = 0; i < forest.size(); ++i) {
      ASSERT_EQ (forest[i].source, expected[i].source) << "case " << k << " edge " << i;
      ASSERT_EQ (forest[i].target, expected[i].target) << "case " << k << " edge " << i;
      ASSERT_EQ (forest[i].value, expected[i].value) << "case " << k << " edge " << i;
    }
  }
}

TEST (SpanningForest, EmptyAndEdgelessGraphs)
{
  std::vector<FilteredEdge> none;
  EXPECT_TRUE (minimumSpanningForest (0, none).empty());
  EXPECT_TRUE (minimumSpanningForest (5, none).empty());
  std::vector<FilteredEdge> one{{0, 1, 2.0}};
  const auto forest = minimumSpanningForest (3, one);
  ASSERT_EQ (forest.size(), 1u);
  EXPECT_EQ (forest[0].value, 2.0);
}
