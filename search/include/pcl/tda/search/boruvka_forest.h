#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/common/union_find.h>
#include <pcl/tda/search/radius_edges.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace pcl {
namespace tda {

/** \brief "No edge": above every edge in the filtration order. */
constexpr FilteredEdge NO_EDGE{0, 0, std::numeric_limits<double>::infinity()};

/** \brief A k-d tree over 3D points for Borůvka's search of the shortest edge out of
 * each component of a spanning forest under construction. Besides its bounding box,
 * each node knows, for the current components (labelComponents()), the one component
 * all its points belong to, if there is one: a search skips the parts of its own
 * component whole, and the parts farther than the shortest edge found so far. */
class ComponentKdTree {
public:
  /** \brief Most points of a leaf. */
  static constexpr std::uint32_t LEAF_SIZE = 16;

  /** \brief Builds the tree over \a points (at most 2^32 - 1 of them). */
  explicit ComponentKdTree (const std::vector<Point3d>& points);

  /** \brief Number of points; the tree's positions are 0..size()-1. */
  std::size_t
  size () const
  {
    return ids_.size();
  }

  /** \brief The component of the point at tree position \a position, as read by the
   * last labelComponents(). */
  std::uint32_t
  componentAt (std::uint32_t position) const
  {
    return component_at_[position];
  }

  /** \brief Reads each point's component (its representative in \a components) and
   * labels each node with the component all its points lie in, if any. */
  void
  labelComponents (UnionFind& components);

  /** \brief The shortest edge, in the filtration order (length, then ends), from the
   * point at tree position \a position to a point of another component within
   * \a radius (withinRadius()) that passes \a accept, or NO_EDGE.
   * \param[in] position the point's tree position (0..size()-1)
   * \param[in] radius the longest edge (> 0)
   * \param[in,out] bound the length of the shortest edge found so far out of this
   * component (shared with the searches from its other points): a part of the tree
   * farther away is not searched, and a shorter edge found lowers it
   * \param[in] accept the symmetric pair test accept(a, b) of point ids */
  template <typename Accept>
  FilteredEdge
  shortestEdgeAcross (std::uint32_t position,
                      double radius,
                      const Accept& accept,
                      std::atomic<double>& bound) const;

private:
  struct Node {
    Point3d low, high;   // bounding box of its points
    std::uint32_t begin; // its points: positions begin..end-1
    std::uint32_t end;
    std::uint32_t left; // children left and left + 1; 0 for a leaf
  };

  /** Builds node \a node over positions begin..end-1, and its children. */
  void
  build (std::uint32_t node, std::uint32_t begin, std::uint32_t end);

  /** Squared distance from \a p to the box of \a node (0 inside). */
  double
  squaredDistanceToBox (const Point3d& p, const Node& node) const
  {
    double squared = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double d = std::max ({node.low[k] - p[k], p[k] - node.high[k], 0.0});
      squared += d * d;
    }
    return squared;
  }

  static constexpr std::uint32_t MIXED = std::numeric_limits<std::uint32_t>::max();
  std::vector<Point3d> points_;               // per position
  std::vector<std::uint32_t> ids_;            // per position: the point's id
  std::vector<std::uint32_t> component_at_;   // per position: the point's component
  std::vector<Node> nodes_;                   // node 0 the root
  std::vector<std::uint32_t> node_component_; // per node: its one component, or MIXED
};

template <typename Accept>
FilteredEdge
ComponentKdTree::shortestEdgeAcross (std::uint32_t position,
                                     double radius,
                                     const Accept& accept,
                                     std::atomic<double>& bound) const
{
  // Squared lengths are compared with a margin above the exact test, so a part of the
  // tree or a point is skipped only when it is surely farther than the limit.
  constexpr double MARGIN = 1.0 + 1e-6;
  const Point3d& p = points_[position];
  const std::uint32_t own = component_at_[position];
  const std::uint32_t a = ids_[position];
  FilteredEdge best = NO_EDGE;
  double limit = std::min (radius, bound.load (std::memory_order_relaxed));
  const auto beyond = [&limit] (double squared) {
    return squared > limit * limit * MARGIN;
  };
  // Depth-first, nearer child first: at most one pending sibling per level. Each
  // pending node keeps its squared distance to p, measured once.
  std::array<std::pair<std::uint32_t, double>, 128> stack;
  std::size_t pending = 0;
  stack[pending++] = {0, squaredDistanceToBox (p, nodes_[0])};
  while (pending > 0) {
    const auto [index, squared_distance] = stack[--pending];
    limit = std::min (limit, bound.load (std::memory_order_relaxed));
    if (node_component_[index] == own || beyond (squared_distance))
      continue;
    const Node& node = nodes_[index];
    if (node.left != 0) {
      const double first = squaredDistanceToBox (p, nodes_[node.left]);
      const double second = squaredDistanceToBox (p, nodes_[node.left + 1]);
      if (first <= second) {
        stack[pending++] = {node.left + 1, second};
        stack[pending++] = {node.left, first};
      }
      else {
        stack[pending++] = {node.left, first};
        stack[pending++] = {node.left + 1, second};
      }
      continue;
    }
    for (std::uint32_t j = node.begin; j < node.end; ++j) {
      const Point3d& q = points_[j];
      const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
      if (component_at_[j] == own || beyond (dx * dx + dy * dy + dz * dz) ||
          !withinRadius (p, q, radius))
        continue;
      const std::uint32_t b = ids_[j];
      const FilteredEdge edge{std::min (a, b), std::max (a, b), distance (p, q)};
      if (!edgeFiltrationLess (edge, best) || !accept (a, b))
        continue;
      best = edge;
      limit = std::min (limit, edge.value);
      double shared = bound.load (std::memory_order_relaxed);
      while (edge.value < shared && !bound.compare_exchange_weak (
                                        shared, edge.value, std::memory_order_relaxed))
        ;
    }
  }
  return best;
}

