#pragma once

#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/common/progress.h>

#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief A minimal 1-cycle: the shortest cycle of the complex around one empty
 * region inside an initial cycle (Alg 5.15). */
struct MinimalCycle {
  /** \brief The positive edge of the initial cycle's class (InitialCycle). */
  SimplexIndex class_edge = INVALID_SIMPLEX;
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

/** \brief The positive edges of value at most \a radius whose 1-classes are still
 * alive at \a persistence_radius (their death, \a edge_death, is larger), in
 * filtration order: the classes of the complex of radius \a radius that persist.
 *
 * A hole whose largest empty disk has radius rho lives until about sqrt(3) rho, the
 * side of the equilateral triangle inscribed in its rim; the gaps of a sampling die
 * soon after they are born. With a persistence radius below sqrt(3) times the
 * smallest hole radius, the persistent classes are the holes, the handles and the
 * loops around tubes: tens of classes where the complex has thousands of essential
 * ones.
 * \param[in] edges the edges in filtration order
 * \param[in] edge_positive per edge, 1 when it creates a 1-class
 * \param[in] edge_death per edge, the value at which its 1-class dies
 * (CliqueH1Persistence::edge_death; infinity for an essential class)
 * \param[in] radius the largest birth
 * \param[in] persistence_radius the value at which the classes must be alive */
std::vector<SimplexIndex>
persistentClassEdges (const std::vector<FilteredEdge>& edges,
                      const std::vector<std::uint8_t>& edge_positive,
                      const std::vector<double>& edge_death,
                      double radius,
                      double persistence_radius);

/** \brief A closed polygon of vertices whose inside is searched for holes: the
 * initial cycle of a 1-class, or a polygon around a border (borderPolygons()). */
struct InitialCycle {
  /** \brief The vertices in order (the last joins the first). */
  std::vector<SimplexIndex> vertices;
  /** \brief The positive edge of the class, or INVALID_SIMPLEX for a polygon that
   * is not a class' cycle. */
  SimplexIndex class_edge = INVALID_SIMPLEX;
};

/** \brief The initial cycles of the classes of \a class_edges (thesis Alg 5.15), in
 * their order: for the positive edge uv, the path from u to v in the spanning forest
 * of the negative edges, closed by uv (the forest is rooted once, so a path costs
 * its own length).
 * \param[in] complex the filtered complex
 * \param[in] edge_positive per edge of \a complex, 1 when it creates a 1-class
 * (PersistenceResult::edge_positive): the others form the spanning forest
 * \param[in] class_edges the positive edges of the classes, e.g. essentialEdges()
 * or persistentClassEdges() */
std::vector<InitialCycle>
classCycles (const FilteredComplex& complex,
             const std::vector<std::uint8_t>& edge_positive,
             const std::vector<SimplexIndex>& class_edges);

/** \brief The minimal 1-cycles around the empty regions inside the initial cycles
 * \a initial (thesis Alg 5.15, Sec 5.4.1), cycle by cycle in their order.
 *
 * For each initial cycle (step 1 of Alg 5.15, classCycles()):
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
 * 5. When no such path exists, the polygon cuts through the region's hole (a
 *    border polygon around a centre guessed off the hole's): the region is searched
 *    again, up to three times, from the star polygon around its widest point
 *    (starPolygonAround()) that reaches 1.5 times its clearance and two edges
 *    beyond.
 *
 * Initial cycles are independent: they are searched in parallel, and each result
 * depends only on the complex, not on the number of threads. Several initial cycles
 * may give rims around the same hole (holeRims() keeps one). A long initial cycle
 * (1000 points or more) that shares 90 % of its points, and of the other's, with an
 * earlier one is not searched: many classes can go around the same large region
 * with nearly the same cycle, and would search the same empty regions again.
 * \param[in] complex the filtered complex (the lengths of its edges)
 * \param[in] initial the initial cycles
 * \param[in] positions the position of every vertex of \a complex
 * \param[in] adjacency the neighbours of every vertex: the edges of the complex the
 * rims are searched in (all of \a complex, or those up to some radius)
 * \param[in] min_clearance the radius of the smallest empty disk that makes a hole
 * \param[in] threads number of threads (0: OpenMP's default)
 * \param[in] progress optional callback (cycles searched, cycles), called from
 * one thread */
std::vector<MinimalCycle>
minimalCycles (const FilteredComplex& complex,
               const std::vector<InitialCycle>& initial,
               const std::vector<Point3d>& positions,
               const EdgeAdjacency& adjacency,
               double min_clearance,
               unsigned int threads = 0,
               const ProgressCallback& progress = {});

} // namespace tda
} // namespace pcl
