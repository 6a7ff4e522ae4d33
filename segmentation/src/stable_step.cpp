#include <pcl/tda/segmentation/stable_step.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace pcl {
namespace tda {

bool
longestStableStep (std::vector<std::pair<double, int>> events,
                   double floor,
                   double max_scale,
                   double gap_ratio,
                   bool censor_last,
                   StableStep& step)
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
    if (count > 0)
      steps.push_back ({low, high, count});
    low = high;
  }
  const auto length = [] (const Step* s) {
    return s ? std::log (s->high / s->low) : 0.0;
  };
  // The longest step of a split (a count of two or more; those cut short at the end
  // apart when censored) and of one; the earliest of equally long ones.
  const Step *split = nullptr, *cut_short = nullptr, *whole = nullptr;
  for (const Step& s : steps) {
    const Step*& best = s.count == 1                           ? whole
                        : censor_last && !(s.high < max_scale) ? cut_short
                                                               : split;
    if (length (&s) > length (best))
      best = &s;
  }
  const double enough = std::log (gap_ratio);
  if (length (split) < enough && length (cut_short) >= enough)
    split = cut_short;
  const Step* chosen = split && (length (split) >= enough || !whole) ? split : whole;
  if (!chosen)
    return false;
  double runner_up = 0.0;
  for (const Step& s : steps)
    if (s.count > 1 && &s != chosen)
      runner_up = std::max (runner_up, length (&s));
  step.low = chosen->low;
  step.high = chosen->high;
  step.count = static_cast<std::size_t> (chosen->count);
  step.clear = length (chosen) >= enough && length (chosen) >= gap_ratio * runner_up;
  return true;
}

} // namespace tda
} // namespace pcl
