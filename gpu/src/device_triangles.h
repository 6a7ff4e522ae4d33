#pragma once

// Part of the gpu/ module's Thrust code (thrust_phases.inl), compiled once per backend.

#include <pcl/tda/common/host_device.h>

#include "device_grid.h"
#include "small_sort.h"

#include <cstdint>

namespace pcl {
namespace tda {
namespace gpu {
namespace detail {
namespace PCL_TDA_GPU_BACKEND {

/** \brief An adjacency entry: a neighbour and the id of the edge to it, as
 * (neighbour << 32 | edge), so that entries sort by neighbour. */
PCL_TDA_HOST_DEVICE inline std::uint64_t
adjacencyEntry (Index neighbor, Index edge)
{
  return static_cast<std::uint64_t> (neighbor) << 32 | edge;
}

/** \brief The entries of one vertex, [first, last). */
struct EntryRange {
  const std::uint64_t* first;
  const std::uint64_t* last;
};

/** \brief The adjacency of the edges in filtration order: every vertex's entries
 * sorted by neighbour, its earlier neighbours first, then its later ones from
 * forward_begin. The later ones are its edges in the (source, target) order of the
 * fill pass, from edge_positions. */
struct DeviceAdjacency {
  const std::uint64_t* offsets;       // per vertex, and the end
  const std::uint64_t* forward_begin; // per vertex
  const std::uint64_t* entries;
  const std::uint64_t* edge_positions; // per vertex

  /** The entries of vertex \a v. */
  PCL_TDA_HOST_DEVICE EntryRange
  entriesOf (Index v) const
  {
    return {entries + offsets[v], entries + offsets[v + 1]};
  }
};

/** \brief Writes the adjacency lists of every vertex x: the backward list (earlier
 * neighbours u of x, by u, from the edge list sorted by target) then the forward
 * list (the fill pass's later neighbours, in order), each entry with its edge id. */
struct FillAdjacency {
  const std::uint64_t* forward_offsets; // per vertex, and the end
  const Index* forward_vertex;
  const Index* forward_edge;
  const std::uint64_t* backward_offsets;
  const Index* backward_vertex;
  const Index* backward_edge;
  std::uint64_t* entries; // at forward_offsets[x] + backward_offsets[x]

  PCL_TDA_HOST_DEVICE void
  operator() (Index x) const
  {
    std::uint64_t* out = entries + forward_offsets[x] + backward_offsets[x];
    for (std::uint64_t q = backward_offsets[x]; q < backward_offsets[x + 1]; ++q)
      *out++ = adjacencyEntry (backward_vertex[q], backward_edge[q]);
    for (std::uint64_t p = forward_offsets[x]; p < forward_offsets[x + 1]; ++p)
      *out++ = adjacencyEntry (forward_vertex[p], forward_edge[p]);
  }
};

/** \brief One step of merging the entries of the two ends u, v of edge \a e: true
 * when both entries name the same vertex w through edges uw, vw older than \a e, a
 * triangle whose youngest edge is \a e (Alg 3.4). Advances past the smaller
 * neighbour (both on a tie), without branches. */
PCL_TDA_HOST_DEVICE inline bool
mergeStep (EntryRange& a, EntryRange& b, Index e, std::uint64_t& older_edges)
{
  const std::uint64_t x = *a.first, y = *b.first;
  const auto wx = static_cast<Index> (x >> 32), wy = static_cast<Index> (y >> 32);
  const auto uw = static_cast<Index> (x), vw = static_cast<Index> (y);
  a.first += wx <= wy;
  b.first += wy <= wx;
  older_edges = uw < vw ? adjacencyEntry (vw, uw) : adjacencyEntry (uw, vw);
  return (wx == wy) & (uw < e) & (vw < e);
}

/** \brief The number of triangles whose youngest edge is \a e, of ends with entries
 * \a a and \a b: a merge of the two lists. */
PCL_TDA_HOST_DEVICE inline std::uint64_t
countOlderTriangles (EntryRange a, EntryRange b, Index e)
{
  std::uint64_t count = 0, older_edges;
  while (a.first != a.last && b.first != b.last)
    count += mergeStep (a, b, e, older_edges);
  return count;
}

/** \brief The triangles of two edges, as countOlderTriangles(): the two merges run
 * side by side, so that the processor overlaps their independent steps. */
PCL_TDA_HOST_DEVICE inline void
countOlderTrianglesOfTwo (EntryRange a0,
                          EntryRange b0,
                          Index e0,
                          EntryRange a1,
                          EntryRange b1,
                          Index e1,
                          Index& count0,
                          Index& count1)
{
  std::uint64_t both[2] = {0, 0}, older_edges;
  while (a0.first != a0.last && b0.first != b0.last && a1.first != a1.last &&
         b1.first != b1.last) {
    both[0] += mergeStep (a0, b0, e0, older_edges);
    both[1] += mergeStep (a1, b1, e1, older_edges);
  }
  count0 = static_cast<Index> (both[0] + countOlderTriangles (a0, b0, e0));
  count1 = static_cast<Index> (both[1] + countOlderTriangles (a1, b1, e1));
}

/** \brief Writes the \a count triangles whose youngest edge is \a e to \a out, as
 * (middle << 32 | oldest), stopping at the last one. */
PCL_TDA_HOST_DEVICE inline void
writeOlderTriangles (
    EntryRange a, EntryRange b, Index e, std::uint64_t* out, std::uint64_t count)
{
  for (std::uint64_t k = 0; k < count;)
    k += mergeStep (a, b, e, out[k]);
}

/** \brief Calls \a visit(e, p, entries of u, entries of v) for every edge e = (u, v)
 * of \a u to a later vertex v, p its position in (source, target) order: each edge
 * once, from its smaller end, whose entries stay in cache over all its edges, and
 * in the order of p, so that arrays indexed by p are read and written in sequence.
 */
template <typename Visit>
PCL_TDA_HOST_DEVICE void
forEachForwardEdge (const DeviceAdjacency& adjacency, Index u, Visit& visit)
{
  const EntryRange own = adjacency.entriesOf (u);
  std::uint64_t p = adjacency.edge_positions[u];
  for (const std::uint64_t* k = adjacency.entries + adjacency.forward_begin[u];
       k != own.last;
       ++k, ++p)
    visit (static_cast<Index> (*k),
           p,
           own,
           adjacency.entriesOf (static_cast<Index> (*k >> 32)));
}

/** \brief Count pass of the triangles: the number of triangles of every edge whose
 * youngest edge it is, from the vertex at its smaller end, by (source, target)
 * position. */
struct CountOlderTriangles {
  DeviceAdjacency adjacency;
  Index* counts; // per edge position

