#include <pcl/tda/common/diagram_comparison.h>
#include <pcl/tda/common/diagram_io.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

namespace pcl {
namespace tda {

namespace {

/** Values closer than this times the largest finite magnitude of the two diagrams
 * match whatever the relative tolerance: a floor that scales with the diagrams (an
 * absolute 1e-12 matched every value of a cloud in units of 1e-20 with every other). */
constexpr double ABSOLUTE_TOLERANCE_PER_SCALE = 1e-12;

/** When two values match: within the relative tolerance of the larger, or within the
 * absolute floor. */
struct Tolerance {
  double relative;
  double absolute;

  bool
  match (double x, double y) const
  {
    if (x == y)
      return true;
    if (std::isinf (x) || std::isinf (y))
      return false;
    return std::abs (x - y) <=
           std::max (relative * std::max (std::abs (x), std::abs (y)), absolute);
  }
};

/** The largest magnitude of a finite value of \a diagram (0 for none). */
double
largestFiniteValue (const PersistenceDiagram& diagram)
{
  double largest = 0.0;
  for (const auto& interval : diagram)
    for (const double value : {interval.birth, interval.death})
      if (std::isfinite (value))
        largest = std::max (largest, std::abs (value));
  return largest;
}

bool
byValue (const PersistenceInterval& a, const PersistenceInterval& b)
{
  return std::tie (a.dimension, a.birth, a.death) <
         std::tie (b.dimension, b.birth, b.death);
}

/** The intervals of \a diagram that are not of length zero, sorted by value. */
PersistenceDiagram
nonZeroIntervals (const PersistenceDiagram& diagram,
                  const char* name,
                  const Tolerance& tolerance)
{
  PersistenceDiagram kept;
  kept.reserve (diagram.size());
  for (std::size_t i = 0; i < diagram.size(); ++i) {
    const auto& interval = diagram[i];
    if (std::isnan (interval.birth) || std::isnan (interval.death))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "interval " << i << " of the " << name
                                       << " diagram has a NaN value");
    if (!tolerance.match (interval.birth, interval.death))
      kept.push_back (interval);
  }
  std::sort (kept.begin(), kept.end(), byValue);
  return kept;
}

/** Indices of the intervals of \a second[0, \a second_size) (sorted by value) that
 * match \a interval in birth and death. */
template <typename Visit>
void
forEachMatchingInterval (const PersistenceInterval& interval,
                         const PersistenceInterval* second,
                         std::size_t second_size,
                         const Tolerance& tolerance,
                         Visit visit)
{
  const double reach =
      std::abs (interval.birth) * tolerance.relative / (1.0 - tolerance.relative) +
      tolerance.absolute;
  const auto begin = std::lower_bound (
      second,
      second + second_size,
      interval.birth - reach,
      [] (const PersistenceInterval& x, double birth) { return x.birth < birth; });
  for (auto candidate = begin;
       candidate != second + second_size && candidate->birth <= interval.birth + reach;
       ++candidate)
    if (tolerance.match (interval.birth, candidate->birth) &&
        tolerance.match (interval.death, candidate->death))
      if (!visit (static_cast<std::size_t> (candidate - second)))
        return;
}

/** Matches the intervals \a first[0, \a first_size) to \a second[0, \a
 * second_size), all of one dimension and sorted by value, and records the result.
 *
 * A window slides over \a second: it holds, keyed by death, the unmatched intervals
 * whose birth matches the birth of the current interval of \a first, and each
 * interval takes the one of closest death. Augmenting paths then make the matching
 * maximum, so values crowded closer than the tolerance never leave an interval
 * unmatched that a different pairing would match. */
void
matchDimension (const PersistenceInterval* first,
                std::size_t first_size,
                const PersistenceInterval* second,
                std::size_t second_size,
                const Tolerance& tolerance,
                DiagramComparison& result)
{
  constexpr std::size_t NONE = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> mate_of_first (first_size, NONE);
  std::vector<std::size_t> mate_of_second (second_size, NONE);
  std::set<std::pair<double, std::size_t>> window;
  std::size_t window_begin = 0, window_end = 0;
  for (std::size_t i = 0; i < first_size; ++i) {
    const double birth = first[i].birth;
    const double death = first[i].death;
    for (; window_end < second_size &&
           (second[window_end].birth <= birth ||
            tolerance.match (birth, second[window_end].birth));
         ++window_end)
      window.emplace (second[window_end].death, window_end);
    for (; window_begin < window_end && second[window_begin].birth < birth &&
           !tolerance.match (birth, second[window_begin].birth);
         ++window_begin)
      window.erase ({second[window_begin].death, window_begin});

    // The closest deaths are the neighbours of death in the window.
    auto best = window.end();
    double best_distance = std::numeric_limits<double>::infinity();
    const auto above = window.lower_bound ({death, 0});
    for (auto candidate :
         {above, above == window.begin() ? window.end() : std::prev (above)}) {
      if (candidate == window.end() || !tolerance.match (death, candidate->first))
        continue;
      const double distance =
          candidate->first == death ? 0.0 : std::abs (candidate->first - death);
      if (distance < best_distance) {
        best = candidate;
        best_distance = distance;
      }
    }
    if (best != window.end()) {
      mate_of_first[i] = best->second;
      mate_of_second[best->second] = i;
      window.erase (best);
    }
  }

  // Augmenting paths (breadth first) from every interval of first left unmatched.
  std::vector<std::size_t> parent_of_second (second_size);
  std::vector<bool> visited (second_size);
  for (std::size_t start = 0; start < first_size; ++start) {
    if (mate_of_first[start] != NONE)
      continue;
    std::fill (visited.begin(), visited.end(), false);
    std::vector<std::size_t> queue{start};
    std::size_t free_end = NONE;
    for (std::size_t q = 0; q < queue.size() && free_end == NONE; ++q) {
      const std::size_t i = queue[q];
      forEachMatchingInterval (
          first[i], second, second_size, tolerance, [&] (std::size_t j) {
            if (visited[j])
              return true;
            visited[j] = true;
            parent_of_second[j] = i;
            if (mate_of_second[j] == NONE) {
              free_end = j;
              return false;
            }
            queue.push_back (mate_of_second[j]);
            return true;
          });
    }
    for (std::size_t j = free_end; j != NONE;) {
      const std::size_t i = parent_of_second[j];
      const std::size_t previous = mate_of_first[i];
      mate_of_first[i] = j;
      mate_of_second[j] = i;
      j = previous;
    }
  }

  for (std::size_t i = 0; i < first_size; ++i)
    if (mate_of_first[i] == NONE)
      result.only_in_first.push_back (first[i]);
    else
      ++result.matched;
  for (std::size_t j = 0; j < second_size; ++j)
    if (mate_of_second[j] == NONE)
      result.only_in_second.push_back (second[j]);
}

/** Writes the counts per dimension of \a diagram and its first \a max_listed
 * intervals, under the title \a title. */
void
describeUnmatched (std::ostream& out,
                   const char* title,
                   const PersistenceDiagram& diagram,
                   std::size_t max_listed)
{
  std::map<int, std::size_t> counts;
  for (const auto& interval : diagram)
    ++counts[interval.dimension];
  out << "\n" << diagram.size() << " only in the " << title;
  const char* separator = " (";
  for (const auto& [dimension, count] : counts) {
    out << separator << "H" << dimension << ": " << count;
    separator = ", ";
  }
  out << (counts.empty() ? "" : ")");
  const std::size_t listed = std::min (max_listed, diagram.size());
  for (std::size_t i = 0; i < listed; ++i)
    out << "\n  H" << diagram[i].dimension << " ["
        << formatFiltrationValue (diagram[i].birth) << ", "
        << formatFiltrationValue (diagram[i].death) << ")";
  if (listed < diagram.size())
    out << "\n  ... and " << diagram.size() - listed << " more";
}

} // namespace

std::string
DiagramComparison::summary (std::size_t max_listed) const
{
  std::ostringstream out;
  if (equal) {
    out << "diagrams are equal: " << matched << " intervals matched";
    return out.str();
  }
  out << "diagrams differ: " << matched << " intervals matched";
  describeUnmatched (out, "first", only_in_first, max_listed);
  describeUnmatched (out, "second", only_in_second, max_listed);
  return out.str();
}

DiagramComparison
compareDiagrams (const PersistenceDiagram& first,
                 const PersistenceDiagram& second,
                 double relative_tolerance)
{
  if (!(relative_tolerance >= 0.0 && relative_tolerance < 1.0))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "relative tolerance " << relative_tolerance
                                               << " is not in [0, 1)");
  const Tolerance tolerance{
      relative_tolerance,
      ABSOLUTE_TOLERANCE_PER_SCALE *
          std::max (largestFiniteValue (first), largestFiniteValue (second))};
  const PersistenceDiagram a = nonZeroIntervals (first, "first", tolerance);
  const PersistenceDiagram b = nonZeroIntervals (second, "second", tolerance);
  DiagramComparison result{false, 0, {}, {}};
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    const int dimension =
        j == b.size() || (i < a.size() && a[i].dimension < b[j].dimension)
            ? a[i].dimension
            : b[j].dimension;
    std::size_t i_end = i, j_end = j;
    while (i_end < a.size() && a[i_end].dimension == dimension)
      ++i_end;
    while (j_end < b.size() && b[j_end].dimension == dimension)
      ++j_end;
    matchDimension (
        a.data() + i, i_end - i, b.data() + j, j_end - j, tolerance, result);
    i = i_end;
    j = j_end;
  }
  // An unmatched interval within the tolerance of a point of the diagonal (both
  // values match its middle) is one the other tool, in its precision, had of length
  // zero: dropped as well.
  const auto nearDiagonal = [&tolerance] (const PersistenceInterval& interval) {
    const double middle = 0.5 * (interval.birth + interval.death);
    return tolerance.match (interval.birth, middle) &&
           tolerance.match (interval.death, middle);
  };
  for (PersistenceDiagram* unmatched : {&result.only_in_first, &result.only_in_second})
    unmatched->erase (
        std::remove_if (unmatched->begin(), unmatched->end(), nearDiagonal),
        unmatched->end());
  result.equal = result.only_in_first.empty() && result.only_in_second.empty();
  return result;
}

} // namespace tda
} // namespace pcl
