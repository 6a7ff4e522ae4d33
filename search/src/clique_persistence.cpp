#include <pcl/tda/common/coboundary_reduction.h>
#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/search/clique_persistence.h>
#include <pcl/tda/search/youngest_edge_triangles.h>

#include <algorithm>
#include <limits>
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
 * apparent pairs from findApparentPairs(), the pairs the reduction makes in lists
 * per youngest edge. */
class CliqueCoboundaries {
public:
  using Key = TriangleKey;

  CliqueCoboundaries (const std::vector<FilteredEdge>& edges,
                      const EdgeAdjacency& adjacency,
                      const std::vector<SimplexIndex>& apparent_middle)
  : edges_ (edges)
  , adjacency_ (adjacency)
  , apparent_middle_ (apparent_middle)
  , first_reduced_pair_ (largeVector<std::uint32_t> (edges.size(), NO_PAIR))
  {}

  bool
  claimApparentPair (SimplexIndex edge) const
  {
    return apparent_middle_[edge] != INVALID_SIMPLEX;
  }

  CommonNeighborSearch
  commonNeighborSearch () const
  {
    return {edges_, adjacency_};
  }

  void
  coboundary (SimplexIndex edge,
              CommonNeighborSearch& search,
              std::vector<Key>& column) const
  {
    column.clear();
    search.forEach (edge, [&] (SimplexIndex uw, SimplexIndex vw) {
      const SimplexIndex youngest = std::max ({edge, uw, vw});
      const SimplexIndex oldest = std::min ({edge, uw, vw});
      column.push_back (triangleKey (youngest, edge ^ uw ^ vw ^ youngest ^ oldest));
    });
  }

  SimplexIndex
  owner (Key triangle) const
  {
    const SimplexIndex youngest = youngestEdge (triangle);
    const SimplexIndex middle = middleEdge (triangle);
    if (apparent_middle_[youngest] == middle)
      return youngest;
    for (auto pair = first_reduced_pair_[youngest]; pair != NO_PAIR;
         pair = reduced_pairs_[pair].next)
      if (reduced_pairs_[pair].middle == middle)
        return reduced_pairs_[pair].edge;
    return INVALID_SIMPLEX;
  }

  void
  setOwner (Key triangle, SimplexIndex edge)
  {
    const SimplexIndex youngest = youngestEdge (triangle);
    reduced_pairs_.push_back (
        {middleEdge (triangle), edge, first_reduced_pair_[youngest]});
    first_reduced_pair_[youngest] =
        static_cast<std::uint32_t> (reduced_pairs_.size() - 1);
  }

  /** The pairs the reduction made (the apparent ones have zero length), as (killing
   * triangle, edge) in filtration order. */
  std::vector<std::pair<Key, SimplexIndex>>
  sortedReducedPairs () const
  {
    std::vector<std::pair<Key, SimplexIndex>> pairs;
    pairs.reserve (reduced_pairs_.size());
    for (SimplexIndex youngest = 0; youngest < first_reduced_pair_.size(); ++youngest)
      for (auto pair = first_reduced_pair_[youngest]; pair != NO_PAIR;
           pair = reduced_pairs_[pair].next)
        pairs.emplace_back (triangleKey (youngest, reduced_pairs_[pair].middle),
                            reduced_pairs_[pair].edge);
    std::sort (pairs.begin(), pairs.end());
    return pairs;
  }

private:
  const std::vector<FilteredEdge>& edges_;
  const EdgeAdjacency& adjacency_;
  /** A pair the reduction made: its triangle's middle edge, its edge, and the next
   * pair of a triangle with the same youngest edge. */
  struct ReducedPair {
    SimplexIndex middle;
    SimplexIndex edge;
    std::uint32_t next;
  };
  static constexpr std::uint32_t NO_PAIR = 0xffffffffu;

  const std::vector<SimplexIndex>& apparent_middle_;
  // The pairs the reduction made (a few percent of the positive edges on real
  // scans), listed per youngest edge of their triangle: looking one up reads an
  // entry per edge, mostly NO_PAIR, where a hash map of triangles chased pointers.
  std::vector<std::uint32_t> first_reduced_pair_;
  std::vector<ReducedPair> reduced_pairs_;
};

} // namespace

CliqueH1Persistence
computeCliqueH1Persistence (const FilteredComplex& skeleton,
                            const PersistenceResult& h0,
                            unsigned int threads,
                            const ProgressCallback& progress)
{
  const auto& edges = skeleton.edges();
  // \a threads, or OpenMP's default but at most one per \a work_per_thread.
  const auto threads_for = [threads] (std::uint64_t work,
                                      std::uint64_t work_per_thread) {
    if (threads > 0)
      return resolveThreads (threads);
    return static_cast<int> (std::clamp<std::uint64_t> (
        work / work_per_thread, 1, static_cast<std::uint64_t> (resolveThreads (0))));
  };
  const EdgeAdjacency adjacency = buildEdgeAdjacency (skeleton.numVertices(), edges);
  const ApparentPairs apparent = findApparentPairs (
      adjacency,
      h0.edge_positive,
      static_cast<unsigned int> (threads_for (edges.size(), EDGES_PER_THREAD)));
  CliqueCoboundaries coboundaries (edges, adjacency, apparent.middle);
  reduceEdgeCoboundaries (h0.edge_positive,
                          coboundaries,
                          threads_for (apparent.num_triangles, TRIANGLES_PER_THREAD),
                          progress);

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
