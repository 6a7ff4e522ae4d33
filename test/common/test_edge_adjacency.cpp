#include <pcl/tda/common/edge_adjacency.h>

#include <gtest/gtest.h>

#include "test_utils.h"

#include <algorithm>
#include <set>

using namespace pcl::tda;

// The lists hold, per vertex, exactly the kept edges at it, by edge id.
TEST (EdgeAdjacency, ListsEqualBruteForceWithAndWithoutFilter)
{
  for (unsigned int k = 0; k < test::RANDOM_CASES; k += 3) {
    const FilteredComplex complex = test::randomComplexCase (k);
    const auto& edges = complex.edges();
    const EdgeFilter odd = [] (SimplexIndex e) { return e % 2 == 1; };
    for (const EdgeFilter& keep : {EdgeFilter{}, odd}) {
      const EdgeAdjacency adjacency =
          buildEdgeAdjacency (complex.numVertices(), edges, keep);
      ASSERT_EQ (adjacency.numVertices(), complex.numVertices());
      for (SimplexIndex v = 0; v < complex.numVertices(); ++v) {
        std::vector<std::pair<SimplexIndex, SimplexIndex>> expected, actual;
        for (SimplexIndex e = 0; e < edges.size(); ++e)
          if ((!keep || keep (e)) && (edges[e].source == v || edges[e].target == v))
            expected.emplace_back (
                edges[e].source == v ? edges[e].target : edges[e].source, e);
        for (const auto& entry : adjacency.neighbors (v))
          actual.emplace_back (entry.neighbor, entry.edge);
        ASSERT_EQ (actual, expected) << "case " << k << " vertex " << v;
      }
    }
  }
}

// The common neighbours of an edge's ends are those of a brute-force search.
TEST (EdgeAdjacency, CommonNeighborsEqualBruteForce)
{
  for (unsigned int k = 0; k < test::RANDOM_CASES; k += 3) {
    const FilteredComplex complex = test::randomComplexCase (k);
    const auto& edges = complex.edges();
    const EdgeAdjacency adjacency = buildEdgeAdjacency (complex.numVertices(), edges);
    CommonNeighborSearch search (edges, adjacency);
    for (SimplexIndex e = 0; e < edges.size(); ++e) {
      std::set<std::pair<SimplexIndex, SimplexIndex>> expected, actual;
      for (SimplexIndex a = 0; a < edges.size(); ++a)
        for (SimplexIndex b = 0; b < edges.size(); ++b) {
          if (a == e || b == e)
            continue;
          const auto other = [] (const FilteredEdge& edge, SimplexIndex v) {
            return edge.source == v   ? edge.target
                   : edge.target == v ? edge.source
                                      : INVALID_SIMPLEX;
          };
          const SimplexIndex w = other (edges[a], edges[e].source);
          if (w != INVALID_SIMPLEX && w == other (edges[b], edges[e].target))
            expected.emplace (a, b);
        }
      search.forEach (
          e, [&] (SimplexIndex uw, SimplexIndex vw) { actual.emplace (uw, vw); });
      ASSERT_EQ (actual, expected) << "case " << k << " edge " << e;
    }
  }
}
