#include <pcl/tda/common/coboundary_reduction.h>
#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/search/clique_persistence.h>
#include <pcl/tda/search/youngest_edge_triangles.h>

#include <algorithm>
#include <limits>
#include <unordered_map>
#include <utility>

namespace pcl {
namespace tda {

namespace {

/** A triangle of a clique complex named by its youngest and middle edges: keys
 * sort as the filtration orders triangles (by value, then edges). */
using TriangleKey = std::uint64_t;

TriangleKey
triangleKey (SimplexIndex youngest, SimplexIndex middle)
{
  return (static_cast<TriangleKey> (youngest) << 32) | middle;
}

SimplexIndex
youngestEdge (TriangleKey triangle)
{
  return static_cast<SimplexIndex> (triangle >> 32);
}

SimplexIndex
middleEdge (TriangleKey triangle)
{
  return static_cast<SimplexIndex> (triangle & 0xffffffffu);
}

/** The apparent pairs of a clique complex, found in one parallel pass. */
struct ApparentPairs {
  /** Per edge: for a positive edge that is the youngest edge of some triangle, the
   * middle edge of the oldest such triangle, the oldest of its coboundary, with
   * which it forms an apparent pair; INVALID_SIMPLEX for any other edge. */
  std::vector<SimplexIndex> middle;
  std::uint64_t num_triangles = 0;
};

ApparentPairs
findApparentPairs (const EdgeAdjacency& adjacency,
                   const std::vector<std::uint8_t>& edge_positive,
                   unsigned int threads)
{
  ApparentPairs pairs;
  pairs.middle = largeVector<SimplexIndex> (edge_positive.size(), INVALID_SIMPLEX);
  pairs.num_triangles = forEachEdgeWithYoungestTriangles (
      adjacency, threads, {}, [&] (SimplexIndex e, const auto& triangles) {
        // Every edge's triangles are enumerated: they are all counted.
        SimplexIndex oldest_middle = INVALID_SIMPLEX;
        triangles ([&] (SimplexIndex uw, SimplexIndex vw) {
          oldest_middle = std::min (oldest_middle, std::max (uw, vw));
        });
        if (edge_positive[e])
          pairs.middle[e] = oldest_middle;
      });
  return pairs;
}

/** The triangles of a clique complex for reduceEdgeCoboundaries(), named by
 * TriangleKey: coboundaries from the common neighbours of an edge's ends; the
 * apparent pairs from findApparentPairs(), the pairs the reduction makes in a hash
 * map (a few percent of the positive edges on real scans). */
class CliqueCoboundaries {
public:
  using Key = TriangleKey;

  CliqueCoboundaries (const std::vector<FilteredEdge>& edges,
                      const EdgeAdjacency& adjacency,
                      const std::vector<SimplexIndex>& apparent_middle)
  : common_neighbors_ (edges, adjacency), apparent_middle_ (apparent_middle)
  {}

  bool
  claimApparentPair (SimplexIndex edge) const
  {
    return apparent_middle_[edge] != INVALID_SIMPLEX;
  }

  void
  coboundary (SimplexIndex edge, std::vector<Key>& column)
  {
    column.clear();
    common_neighbors_.forEach (edge, [&] (SimplexIndex uw, SimplexIndex vw) {
      const SimplexIndex youngest = std::max ({edge, uw, vw});
      const SimplexIndex oldest = std::min ({edge, uw, vw});
      column.push_back (triangleKey (youngest, edge ^ uw ^ vw ^ youngest ^ oldest));
    });
  }

  SimplexIndex
  owner (Key triangle) const
  {
    const SimplexIndex youngest = youngestEdge (triangle);
    if (apparent_middle_[youngest] == middleEdge (triangle))
      return youngest;
    const auto found = reduced_pairs_.find (triangle);
    return found == reduced_pairs_.end() ? INVALID_SIMPLEX : found->second;
  }

  void
  setOwner (Key triangle, SimplexIndex edge)
  {
    reduced_pairs_.emplace (triangle, edge);
  }

  /** The pairs the reduction made (the apparent ones have zero length), as (killing
   * triangle, edge) in filtration order. */
  std::vector<std::pair<Key, SimplexIndex>>
  sortedReducedPairs () const
  {
    std::vector<std::pair<Key, SimplexIndex>> pairs (reduced_pairs_.begin(),
                                                     reduced_pairs_.end());
    std::sort (pairs.begin(), pairs.end());
    return pairs;
  }

private:
  CommonNeighborSearch common_neighbors_;
  const std::vector<SimplexIndex>& apparent_middle_;
  std::unordered_map<Key, SimplexIndex> reduced_pairs_;
};

} // namespace

CliqueH1Persistence
computeCliqueH1Persistence (const FilteredComplex& skeleton,
                            const PersistenceResult& h0,
                            unsigned int threads,
                            const ProgressCallback& progress)
{
  const auto& edges = skeleton.edges();
  const EdgeAdjacency adjacency = buildEdgeAdjacency (skeleton.numVertices(), edges);
  const ApparentPairs apparent =
      findApparentPairs (adjacency, h0.edge_positive, threads);
  CliqueCoboundaries coboundaries (edges, adjacency, apparent.middle);
  reduceEdgeCoboundaries (h0.edge_positive, coboundaries, progress);

  CliqueH1Persistence persistence;
  persistence.num_triangles = apparent.num_triangles;
  // An apparent pair's triangle has the edge's value: only the reduced pairs and the
  // essential classes have length.
  std::vector<std::uint8_t> paired (edges.size(), 0);
  persistence.edge_death = largeVector<double> (edges.size(), 0.0);
  for (SimplexIndex e = 0; e < edges.size(); ++e)
    persistence.edge_death[e] = edges[e].value;
  for (const auto& [triangle, edge] : coboundaries.sortedReducedPairs()) {
    paired[edge] = 1;
    const double birth = edges[edge].value;
    const double death = edges[youngestEdge (triangle)].value;
    persistence.edge_death[edge] = death;
    if (birth != death)
      persistence.diagram.push_back ({1, birth, death});
  }
  for (SimplexIndex e = 0; e < edges.size(); ++e)
    if (h0.edge_positive[e] && !paired[e] && apparent.middle[e] == INVALID_SIMPLEX) {
      persistence.edge_death[e] = std::numeric_limits<double>::infinity();
      persistence.diagram.push_back (
          {1, edges[e].value, std::numeric_limits<double>::infinity()});
    }
  return persistence;
}

} // namespace tda
} // namespace pcl
