#pragma once

#include <pcl/tda/common/filtered_complex.h>

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
   * edge \a e, with the ids of the edges uw and vw: in a clique complex, the
   * triangles on \a e (forEachEdgeWithYoungestTriangles() finds those whose youngest
   * edge is \a e, for all edges at once). */
  template <typename Visit>
  void
  forEach (SimplexIndex e, Visit visit)
  {
    const FilteredEdge& edge = edges_[e];
    for (const auto& entry : adjacency_.neighbors (edge.source))
      marks_[entry.neighbor] = {e, entry.edge};
    for (const auto& entry : adjacency_.neighbors (edge.target)) {
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

  const std::vector<FilteredEdge>& edges_;
  const EdgeAdjacency& adjacency_;
  std::vector<Mark> marks_;
};

} // namespace tda
} // namespace pcl