/** \brief Borůvka's algorithm on the radius graph of \a points, from components
 * already joined: in each round, the shortest edge out of each component (in the
 * filtration order, a strict total order) is found by one search per point on a
 * ComponentKdTree, and those edges join the components; the rounds end when no
 * component has an edge out within \a radius. Since the order is strict, the edges
 * are those of the one minimum spanning forest, as Kruskal's, edge for edge.
 *
 * It holds one edge per point, never the graph: where two large components lie within
 * the radius of each other (at a radius far above the spacing, a million pairs across
 * where one edge joins them), it takes time of the searches, not of the pairs.
 * \param[in] points the points, vertex v at points[v]
 * \param[in] radius the largest edge length (> 0)
 * \param[in] accept the extra symmetric test of a pair (a, b) of vertex ids
 * \param[in] threads OpenMP threads (0: OpenMP's default)
 * \param[in,out] components the components, joined by every edge shorter than any
 * pair across two of them (e.g. Kruskal's up to a length); joined
 * \param[in,out] forest the forest's edges so far; the new ones are appended in
 * filtration order */
template <typename Accept>
void
extendSpanningForestByBoruvka (const std::vector<Point3d>& points,
                               double radius,
                               const Accept& accept,
                               unsigned int threads,
                               UnionFind& components,
                               std::vector<FilteredEdge>& forest)
{
  ComponentKdTree tree (points);
  const auto num_points = static_cast<std::int64_t> (tree.size());
  std::vector<std::uint8_t> searching (tree.size(), 1); // its component may join
  std::vector<std::atomic<double>> bound (tree.size()); // per component
  std::vector<FilteredEdge> shortest (tree.size());     // per position, then component
  std::vector<FilteredEdge> joined;
  for (;;) {
    tree.labelComponents (components);
    for (auto& length : bound)
      length.store (radius, std::memory_order_relaxed);
#pragma omp parallel for schedule(dynamic, 256) num_threads(resolveThreads(threads))
    for (std::int64_t i = 0; i < num_points; ++i) {
      const auto position = static_cast<std::uint32_t> (i);
      shortest[i] =
          searching[i]
              ? tree.shortestEdgeAcross (
                    position, radius, accept, bound[tree.componentAt (position)])
              : NO_EDGE;
    }
    std::vector<FilteredEdge> out (tree.size(), NO_EDGE); // per component
    for (std::uint32_t i = 0; i < tree.size(); ++i) {
      FilteredEdge& of_component = out[tree.componentAt (i)];
      if (edgeFiltrationLess (shortest[i], of_component))
        of_component = shortest[i];
    }
    std::vector<FilteredEdge> chosen;
    for (std::uint32_t i = 0; i < tree.size(); ++i) {
      if (out[i].value != NO_EDGE.value)
        chosen.push_back (out[i]);
      if (out[tree.componentAt (i)].value == NO_EDGE.value)
        searching[i] = 0; // no edge out now, none after joins
    }
    if (chosen.empty())
      break;
    std::sort (chosen.begin(), chosen.end(), edgeFiltrationLess);
    for (const FilteredEdge& edge : chosen) {
      const std::uint32_t a = components.find (edge.source);
      const std::uint32_t b = components.find (edge.target);
      if (a != b) { // the same edge may leave both its components
        components.linkRoots (a, b);
        joined.push_back (edge);
      }
    }
  }
  std::sort (joined.begin(), joined.end(), edgeFiltrationLess);
  forest.insert (forest.end(), joined.begin(), joined.end());
}

} // namespace tda
} // namespace pcl
