#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The widest gap between consecutive directions around a point. */
struct AngularGap {
  /** \brief Its width in radians (2 pi for a single direction). */
  double width;
  /** \brief The angle that halves it. */
  double middle;
};

/** \brief The widest gap between the directions around a point, given as angles in
 * radians (e.g. atan2 in a plane fitted to the point's neighbourhood): a point on
 * the rim of a hole sees empty surface on one side, a point inside a surface sees
 * it all round. The hole detection's border test and the benchmark that cuts holes
 * into scans share it.
 * \param[in,out] angles at least one angle in [-pi, pi]; sorted on return
 */
inline AngularGap
widestAngularGap (std::vector<double>& angles)
{
  std::sort (angles.begin(), angles.end());
  AngularGap gap{angles.front() + 2.0 * M_PI - angles.back(), 0.0};
  gap.middle = angles.back() + gap.width / 2.0;
  for (std::size_t k = 1; k < angles.size(); ++k)
    if (angles[k] - angles[k - 1] > gap.width) {
      gap.width = angles[k] - angles[k - 1];
      gap.middle = angles[k - 1] + gap.width / 2.0;
    }
  return gap;
}

} // namespace tda
} // namespace pcl
