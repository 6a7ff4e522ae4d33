#pragma once

// Random point sets and brute-force radius graphs for the grid and complex size
// tests.

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/point3d.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace pcl {
namespace tda {
namespace test {

/** Random points with duplicates and lattice points whose distances hit the radius
 * exactly (spacing r / 2 on a grid), to exercise the test near the radius. */
inline std::vector<Point3d>
randomPoints (std::mt19937& random, std::size_t n, double radius)
{
  std::uniform_real_distribution<double> coordinate (-1.0, 1.0);
  std::uniform_int_distribution<int> lattice (-6, 6);
  std::vector<Point3d> points;
  while (points.size() < n) {
    const int kind = static_cast<int> (points.size() % 4);
    if (kind == 0 && !points.empty())
      points.push_back (points[random() % points.size()]); // a duplicate
    else if (kind == 1)
      points.push_back ({lattice (random) * radius / 2,
                         lattice (random) * radius / 2,
                         lattice (random) * radius / 2});
    else
      points.push_back (
          {coordinate (random), coordinate (random), coordinate (random)});
  }
  return points;
}

inline std::vector<FilteredEdge>
bruteForceEdges (const std::vector<Point3d>& points, double radius, bool odd_sum_only)
{
  std::vector<FilteredEdge> edges;
  for (SimplexIndex a = 0; a < points.size(); ++a)
    for (SimplexIndex b = a + 1; b < points.size(); ++b)
      if (withinRadius (points[a], points[b], radius) &&
          (!odd_sum_only || (a + b) % 2 == 1))
        edges.push_back ({a, b, distance (points[a], points[b])});
  std::sort (edges.begin(), edges.end(), edgeFiltrationLess);
  return edges;
}

inline void
expectSameEdges (const std::vector<FilteredEdge>& actual,
                 const std::vector<FilteredEdge>& expected,
                 const std::string& what)
{
  ASSERT_EQ (actual.size(), expected.size()) << what;
  for (std::size_t e = 0; e < actual.size(); ++e) {
    ASSERT_EQ (actual[e].source, expected[e].source) << what << " edge " << e;
    ASSERT_EQ (actual[e].target, expected[e].target) << what << " edge " << e;
    ASSERT_EQ (actual[e].value, expected[e].value) << what << " edge " << e;
  }
}

struct OddSum {
  bool
  operator() (SimplexIndex a, SimplexIndex b) const
  {
    return (a + b) % 2 == 1;
  }
};

} // namespace test
} // namespace tda
} // namespace pcl
