#pragma once

#include <pcl/tda/common/filtered_complex.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace pcl {
namespace tda {

/** \brief A point of R^3 in double precision, as the builders measure distances. */
using Point3d = std::array<double, 3>;

/** \brief The r-neighbourhood graph of points in canonical order, in compressed
 * sparse row form (thesis Sec 3.3): the neighbours of vertex i are the vertices
 * j > i within the radius, in increasing order, at positions offsets[i] to
 * offsets[i + 1] of \a neighbors, with their distances in \a lengths. */
struct NeighborGraph {
  std::vector<std::uint64_t> offsets;
  std::vector<SimplexIndex> neighbors;
  std::vector<double> lengths;

  std::size_t
  numVertices () const
  {
    return offsets.empty() ? 0 : offsets.size() - 1;
  }

  std::size_t
  numEdges () const
  {
    return neighbors.size();
  }
};

/** \brief Lists candidate neighbours of a vertex: any set of vertices that holds all
 * later vertices (larger ids, i.e. later in canonical order) within the radius; the
 * exact test is made afterwards. Must be callable from several threads at once. */
using CandidateSearch =
    std::function<void (SimplexIndex vertex, std::vector<SimplexIndex>& candidates)>;

/** \brief Candidate search by a uniform grid of cubic cells of the radius' size.
 * Canonical order sorts by x first, so a later point lies in the same cell column
 * or in the next one in x: the candidates of a point are the points of the 18 cells
 * of those two layers around its cell, found once per cell at construction. */
class UniformGridSearch {
public:
  /** \throws pcl::BadArgumentException when the radius is not positive or so small
   * against the extent of the points that cells cannot be indexed */
  UniformGridSearch (const std::vector<Point3d>& points, double radius);

  void
  operator() (SimplexIndex vertex, std::vector<SimplexIndex>& candidates) const;

private:
  using CellKey = std::array<std::int64_t, 3>;

  CellKey
  cellOf (const Point3d& point) const;

  /** Six runs [begin, end) of point_ids_: the cells (x + dx, y + dy, z - 1 .. z + 1)
   * for dx in {0, 1} and dy in {-1, 0, 1}. */
  using Stencil = std::array<std::pair<std::uint32_t, std::uint32_t>, 6>;

  double radius_;
  Point3d origin_;
  std::vector<SimplexIndex> point_ids_; // points grouped by cell, cells in key order
  std::vector<std::uint32_t> cell_of_point_; // index of every point's cell
  std::vector<Stencil> stencils_;            // one per non-empty cell
};

/** \brief Count pass of the neighbour search (thesis Alg 3.2): the number of
 * neighbours j > i within \a radius of every vertex i, in parallel. */
std::vector<std::uint32_t>
countNeighbors (const std::vector<Point3d>& points,
                double radius,
                const CandidateSearch& search);

/** \brief Prefix sum and fill pass of the neighbour search (thesis Alg 3.2-3.3):
 * the graph whose vertex i has \a counts[i] neighbours, filled in parallel. */
NeighborGraph
fillNeighborGraph (const std::vector<Point3d>& points,
                   double radius,
                   const CandidateSearch& search,
                   const std::vector<std::uint32_t>& counts);

/** \brief Euclidean distance of two points. */
double
distance (const Point3d& a, const Point3d& b);

} // namespace tda
} // namespace pcl
