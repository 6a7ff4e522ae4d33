#pragma once

#include <pcl/tda/common/cycle_set.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The column a coboundary reduction is reducing: a sum over Z2 of sorted
 * columns, with its oldest key as pivot.
 *
 * A short column is a sorted vector, and adding a column merges the two. A column
 * longer than HEAP_FROM keys becomes a heap in which a key added twice cancels when
 * it reaches the top (as in Ripser), so that adding a short column to it costs the
 * short one's length times a logarithm instead of the long one's length. The reduced
 * columns of classes that live long grow to tens of thousands of triangles on dense
 * real scans (136,721 on kinect_frame.pcd at 2.6 spacings), where merging made the
 * reduction quadratic. \a Key names a triangle, ordered as the filtration. */
template <typename Key>
class ReductionColumn {
public:
  /** Keys past which the column is a heap: 16 KiB of 8-byte keys. */
  static constexpr std::size_t HEAP_FROM = 2048;

  /** \brief Starts from the sorted, distinct \a keys, taken over (\a keys gets
   * the old contents as scratch space). */
  void
  assign (std::vector<Key>& keys)
  {
    keys_.swap (keys);
    is_heap_ = false;
  }

  /** \brief True when a key is left (after the cancellations at the top of a heap):
   * then pivot() is the oldest one. */
  bool
  findPivot ()
  {
    if (!is_heap_)
      return !keys_.empty();
    const std::greater<Key> later;
    while (!keys_.empty()) {
      std::pop_heap (keys_.begin(), keys_.end(), later);
      if (keys_.size() == 1 || keys_.front() != keys_.back()) {
        std::push_heap (keys_.begin(), keys_.end(), later);
        return true;
      }
      keys_.pop_back();
      std::pop_heap (keys_.begin(), keys_.end(), later);
      keys_.pop_back();
    }
    return false;
  }

  /** \brief The oldest key; only after findPivot() returned true. */
  Key
  pivot () const
  {
    return keys_.front();
  }

  /** \brief Adds the sorted, distinct keys [\a first, \a last) over Z2. */
  void
  add (const Key* first, const Key* last)
  {
    if (!is_heap_) {
      addCycle (keys_, first, last, buffer_);
      if (keys_.size() > HEAP_FROM) {
        std::make_heap (keys_.begin(), keys_.end(), std::greater<Key>());
        is_heap_ = true;
      }
      return;
    }
    for (; first != last; ++first) {
      keys_.push_back (*first);
      std::push_heap (keys_.begin(), keys_.end(), std::greater<Key>());
    }
  }

  /** \brief The keys left, sorted and distinct: the sum. */
  const std::vector<Key>&
  sum ()
  {
    if (is_heap_) {
      std::sort (keys_.begin(), keys_.end());
      std::size_t kept = 0;
      for (std::size_t first = 0, last; first < keys_.size(); first = last) {
        for (last = first + 1; last < keys_.size() && keys_[last] == keys_[first];)
          ++last;
        if ((last - first) % 2 == 1)
          keys_[kept++] = keys_[first];
      }
      keys_.resize (kept);
      is_heap_ = false;
    }
    return keys_;
  }

  /** \brief Moves the sum (sorted, distinct) into \a keys, whose old contents the
   * column takes as scratch space; the column is then empty. */
  void
  release (std::vector<Key>& keys)
  {
    sum();
    keys_.swap (keys);
    keys_.clear();
  }

private:
  std::vector<Key> keys_;
  std::vector<Key> buffer_; // scratch space of the merges
  bool is_heap_ = false;
};

} // namespace tda
} // namespace pcl
