#include <pcl/tda/search/youngest_edge_triangles.h>

#include <gtest/gtest.h>

#include "common/test_utils.h"

#include <algorithm>
#include <map>
#include <set>

using namespace pcl::tda;

namespace {

using EdgePairs =
    std::map<SimplexIndex, std::set<std::pair<SimplexIndex, SimplexIndex>>>;

/** Per edge e kept by \a keep, the pairs (min, max) of kept edges {uw, vw} older than
 * e that close a triangle with it, by testing every pair of edges. */
EdgePairs
bruteForceYoungestTriangles (const std::vector<FilteredEdge>& edges,
                             const EdgeFilter& keep)
{
  const auto kept = [&keep] (SimplexIndex e) { return !keep || keep (e); };
  const auto other = [] (const FilteredEdge& edge, SimplexIndex v) {
    return edge.source == v   ? edge.target
           : edge.target == v ? edge.source
                              : INVALID_SIMPLEX;
  };
  EdgePairs pairs;
  for (SimplexIndex e = 0; e < edges.size(); ++e) {
    if (!kept (e))
      continue;
    pairs[e];
    for (SimplexIndex a = 0; a < e; ++a)
      for (SimplexIndex b = 0; b < e; ++b) {
        if (a == b || !kept (a) || !kept (b))
          continue;
        const SimplexIndex w = other (edges[a], edges[e].source);
        if (w != INVALID_SIMPLEX && w == other (edges[b], edges[e].target))
          pairs[e].emplace (std::min (a, b), std::max (a, b));
      }
  }
  return pairs;
}

} // namespace

// Every kept edge is visited once, with exactly the triangles whose youngest edge it
// is, on random complexes with ties, with and without a filter, on 1 to 3 threads;
// the count returned is their number.
TEST (YoungestEdgeTriangles, EqualBruteForce)
{
  for (unsigned int k = 0; k < test::RANDOM_CASES; k += 3) {
    const FilteredComplex complex = test::randomComplexCase (k);
    const auto& edges = complex.edges();
    const EdgeFilter odd = [] (SimplexIndex e) { return e % 2 == 1; };
    for (const EdgeFilter& keep : {EdgeFilter{}, odd}) {
      const EdgePairs expected = bruteForceYoungestTriangles (edges, keep);
      std::size_t expected_count = 0;
      for (const auto& [edge, triangles] : expected)
        expected_count += triangles.size();
      const EdgeAdjacency adjacency =
          buildEdgeAdjacency (complex.numVertices(), edges, keep);
      for (unsigned int threads = 1; threads <= 3; ++threads) {
        EdgePairs actual;
        std::map<SimplexIndex, int> visits;
        const std::uint64_t count = forEachEdgeWithYoungestTriangles (
            adjacency, threads, {}, [&] (SimplexIndex e, const auto& triangles) {
#pragma omp critical
              {
                ++visits[e];
                actual[e];
                triangles ([&] (SimplexIndex uw, SimplexIndex vw) {
                  ASSERT_TRUE (
                      actual[e].emplace (std::min (uw, vw), std::max (uw, vw)).second)
                      << "a triangle found twice";
                });
              }
            });
        ASSERT_EQ (actual, expected) << "case " << k << ", " << threads << " threads";
        ASSERT_EQ (count, expected_count) << "case " << k;
        for (const auto& [edge, times] : visits)
          ASSERT_EQ (times, 1) << "case " << k << " edge " << edge;
      }
    }
  }
}
