#include <pcl/tda/common/plane_fit.h>
#include <pcl/tda/common/union_find.h>
#include <pcl/tda/features/signature_types.h>
#include <pcl/tda/features/stpp_sublevel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace pcl {
namespace tda {

std::array<std::vector<double>, STPP_SUBLEVEL_FUNCTIONS>
shapeFunctions (const std::vector<Point3d>& points, double size)
{
  std::array<std::vector<double>, STPP_SUBLEVEL_FUNCTIONS> functions;
  if (points.empty())
    return functions;
  PlaneFit spread (points.front());
  for (const Point3d& p : points)
    spread.add (p);
  const Eigen::Vector3d centroid = spread.centroid();
  const Eigen::Matrix3d axes = spread.principalAxes();
  for (auto& f : functions)
    f.reserve (points.size());
  for (const Point3d& p : points) {
    const Eigen::Vector3d d = Eigen::Vector3d (p[0], p[1], p[2]) - centroid;
    functions[0].push_back (d.norm() / size);
    for (int axis = 0; axis < 3; ++axis)
      functions[1 + axis].push_back (d.dot (axes.col (axis)) / size);
  }
  for (std::size_t k = 1; k < STPP_SUBLEVEL_FUNCTIONS; ++k) {
    double third_moment = 0.0;
    for (const double x : functions[k])
      third_moment += x * x * x;
    if (third_moment < 0.0)
      for (double& x : functions[k])
        x = -x;
  }
  return functions;
}

void
sublevelValues (const FilteredComplex& complex,
                const std::vector<double>& f,
                float* values)
{
  const std::size_t n = complex.numVertices();
  std::vector<double> height (n);
  const pcl::Indices& point_indices = complex.pointIndices();
  for (std::size_t v = 0; v < n; ++v)
    height[v] =
        f[point_indices.empty() ? v : static_cast<std::size_t> (point_indices[v])];
  if (n == 0) {
    std::fill (values, values + STPP_SUBLEVEL_PER_FUNCTION, 0.0f);
    return;
  }
  const auto [lowest, highest] = std::minmax_element (height.begin(), height.end());
  const double low = *lowest, high = *highest;
  const double step = (high - low) / static_cast<double> (STPP_CURVE_SAMPLES);

  // H0 of the lower-star filtration (an edge enters with its higher end): when an
  // edge joins two components, the one born higher dies (the elder rule).
  std::vector<std::pair<double, std::size_t>> edge_heights;
  edge_heights.reserve (complex.numEdges());
  const std::vector<FilteredEdge>& edges = complex.edges();
  for (std::size_t e = 0; e < edges.size(); ++e)
    edge_heights.emplace_back (
        std::max (height[edges[e].source], height[edges[e].target]), e);
  std::sort (edge_heights.begin(), edge_heights.end());
  // A component is named by its lowest vertex, where it was born; death[v] is the
  // value at which the component born at v joins an older one.
  UnionFind components (n);
  std::vector<std::uint32_t> lowest_vertex (n); // of each component, at its root
  std::iota (lowest_vertex.begin(), lowest_vertex.end(), std::uint32_t{0});
  std::vector<double> death (n, std::numeric_limits<double>::infinity());
  for (const auto& [value, e] : edge_heights) {
    const auto a = components.find (static_cast<std::uint32_t> (edges[e].source));
    const auto b = components.find (static_cast<std::uint32_t> (edges[e].target));
    if (a == b)
      continue;
    const bool a_younger = height[lowest_vertex[a]] > height[lowest_vertex[b]];
    death[lowest_vertex[a_younger ? a : b]] = value;
    const std::uint32_t elder = lowest_vertex[a_younger ? b : a];
    lowest_vertex[components.linkRoots (a, b)] = elder;
  }

  // The components alive at t that live at least one step between samples: a piece
  // of the sampling that parts from the rest for a moment is not counted.
  for (std::size_t j = 0; j < STPP_CURVE_SAMPLES; ++j) {
    const double t = low + step * (static_cast<double> (j) + 0.5);
    std::size_t below = 0, pieces = 0;
    for (std::size_t v = 0; v < n; ++v) {
      if (height[v] > t)
        continue;
      ++below;
      pieces += t < death[v] && death[v] - height[v] >= step ? 1 : 0;
    }
    values[j] =
        static_cast<float> (static_cast<double> (below) / static_cast<double> (n));
    values[STPP_CURVE_SAMPLES + j] =
        static_cast<float> (std::log2 (1.0 + static_cast<double> (pieces)));
  }
  values[2 * STPP_CURVE_SAMPLES] = static_cast<float> (high - low);
}

} // namespace tda
} // namespace pcl
