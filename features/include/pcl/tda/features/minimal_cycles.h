#pragma once

#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/common/progress.h>

#include <vector>

namespace pcl {
namespace tda {

/** \brief A minimal 1-cycle: the shortest cycle of the complex around one empty
 * region inside the initial cycle of an essential 1-class (Alg 5.15). */
struct MinimalCycle {
  /** \brief The unpaired positive edge of the class. */
  SimplexIndex essential_edge = INVALID_SIMPLEX;
  /** \brief The vertices in cycle order (the last joins the first). */
  std::vector<SimplexIndex> vertices;
  /** \brief The empty region's centre: its point farthest from every vertex, in
   * the plane of the initial cycle. */
  Point3d hole_center{0.0, 0.0, 0.0};
  /** \brief Its distance to the nearest vertex: the radius of the region's largest
   * empty disk. */
  double clearance = 0.0;
};

/** \brief The unpaired positive edges of \a result (it must hold H1): one per
 * essential 1-class, in filtration order. */
std::vector<SimplexIndex>
essentialEdges (const PersistenceResult& result);

/** \brief The minimal 1-cycles around the empty regions that the essential
 * 1-classes of \a complex go around (thesis Alg 5.15, Sec 5.4.1), class by class in
 * the order of essentialEdges().
 *
 * For the unpaired positive edge uv of a class:
 * 1. The initial cycle is uv and the path from u to v in the spanning forest of the
 *    negative edges (the forest is rooted once, so a path costs its own length).
 * 2. The cycle's points are projected onto their least-squares plane
 *    (ProjectedPolygon). The vertices inside the polygon are those reached from the
 *    cycle through edges of the complex without leaving the polygon, so that the far
 *    side of a curved surface, which may project inside too, is not taken.
 * 3. Chords are the edges among the cycle's and the inner vertices that lie inside
 *    the polygon: an edge is kept when its midpoint projects inside (this covers
 *    the three corner cases of Fig 5.6: boundary-boundary, interior-boundary and
 *    interior-interior edges); the cycle's own edges are kept.
 * 4. The thesis then takes the shortest path from u to v over the cycle and its
 *    chords (BFS). That path can close on the near side of uv, around nothing (a
 *    cycle that bounds), and the initial cycle of one class often goes around
 *    several holes. So the holes are located first: the empty regions of the
 *    polygon, where the distance to every vertex is at least \a min_clearance (on
 *    a grid of at most 128 x 128 cells). Around the centre of each, the minimal
 *    cycle is the shortest closed path over the cycle and its chords that winds
 *    around the centre an odd number of times (Dijkstra by edge length on two copies
 *    of the graph, the copy switched by every crossing of a ray from the centre),
 *    from the vertex nearest the centre.
 *
 * Classes are independent: they are computed in parallel, and each result depends
 * only on the complex, not on the number of threads. Several classes may give
 * cycles around the same hole (holeRims() keeps one).
 * \param[in] complex the filtered complex
 * \param[in] result its persistence, with H1 (max_dimension 1)
 * \param[in] positions the position of every vertex of \a complex
 * \param[in] adjacency the neighbours of every vertex (all edges of \a complex)
 * \param[in] min_clearance the radius of the smallest empty disk that makes a hole
 * \param[in] threads number of threads (0: OpenMP's default)
 * \param[in] progress optional callback (classes searched, classes), called from
 * one thread */
std::vector<MinimalCycle>
minimalCycles (const FilteredComplex& complex,
               const PersistenceResult& result,
               const std::vector<Point3d>& positions,
               const EdgeAdjacency& adjacency,
               double min_clearance,
               unsigned int threads = 0,
               const ProgressCallback& progress = {});

} // namespace tda
} // namespace pcl
