#pragma once

#include <pcl/tda/common/persistence_diagram.h>

#include <cstddef>
#include <string>

namespace pcl {
namespace tda {

/** \brief The outcome of compareDiagrams(): how many intervals were matched and the
 * intervals of each diagram that have no partner in the other. */
struct DiagramComparison {
  /** True when every interval found a partner. */
  bool equal;
  /** Number of matched pairs of intervals. */
  std::size_t matched;
  /** Intervals of the first diagram without partner, sorted by (dim, birth, death). */
  PersistenceDiagram only_in_first;
  /** Intervals of the second diagram without partner, sorted likewise. */
  PersistenceDiagram only_in_second;

  /** \brief A human-readable report: that the diagrams are equal, or the counts of
   * unmatched intervals per dimension and the first \a max_listed unmatched
   * intervals of each diagram. */
  std::string
  summary (std::size_t max_listed = 10) const;
};

/** \brief Compares two persistence diagrams as multisets of (dimension, birth,
 * death), the way results of different tools (Ripser, GUDHI, PHAT) are compared.
 *
 * Two values x and y match when both are infinite or |x - y| <= max(\a
 * relative_tolerance * max(|x|, |y|), 1e-12 * m), m the largest magnitude of a finite
 * value of the two diagrams (a floor for values near 0, in the diagrams' unit, so that
 * clouds in any unit compare alike). Intervals whose birth matches their
 * death are dropped from both diagrams first, since tools break ties differently.
 * Each interval of \a first, in (birth, death) order, is matched to the unmatched
 * interval of \a second of the same dimension with matching birth whose matching
 * death is closest to its own. An interval left unmatched whose birth and death both
 * match its middle (up to twice the tolerance long) is dropped too: the other tool,
 * in its precision, may have had it of length zero (Ripser prints 6 digits: its
 * [0.100499, 0.1005) is dropped first, our [0.1004993, 0.1005004) was not). Runs in
 * O(n log n).
 * \param[in] relative_tolerance in [0, 1); Ripser computes distances in float,
 * hence the default 1e-5
 * \throws pcl::BadArgumentException for a tolerance outside [0, 1) or a NaN value
 */
DiagramComparison
compareDiagrams (const PersistenceDiagram& first,
                 const PersistenceDiagram& second,
                 double relative_tolerance = 1e-5);

} // namespace tda
} // namespace pcl
