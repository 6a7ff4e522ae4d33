#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/common/progress.h>
#include <pcl/tda/common/reduction_column.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The columns a coboundary reduction keeps for later additions, one after
 * another in a few large blocks: the reduced column of a paired edge, or the
 * coboundary of an apparent pair's edge once some column needs it. A column is
 * stored once and never changes, so blocks and an index per edge replace a map of
 * vectors (tens of thousands of allocations on a real scan); a block is never moved
 * (a full one is followed by a new one), so that storing costs no copy of the columns
 * stored before. \a Key names a triangle. */
template <typename Key>
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
  store (SimplexIndex edge, const std::vector<Key>& column)
  {
    if (blocks_.empty() ||
        blocks_.back().capacity() - blocks_.back().size() < column.size()) {
      blocks_.emplace_back();
      blocks_.back().reserve (std::max (BLOCK_KEYS, column.size()));
    }
    std::vector<Key>& block = blocks_.back();
    const Key* first = block.data() + block.size();
    block.insert (block.end(), column.begin(), column.end());
    slot_[edge] = static_cast<std::uint32_t> (columns_.size());
    columns_.emplace_back (first, first + column.size());
  }

  /** The stored column of \a edge as [first, last). */
  std::pair<const Key*, const Key*>
  column (SimplexIndex edge) const
  {
    return columns_[slot_[edge]];
  }

private:
  static constexpr std::uint32_t NONE = 0xffffffffu;
  /** Keys per block: 2 MiB, a huge page where malloc takes them. */
  static constexpr std::size_t BLOCK_KEYS = (std::size_t{2} << 20) / sizeof (Key);
  std::vector<std::uint32_t> slot_; // per edge: its column's slot, or NONE
  std::vector<std::pair<const Key*, const Key*>> columns_; // per slot
  std::vector<std::vector<Key>> blocks_;
};

/** \brief Persistent cohomology of the edges (H1): the reduction loop of the
 * cohomology engines, whichever way they name and enumerate triangles.
 *
 * The coboundary of every positive edge (the triangles containing it, in filtration
 * order) is reduced over Z2, youngest edge first, with the oldest triangle as
 * pivot; negative edges need no column (clearing). A positive edge whose oldest
 * coboundary triangle has it as youngest edge forms an apparent pair with that
 * triangle and needs no reduction: in a Vietoris-Rips complex most pairs are such.
 * Of the others, an edge whose oldest coboundary triangle no column has as pivot yet
 * forms an emergent pair with it: its column is reduced as it is, so it is neither
 * sorted nor stored (as Ripser does). Cohomology pairs the same simplices as
 * homology. The column under reduction is a ReductionColumn: a heap once long.
 *
 * \a Coboundaries names a triangle by a \c Key ordered as the filtration and
 * provides:
 * - `bool claimApparentPair (SimplexIndex edge)`: true when the positive \a edge
 *   forms an apparent pair, which it then records;
 * - `void coboundary (SimplexIndex edge, std::vector<Key>& column)`: the
 *   coboundary of \a edge, in any order;
 * - `SimplexIndex owner (Key triangle)`: the edge paired with \a triangle so far
 *   (apparent pairs included), or INVALID_SIMPLEX;
 * - `void setOwner (Key triangle, SimplexIndex edge)`: pairs them.
 * \param[in] edge_positive per edge, 1 when it is positive (from H0)
 * \param[in,out] coboundaries the triangles and the pairing
 * \param[in] progress optional callback (edges processed, edges)
 */
template <typename Coboundaries>
void
reduceEdgeCoboundaries (const std::vector<std::uint8_t>& edge_positive,
                        Coboundaries& coboundaries,
                        const ProgressCallback& progress)
{
  using Key = typename Coboundaries::Key;
  const std::size_t num_edges = edge_positive.size();
  // The reduced columns of the edges whose columns were added to, an apparent or
  // emergent pair's (its coboundary, unchanged) only when first needed: few edges
  // need one.
  StoredColumns<Key> stored (num_edges);
  std::vector<Key> column, owner_column;
  ReductionColumn<Key> reduced;
  for (std::size_t k = 0; k < num_edges; ++k) {
    const auto edge = static_cast<SimplexIndex> (num_edges - 1 - k);
    reportProgress (progress, k, num_edges);
    if (!edge_positive[edge] || coboundaries.claimApparentPair (edge))
      continue;
    coboundaries.coboundary (edge, column);
    if (column.empty())
      continue; // in no triangle: an essential class
    const Key pivot = *std::min_element (column.begin(), column.end());
    if (coboundaries.owner (pivot) == INVALID_SIMPLEX) {
      coboundaries.setOwner (pivot, edge); // an emergent pair
      continue;
    }
    std::sort (column.begin(), column.end());
    reduced.assign (column);
    SimplexIndex owner;
    while (reduced.findPivot() &&
           (owner = coboundaries.owner (reduced.pivot())) != INVALID_SIMPLEX) {
      if (!stored.has (owner)) { // an apparent or emergent pair: its coboundary
        coboundaries.coboundary (owner, owner_column);
        std::sort (owner_column.begin(), owner_column.end());
        stored.store (owner, owner_column);
      }
      const auto [first, last] = stored.column (owner);
      reduced.add (first, last);
    }
    if (reduced.findPivot()) {
      coboundaries.setOwner (reduced.pivot(), edge);
      stored.store (edge, reduced.sum());
    }
  }
}

} // namespace tda
} // namespace pcl
