#pragma once

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Disjoint sets over the elements 0..n-1 with union by size and path
 * halving: near-constant amortized time per operation (thesis Sec 4.1.4). */
class UnionFind {
public:
  explicit UnionFind (std::size_t n) : parent_ (n), size_ (n, 1)
  {
    std::iota (parent_.begin(), parent_.end(), std::uint32_t{0});
  }

  /** \brief The representative of the set holding \a x. */
  std::uint32_t
  find (std::uint32_t x)
  {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  /** \brief Merges the sets with representatives \a a and \a b (a != b) and returns
   * the representative of the union. */
  std::uint32_t
  linkRoots (std::uint32_t a, std::uint32_t b)
  {
    if (size_[a] < size_[b])
      std::swap (a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return a;
  }

  /** \brief Number of elements in the set whose representative is \a root. */
  std::uint32_t
  setSize (std::uint32_t root) const
  {
    return size_[root];
  }

private:
  std::vector<std::uint32_t> parent_;
  std::vector<std::uint32_t> size_;
};

} // namespace tda
} // namespace pcl
