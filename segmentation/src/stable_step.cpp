#include <pcl/tda/segmentation/stable_step.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace pcl {
namespace tda {

bool
chooseStableStep (std::vector<std::pair<double, int>> events,
                  double floor,
                  double max_scale,
                  double gap_ratio,
                  StableStep& step,
                  StableStepPreference preference)
{
  struct Step {
    double low;
    double high;
    std::ptrdiff_t count;
  };
  std::vector<Step> steps;
  std::sort (events.begin(), events.end());
  std::ptrdiff_t count = 0;
  std::size_t e = 0;
  for (double low = floor; low < max_scale;) {
    for (; e < events.size() && events[e].first <= low; ++e)
      count += events[e].second;
    const double high =
        e < events.size() ? std::min (events[e].first, max_scale) : max_scale;
    if (count > 0 && !steps.empty() && steps.back().count == count &&
        steps.back().high == low)
      steps.back().high = high; // events that leave the count as it was
    else if (count > 0)
      steps.push_back ({low, high, count});
    low = high;
  }
  const auto length = [] (const Step* s) {
    return s ? std::log (s->high / s->low) : 0.0;
  };
  // The longest of the steps of a count of two or more other than \a s.
  const auto longest_other_split = [&] (const Step* s) {
    double longest = 0.0;
    for (const Step& other : steps)
      if (other.count > 1 && &other != s)
        longest = std::max (longest, length (&other));
    return longest;
  };
  const double enough = std::log (gap_ratio);
  // The longest step of a split (a count of two or more), the finest split that
  // spans the gap ratio, and the longest step of one; the earliest of equally long
  // ones.
  const Step *split = nullptr, *finest = nullptr, *whole = nullptr;
  for (const Step& s : steps) {
    if (s.count > 1 && !finest && length (&s) >= enough)
      finest = &s;
    const Step*& best = s.count == 1 ? whole : split;
    if (length (&s) > length (best))
      best = &s;
  }
  const auto is_clear = [&] (const Step* s) {
    return length (s) >= enough && length (s) >= gap_ratio * longest_other_split (s);
  };
  if (finest && (preference == StableStepPreference::FINEST || !is_clear (split)))
    split = finest;
  const Step* chosen = split && (length (split) >= enough || !whole) ? split : whole;
  if (!chosen)
    return false;
  step.low = chosen->low;
  step.high = chosen->high;
  step.count = static_cast<std::size_t> (chosen->count);
  step.clear = is_clear (chosen);
  return true;
}

} // namespace tda
} // namespace pcl
