#include <pcl/tda/common/cohomology_persistence.h>
#include <pcl/tda/common/cycle_set.h>
#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/large_vector.h>

#include "triangle_deaths.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace pcl {
namespace tda {

namespace {

/** Enumerates the coboundary of an edge (the triangles containing it, by id)
 * without storing all coboundaries: from the common neighbours of its ends and the
 * triangle list, whose triangles are grouped by youngest edge and sorted by the
 * next one within a group. */
class CoboundaryEnumerator {
public:
  explicit CoboundaryEnumerator (const FilteredComplex& complex)
  : complex_ (complex)
  , block_offsets_ (largeVector<std::uint64_t> (complex.numEdges() + 1, 0))
  , adjacency_ (buildEdgeAdjacency (complex.numVertices(), complex.edges()))
  , common_neighbors_ (complex.edges(), adjacency_)
  {
    for (const auto& triangle : complex.triangles())
      ++block_offsets_[triangle.edges[0] + 1];
    for (std::size_t e = 0; e < complex.numEdges(); ++e)
      block_offsets_[e + 1] += block_offsets_[e];
  }

  /** True when some triangle has \a edge as its youngest edge; the first such
   * triangle is then the oldest of the coboundary of \a edge. */
  bool
  isYoungestEdgeOfSome (SimplexIndex edge) const
  {
    return block_offsets_[edge] != block_offsets_[edge + 1];
  }

  SimplexIndex
  firstTriangleOf (SimplexIndex edge) const
  {
    return static_cast<SimplexIndex> (block_offsets_[edge]);
  }

  /** The coboundary of \a edge, sorted, into \a coboundary. */
  void
  coboundary (SimplexIndex edge, CycleSet& coboundary)
  {
    coboundary.clear();
    common_neighbors_.forEach (edge, false, [&] (SimplexIndex uw, SimplexIndex vw) {
      const SimplexIndex triangle = triangleOf (edge, uw, vw);
      if (triangle != INVALID_SIMPLEX)
        coboundary.push_back (triangle);
    });
    std::sort (coboundary.begin(), coboundary.end());
  }

private:
  /** The id of the triangle with edges \a a, \a b, \a c, or INVALID_SIMPLEX when
   * the complex does not have it (it need not be a clique complex). */
  SimplexIndex
  triangleOf (SimplexIndex a, SimplexIndex b, SimplexIndex c) const
  {
    const SimplexIndex youngest = std::max ({a, b, c});
    const SimplexIndex oldest = std::min ({a, b, c});
    const SimplexIndex middle = a ^ b ^ c ^ youngest ^ oldest;
    const auto& triangles = complex_.triangles();
    const auto found = std::lower_bound (
        triangles.begin() + block_offsets_[youngest],
        triangles.begin() + block_offsets_[youngest + 1],
        middle,
        [] (const FilteredTriangle& t, SimplexIndex e) { return t.edges[1] < e; });
    if (found == triangles.begin() + block_offsets_[youngest + 1] ||
        found->edges[1] != middle)
      return INVALID_SIMPLEX;
    return static_cast<SimplexIndex> (found - triangles.begin());
  }

  const FilteredComplex& complex_;
  std::vector<std::uint64_t> block_offsets_;
  EdgeAdjacency adjacency_;
  CommonNeighborSearch common_neighbors_;
};

/** The columns the reduction keeps for later additions, one after another in one
 * array: the reduced column of a paired edge, or the coboundary of an apparent
 * pair's edge once some column needs it. A column is stored once and never
 * changes, so one array and an index per edge replace a map of vectors (tens of
 * thousands of allocations on a real scan). */
class StoredColumns {
public:
  explicit StoredColumns (std::size_t num_edges)
  : slot_ (largeVector<std::uint32_t> (num_edges, NONE))
  {}

  bool
  has (SimplexIndex edge) const
  {
    return slot_[edge] != NONE;
  }

  void
  store (SimplexIndex edge, const CycleSet& column)
  {
    slot_[edge] = static_cast<std::uint32_t> (bounds_.size() - 1);
    entries_.insert (entries_.end(), column.begin(), column.end());
    bounds_.push_back (entries_.size());
  }

  /** The stored column of \a edge as [first, last). */
  std::pair<const SimplexIndex*, const SimplexIndex*>
  column (SimplexIndex edge) const
  {
    const std::uint32_t slot = slot_[edge];
    return {entries_.data() + bounds_[slot], entries_.data() + bounds_[slot + 1]};
  }

private:
  static constexpr std::uint32_t NONE = 0xffffffffu;
  std::vector<std::uint32_t> slot_; // per edge: its column's slot, or NONE
  // Column k is entries_[bounds_[k], bounds_[k + 1]).
  std::vector<std::size_t> bounds_ = {0};
  std::vector<SimplexIndex> entries_;
};

} // namespace

void
addCohomologyH1Persistence (const FilteredComplex& complex,
                            PersistenceResult& result,
                            const ProgressCallback& progress)
{
  CoboundaryEnumerator coboundaries (complex);
  const std::size_t num_edges = complex.numEdges();

  // killed_edge[t]: the edge whose reduced coboundary has pivot t (owner of t).
  auto killed_edge =
      largeVector<SimplexIndex> (complex.numTriangles(), INVALID_SIMPLEX);
  // The reduced columns of the paired edges, an apparent pair's (its coboundary,
  // unchanged) only when first needed: few edges need one.
  StoredColumns stored (num_edges);
  CycleSet column, owner_column, buffer;

  for (std::size_t k = 0; k < num_edges; ++k) {
    const auto edge = static_cast<SimplexIndex> (num_edges - 1 - k);
    reportProgress (progress, k, num_edges);
    if (!result.edge_positive[edge])
      continue;
    if (coboundaries.isYoungestEdgeOfSome (edge)) { // apparent pair
      killed_edge[coboundaries.firstTriangleOf (edge)] = edge;
      continue;
    }
    coboundaries.coboundary (edge, column);
    while (!column.empty() && killed_edge[column.front()] != INVALID_SIMPLEX) {
      const SimplexIndex owner = killed_edge[column.front()];
      if (!stored.has (owner)) { // an apparent pair: its column is its coboundary
        coboundaries.coboundary (owner, owner_column);
        stored.store (owner, owner_column);
      }
      const auto [first, last] = stored.column (owner);
      addCycle (column, first, last, buffer);
    }
    if (!column.empty()) {
      killed_edge[column.front()] = edge;
      stored.store (edge, column);
    }
  }
  addTriangleDeaths (killed_edge, result);
}

} // namespace tda
} // namespace pcl
