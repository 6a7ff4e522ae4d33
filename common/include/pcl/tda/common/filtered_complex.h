#pragma once

#include <pcl/types.h>

#include <array>
#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Index of a simplex among the simplices of its own dimension.
 *
 * 32 bits: the builders refuse a complex with more simplices of one dimension.
 */
using SimplexIndex = std::uint32_t;

/** \brief Marks "no simplex" (e.g. the death simplex of an essential class). */
constexpr SimplexIndex INVALID_SIMPLEX = std::numeric_limits<SimplexIndex>::max();

/** \brief An edge of a filtered complex: two vertex ids (source < target) and its
 * filtration value (for a Vietoris-Rips complex, its Euclidean length). */
struct FilteredEdge {
  SimplexIndex source;
  SimplexIndex target;
  double value;
};

/** \brief The filtration order of edges: by (value, source, target). A strict total
 * order on distinct edges, so that any correct sort gives the same list. A function
 * object rather than a function, so that the sorts that take it inline it. */
struct EdgeFiltrationLess {
  bool
  operator() (const FilteredEdge& a, const FilteredEdge& b) const
  {
    return std::tie (a.value, a.source, a.target) <
           std::tie (b.value, b.source, b.target);
  }
};

/** \brief The filtration order of edges (EdgeFiltrationLess). */
constexpr EdgeFiltrationLess edgeFiltrationLess{};

/** \brief A triangle of a filtered complex: its three edge ids in decreasing
 * filtration order (edges[0] is the youngest) and its filtration value (for a
 * Vietoris-Rips complex, the value of its longest edge). */
struct FilteredTriangle {
  std::array<SimplexIndex, 3> edges;
  double value;
};

/** \brief A simplex in the global filtration order: its dimension and its index
 * among the simplices of that dimension. */
struct SimplexRef {
  std::uint8_t dimension;
  SimplexIndex index;
};

/** \brief A filtered simplicial complex of dimension at most 2, kept in filtration
 * order, with the map from its vertices back to input point indices.
 *
 * Vertices enter at value 0. Edges are sorted by (value, source, target), triangles
 * by (value, edges[0], edges[1], edges[2]). The global filtration lists all
 * vertices, then edges and triangles merged by value, an edge before a triangle of
 * equal value: every face precedes its cofaces. This is the complex every
 * persistence engine of PCL-TDA reads (thesis Sec 2.6, Ch. 3).
 */
class FilteredComplex {
public:
  FilteredComplex() = default;

  /** \brief Takes parts that are already in filtration order and checks them.
   * \param[in] num_vertices number of vertices
   * \param[in] edges edges sorted by (value, source, target), source < target, on
   * distinct vertex pairs (not checked here: fromLists() and the readers check it)
   * \param[in] triangles triangles sorted by (value, edges), each no younger than
   * its edges, whose three edges form a triangle
   * \param[in] point_indices input point index of each vertex (empty: identity)
   * \throws pcl::BadArgumentException when a part is out of order or invalid
   */
  FilteredComplex (std::size_t num_vertices,
                   std::vector<FilteredEdge> edges,
                   std::vector<FilteredTriangle> triangles,
                   pcl::Indices point_indices = {});

  /** \brief Takes parts that are valid and in filtration order by construction, as
   * the complex builders make them, without checking them (the checks of the
   * constructor cost as much as a builder phase). Parts as for the constructor. */
  static FilteredComplex
  adoptValidParts (std::size_t num_vertices,
                   std::vector<FilteredEdge> edges,
                   std::vector<FilteredTriangle> triangles,
                   pcl::Indices point_indices);

  /** \brief Builds a complex from plain lists in any order, e.g. for tests and
   * random complexes. A triangle is given by its vertices; its value is the largest
   * value of its edges, which must all be in \a edges.
   * \throws pcl::BadArgumentException on a missing edge, a duplicate, a loop or a
   * vertex out of range
   */
  static FilteredComplex
  fromLists (std::size_t num_vertices,
             std::vector<FilteredEdge> edges,
             const std::vector<std::array<SimplexIndex, 3>>& triangles);

  std::size_t
  numVertices () const
  {
    return num_vertices_;
  }

  std::size_t
  numEdges () const
  {
    return edges_.size();
  }

  std::size_t
  numTriangles () const
  {
    return triangles_.size();
  }

  /** \brief Total number of simplices of all dimensions. */
  std::size_t
  numSimplices () const
  {
    return num_vertices_ + edges_.size() + triangles_.size();
  }

  const std::vector<FilteredEdge>&
  edges () const
  {
    return edges_;
  }

  const std::vector<FilteredTriangle>&
  triangles () const
  {
    return triangles_;
  }

  /** \brief Input point index of every vertex. */
  const pcl::Indices&
  pointIndices () const
  {
    return point_indices_;
  }

  /** \brief Filtration value of a simplex (0 for vertices). */
  double
  value (const SimplexRef& simplex) const;

  /** \brief The three vertices of a triangle, in increasing order. */
  std::array<SimplexIndex, 3>
  triangleVertices (SimplexIndex triangle) const;

  /** \brief All simplices in global filtration order. */
  std::vector<SimplexRef>
  filtrationOrder () const;

private:
  std::size_t num_vertices_ = 0;
  std::vector<FilteredEdge> edges_;
  std::vector<FilteredTriangle> triangles_;
  pcl::Indices point_indices_;
};

} // namespace tda
} // namespace pcl
