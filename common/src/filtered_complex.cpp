#include <pcl/tda/common/filtered_complex.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>
#include <unordered_map>

namespace pcl {
namespace tda {

namespace {

bool
triangleLess (const FilteredTriangle& a, const FilteredTriangle& b)
{
  return std::tie (a.value, a.edges) < std::tie (b.value, b.edges);
}

std::uint64_t
edgeKey (SimplexIndex u, SimplexIndex v)
{
  return (static_cast<std::uint64_t> (std::min (u, v)) << 32) | std::max (u, v);
}

} // namespace

FilteredComplex::FilteredComplex (std::size_t num_vertices,
                                  std::vector<FilteredEdge> edges,
                                  std::vector<FilteredTriangle> triangles,
                                  pcl::Indices point_indices)
: num_vertices_ (num_vertices)
, edges_ (std::move (edges))
, triangles_ (std::move (triangles))
, point_indices_ (std::move (point_indices))
{
  if (num_vertices_ >= INVALID_SIMPLEX || edges_.size() >= INVALID_SIMPLEX ||
      triangles_.size() >= INVALID_SIMPLEX)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "complex too large for 32-bit simplex ids");
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const FilteredEdge& edge = edges_[e];
    if (!(edge.source < edge.target && edge.target < num_vertices_))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "edge " << e << " (" << edge.source << ", " << edge.target
                                   << ") is not a pair of distinct vertices < "
                                   << num_vertices_);
    if (!std::isfinite (edge.value) || edge.value < 0.0)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "edge " << e << " has value " << edge.value
                                   << "; values must be finite and >= 0");
    if (e > 0 && !edgeFiltrationLess (edges_[e - 1], edge))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "edges " << e - 1 << " and " << e
                                    << " are duplicates or out of filtration order");
  }
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const FilteredTriangle& triangle = triangles_[t];
    const auto& ids = triangle.edges;
    if (!(ids[0] < edges_.size() && ids[0] > ids[1] && ids[1] > ids[2]))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "triangle " << t
                                       << " needs three distinct edge ids in "
                                          "decreasing order");
    std::array<SimplexIndex, 6> ends{edges_[ids[0]].source,
                                     edges_[ids[0]].target,
                                     edges_[ids[1]].source,
                                     edges_[ids[1]].target,
                                     edges_[ids[2]].source,
                                     edges_[ids[2]].target};
    std::sort (ends.begin(), ends.end());
    const bool closed = ends[0] == ends[1] && ends[2] == ends[3] &&
                        ends[4] == ends[5] && ends[1] != ends[2] && ends[3] != ends[4];
    if (!closed)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "the edges of triangle " << t << " do not form a triangle");
    if (!(triangle.value >= edges_[ids[0]].value) || !std::isfinite (triangle.value))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "triangle " << t << " enters before its edges");
    if (t > 0 && !triangleLess (triangles_[t - 1], triangle))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "triangles "
                               << t - 1 << " and " << t
                               << " are duplicates or out of filtration order");
  }
  if (point_indices_.empty()) {
    point_indices_.resize (num_vertices_);
    std::iota (point_indices_.begin(), point_indices_.end(), 0);
  }
  else if (point_indices_.size() != num_vertices_)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "point_indices has " << point_indices_.size()
                                              << " entries for " << num_vertices_
                                              << " vertices");
}

FilteredComplex
FilteredComplex::adoptValidParts (std::size_t num_vertices,
                                  std::vector<FilteredEdge> edges,
                                  std::vector<FilteredTriangle> triangles,
                                  pcl::Indices point_indices)
{
  FilteredComplex complex;
  complex.num_vertices_ = num_vertices;
  complex.edges_ = std::move (edges);
  complex.triangles_ = std::move (triangles);
  complex.point_indices_ = std::move (point_indices);
  return complex;
}

FilteredComplex
FilteredComplex::fromLists (std::size_t num_vertices,
                            std::vector<FilteredEdge> edges,
                            const std::vector<std::array<SimplexIndex, 3>>& triangles)
{
  for (auto& edge : edges) {
    if (edge.source == edge.target ||
        std::max (edge.source, edge.target) >= num_vertices)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "edge ("
                               << edge.source << ", " << edge.target
                               << ") is a loop or names a vertex >= " << num_vertices);
    if (edge.source > edge.target)
      std::swap (edge.source, edge.target);
  }
  std::sort (edges.begin(), edges.end(), edgeFiltrationLess);

  std::unordered_map<std::uint64_t, SimplexIndex> edge_ids;
  edge_ids.reserve (edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (!edge_ids.emplace (edgeKey (edges[e].source, edges[e].target), e).second)
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "edge (" << edges[e].source << ", " << edges[e].target
                                    << ") is listed twice");

  std::vector<FilteredTriangle> filtered_triangles;
  filtered_triangles.reserve (triangles.size());
  for (const auto& vertices : triangles) {
    FilteredTriangle triangle;
    const std::array<std::pair<SimplexIndex, SimplexIndex>, 3> sides{
        {{vertices[0], vertices[1]},
         {vertices[0], vertices[2]},
         {vertices[1], vertices[2]}}};
    for (std::size_t side = 0; side < 3; ++side) {
      const auto found =
          edge_ids.find (edgeKey (sides[side].first, sides[side].second));
      if (found == edge_ids.end())
        PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                             "triangle (" << vertices[0] << ", " << vertices[1] << ", "
                                          << vertices[2] << ") lacks edge ("
                                          << sides[side].first << ", "
                                          << sides[side].second << ")");
      triangle.edges[side] = found->second;
    }
    std::sort (triangle.edges.begin(), triangle.edges.end(), std::greater<>());
    triangle.value = edges[triangle.edges[0]].value;
    filtered_triangles.push_back (triangle);
  }
  std::sort (filtered_triangles.begin(), filtered_triangles.end(), triangleLess);
  return FilteredComplex (
      num_vertices, std::move (edges), std::move (filtered_triangles));
}

double
FilteredComplex::value (const SimplexRef& simplex) const
{
  switch (simplex.dimension) {
  case 0:
    return 0.0;
  case 1:
    return edges_[simplex.index].value;
  default:
    return triangles_[simplex.index].value;
  }
}

std::array<SimplexIndex, 3>
FilteredComplex::triangleVertices (SimplexIndex triangle) const
{
  const auto& ids = triangles_[triangle].edges;
  std::array<SimplexIndex, 3> vertices{
      edges_[ids[0]].source, edges_[ids[0]].target, edges_[ids[1]].source};
  if (vertices[2] == vertices[0] || vertices[2] == vertices[1])
    vertices[2] = edges_[ids[1]].target;
  std::sort (vertices.begin(), vertices.end());
  return vertices;
}

std::vector<SimplexRef>
FilteredComplex::filtrationOrder() const
{
  std::vector<SimplexRef> order;
  order.reserve (numSimplices());
  for (SimplexIndex v = 0; v < num_vertices_; ++v)
    order.push_back ({0, v});
  std::size_t e = 0, t = 0;
  while (e < edges_.size() || t < triangles_.size()) {
    if (t == triangles_.size() ||
        (e < edges_.size() && edges_[e].value <= triangles_[t].value))
      order.push_back ({1, static_cast<SimplexIndex> (e++)});
    else
      order.push_back ({2, static_cast<SimplexIndex> (t++)});
  }
  return order;
}

} // namespace tda
} // namespace pcl
