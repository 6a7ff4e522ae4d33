#pragma once

#include <pcl/tda/common/filtered_complex.h>

#include <algorithm>
#include <iterator>
#include <vector>

namespace pcl {
namespace tda {

/** \brief A chain over Z2 as the sorted ids of its simplices: the cycle sets of the
 * incremental engines (thesis Sec 5.2.3, 5.3.1). */
using CycleSet = std::vector<SimplexIndex>;

/** \brief \a target += the sorted simplices [\a first, \a last) over Z2; \a buffer is
 * scratch space, kept by the caller to avoid allocations. \a Id is the type that
 * names a simplex: SimplexIndex, or a wider key where simplices are not listed. */
template <typename Id>
inline void
addCycle (std::vector<Id>& target,
          const Id* first,
          const Id* last,
          std::vector<Id>& buffer)
{
  buffer.clear();
  std::set_symmetric_difference (
      target.begin(), target.end(), first, last, std::back_inserter (buffer));
  target.swap (buffer);
}

/** \brief \a target += \a addend over Z2 (symmetric difference, Eq. 2.1); \a buffer
 * is scratch space, kept by the caller to avoid allocations. */
inline void
addCycle (CycleSet& target, const CycleSet& addend, CycleSet& buffer)
{
  addCycle (target, addend.data(), addend.data() + addend.size(), buffer);
}

/** \brief True when the sorted \a cycle holds \a simplex. */
inline bool
containsSimplex (const CycleSet& cycle, SimplexIndex simplex)
{
  return std::binary_search (cycle.begin(), cycle.end(), simplex);
}

} // namespace tda
} // namespace pcl
