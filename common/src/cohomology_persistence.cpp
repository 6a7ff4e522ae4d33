#include <pcl/tda/common/coboundary_reduction.h>
#include <pcl/tda/common/cohomology_persistence.h>
#include <pcl/tda/common/cycle_set.h>
#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/large_vector.h>

#include "triangle_deaths.h"

#include <algorithm>
#include <cstdint>

namespace pcl {
namespace tda {

namespace {

/** The triangles of a complex that lists them, for reduceEdgeCoboundaries(): named
 * by id. Enumerates the coboundary of an edge without storing all coboundaries, from
 * the common neighbours of its ends and the triangle list, whose triangles are
 * grouped by youngest edge and sorted by the next one within a group; keeps the
 * edge each triangle kills. */
class ListedCoboundaries {
public:
  using Key = SimplexIndex;

  explicit ListedCoboundaries (const FilteredComplex& complex)
  : complex_ (complex)
  , block_offsets_ (largeVector<std::uint64_t> (complex.numEdges() + 1, 0))
  , adjacency_ (buildEdgeAdjacency (complex.numVertices(), complex.edges()))
  , killed_edge_ (largeVector<SimplexIndex> (complex.numTriangles(), INVALID_SIMPLEX))
  {
    for (const auto& triangle : complex.triangles())
      ++block_offsets_[triangle.edges[0] + 1];
    for (std::size_t e = 0; e < complex.numEdges(); ++e)
      block_offsets_[e + 1] += block_offsets_[e];
  }

  /** A positive \a edge forms an apparent pair with the first triangle of its block
   * when it is the youngest edge of some triangle: that triangle is then the oldest
   * of its coboundary. */
  bool
  claimApparentPair (SimplexIndex edge)
  {
    if (block_offsets_[edge] == block_offsets_[edge + 1])
      return false;
    killed_edge_[block_offsets_[edge]] = edge;
    return true;
  }

  CommonNeighborSearch
  commonNeighborSearch () const
  {
    return {complex_.edges(), adjacency_};
  }

  /** The coboundary of \a edge, in no particular order, into \a coboundary. */
  void
  coboundary (SimplexIndex edge,
              CommonNeighborSearch& search,
              CycleSet& coboundary) const
  {
    coboundary.clear();
    search.forEach (edge, [&] (SimplexIndex uw, SimplexIndex vw) {
      const SimplexIndex triangle = triangleOf (edge, uw, vw);
      if (triangle != INVALID_SIMPLEX)
        coboundary.push_back (triangle);
    });
  }

  SimplexIndex
  owner (SimplexIndex triangle) const
  {
    return killed_edge_[triangle];
  }

  void
  setOwner (SimplexIndex triangle, SimplexIndex edge)
  {
    killed_edge_[triangle] = edge;
  }

  /** Per triangle, the edge whose class it kills, or INVALID_SIMPLEX. */
  const std::vector<SimplexIndex>&
  killedEdges () const
  {
    return killed_edge_;
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
  std::vector<SimplexIndex> killed_edge_;
};

} // namespace

void
addCohomologyH1Persistence (const FilteredComplex& complex,
                            PersistenceResult& result,
                            const ProgressCallback& progress)
{
  ListedCoboundaries coboundaries (complex);
  reduceEdgeCoboundaries (result.edge_positive, coboundaries, 1, progress);
  addTriangleDeaths (coboundaries.killedEdges(), result);
}

} // namespace tda
} // namespace pcl