  PCL_TDA_HOST_DEVICE void
  operator() (Index u) const
  {
    // The edges of u two at a time (see countOlderTrianglesOfTwo()).
    const EntryRange own = adjacency.entriesOf (u);
    const std::uint64_t* k = adjacency.entries + adjacency.forward_begin[u];
    Index* out = counts + adjacency.edge_positions[u];
    for (; own.last - k >= 2; k += 2, out += 2)
      countOlderTrianglesOfTwo (own,
                                adjacency.entriesOf (static_cast<Index> (k[0] >> 32)),
                                static_cast<Index> (k[0]),
                                own,
                                adjacency.entriesOf (static_cast<Index> (k[1] >> 32)),
                                static_cast<Index> (k[1]),
                                out[0],
                                out[1]);
    if (k != own.last)
      *out = static_cast<Index> (
          countOlderTriangles (own,
                               adjacency.entriesOf (static_cast<Index> (*k >> 32)),
                               static_cast<Index> (*k)));
  }
};

/** \brief Fill pass of the triangles (Alg 3.5) for the edges [first_edge, last_edge),
 * into a block of the list starting at triangle \a first: every edge writes its
 * triangles at its offset, as (middle << 32 | oldest) sorted by the middle edge,
 * which puts the block in the complex's triangle order. */
struct FillOlderTriangles {
  DeviceAdjacency adjacency;
  const std::uint64_t* offsets; // per edge position: of its first triangle
  const Index* counts;          // per edge position
  Index first_edge, last_edge;
  std::uint64_t first;
  std::uint64_t* middle_oldest;

  PCL_TDA_HOST_DEVICE void
  operator() (Index e, std::uint64_t p, const EntryRange& a, const EntryRange& b) const
  {
    if (e < first_edge || e >= last_edge)
      return;
    std::uint64_t* out = middle_oldest + (offsets[p] - first);
    writeOlderTriangles (a, b, e, out, counts[p]);
    sortInPlace (out, out + counts[p]);
  }

  PCL_TDA_HOST_DEVICE void
  operator() (Index u) const
  {
    forEachForwardEdge (adjacency, u, *this);
  }
};

} // namespace PCL_TDA_GPU_BACKEND
} // namespace detail
} // namespace gpu
} // namespace tda
} // namespace pcl
