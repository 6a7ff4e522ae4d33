#pragma once

#include <pcl/tda/common/filtered_complex.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The adjacency lists of a graph given by its edges in filtration order, in
 * compressed sparse row form: the neighbours of vertex v, each with the id of the
 * edge that joins them, are entries offsets[v] to offsets[v + 1], sorted by edge id
 * (so the neighbours through edges older than some edge form a prefix).
 *
 * The triangle phase of the Vietoris-Rips builder (Alg 3.4-3.5), the coboundaries of
 * the cohomology engine and the walks of hole detection over the positive edges all
 * read it. */
struct EdgeAdjacency {
  struct Entry {
    SimplexIndex neighbor;
    SimplexIndex edge;
  };

  /** \brief A contiguous run of entries, iterable with range-for. */
  struct Range {
    const Entry* first;
    const Entry* last;
    const Entry*
    begin () const
    {
      return first;
    }
    const Entry*
    end () const
    {
      return last;
    }
  };

  std::vector<std::uint64_t> offsets;
  std::vector<Entry> entries;
  /** Per edge of the input list (kept or not): its position in the lists of its
   * source and of its target, i.e. the end of the entries through older edges. */
  std::vector<std::array<std::uint64_t, 2>> positions;

  std::size_t
  numVertices () const
  {
    return offsets.empty() ? 0 : offsets.size() - 1;
  }

  /** \brief All neighbours of \a vertex. */
  Range
  neighbors (SimplexIndex vertex) const
  {
    return {entries.data() + offsets[vertex], entries.data() + offsets[vertex + 1]};
  }

  /** \brief The neighbours of end \a side (0: source, 1: target) \a vertex of edge
   * \a edge through edges older than \a edge. */
  Range
  olderNeighbors (SimplexIndex vertex, SimplexIndex edge, int side) const
  {
    return {entries.data() + offsets[vertex], entries.data() + positions[edge][side]};
  }
};

/** \brief Keeps edge \a e of a list when it returns true. */
using EdgeFilter = std::function<bool (SimplexIndex e)>;

/** \brief The adjacency lists of the edges of \a edges (sorted in filtration order,
 * ends < \a num_vertices) that pass \a keep (all when empty), e.g. the positive edges
 * only. */
EdgeAdjacency
buildEdgeAdjacency (std::size_t num_vertices,
                    const std::vector<FilteredEdge>& edges,
                    const EdgeFilter& keep = {});

/** \brief Finds the vertices adjacent to both ends of an edge, i.e. the third
 * vertices of the triangles on it, by marking the neighbours of one end and scanning
 * those of the other: a search costs the two lists, not their product. One object
 * per thread (it keeps a mark per vertex). */
class CommonNeighborSearch {
public:
  /** \param[in] edges the edges the adjacency was built from (kept by reference)
   * \param[in] adjacency their adjacency lists (kept by reference) */
  CommonNeighborSearch (const std::vector<FilteredEdge>& edges,
                        const EdgeAdjacency& adjacency)
  : edges_ (edges)
  , adjacency_ (adjacency)
  , marks_ (adjacency.numVertices(), {INVALID_SIMPLEX, 0})
  {}

  /** \brief Calls \a visit(uw, vw) for every vertex w adjacent to both ends u, v of
   * edge \a e, with the ids of the edges uw and vw. With \a older_only, only through
   * edges older than \a e: in a clique complex, the triangles whose youngest edge is
   * \a e. Searches of one edge must all use the same \a older_only. */
  template <typename Visit>
  void
  forEach (SimplexIndex e, bool older_only, Visit visit)
  {
    const FilteredEdge& edge = edges_[e];
    for (const auto& entry : neighborsOf (edge.source, e, 0, older_only))
      marks_[entry.neighbor] = {e, entry.edge};
    for (const auto& entry : neighborsOf (edge.target, e, 1, older_only)) {
      const Mark& mark = marks_[entry.neighbor];
      if (mark.edge_searched == e)
        visit (mark.edge_to_source, entry.edge);
    }
  }

private:
  struct Mark {
    SimplexIndex edge_searched;  // the edge whose search marked the vertex last
    SimplexIndex edge_to_source; // the edge from the vertex to that edge's source
  };

  EdgeAdjacency::Range
  neighborsOf (SimplexIndex vertex, SimplexIndex e, int side, bool older_only) const
  {
    return older_only ? adjacency_.olderNeighbors (vertex, e, side)
                      : adjacency_.neighbors (vertex);
  }

  const std::vector<FilteredEdge>& edges_;
  const EdgeAdjacency& adjacency_;
  std::vector<Mark> marks_;
};

} // namespace tda
} // namespace pcl
