#pragma once

#include <pcl/tda/common/cielab.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/common/progress.h>
#include <pcl/tda/search/complex_size.h>

#include <Eigen/Core>

#include <vector>

namespace pcl {
namespace tda {

/** \brief The homogeneity graph of region growing (thesis Sec 4.2.3-4.2.4) is the
 * neighbour graph of the points, every pair within the radius (the 1-skeleton of
 * VR_r), with each edge valued by the colour difference Delta E76 of its ends (Eq
 * 4.5), or by infinity when the angle between their normals (Eq 4.6) is above the
 * angle threshold. Filtering the graph by that value grows the regions of every
 * colour threshold at once: the components of the edges of value <= t are the
 * regions of threshold t. These functions build it in steps: neighborGraph(), then
 * optionally neighborNormals() and medianSmoothedColors(), then
 * valueByHomogeneity(). */

/** \brief The vertices of a homogeneity graph: points with their CIELAB colours
 * (converted once per point) and, optionally, unit surface normals. */
struct HomogeneityVertices {
  /** \brief Position of vertex v. */
  std::vector<Point3d> points;
  /** \brief CIELAB colour of vertex v. */
  std::vector<LabColor> colors;
  /** \brief Unit normal of vertex v; empty for colour-only homogeneity. */
  std::vector<Eigen::Vector3f> normals;
};

/** \brief The neighbour graph: every pair of \a points within \a radius, valued by
 * its length, ends in increasing order, in no particular order; built on a
 * UniformGrid in two parallel passes behind the memory guard of
 * countRadiusEdgesWithinBudget(). The same edges for any number of threads.
 * \param[in] points the points, vertex v at points[v]
 * \param[in] radius the largest distance of neighbours (> 0)
 * \param[in] threads OpenMP threads (0: OpenMP's default)
 * \param[in] budget the memory the edges may take
 * \param[out] edges the graph's edges
 * \param[out] size the number of edges (exact, or estimated when refused early)
 * \param[in] progress told the work done (optional)
 * \return false, with \a edges empty, when the graph is over the budget
 * \throws pcl::BadArgumentException as UniformGrid */
bool
neighborGraph (const std::vector<Point3d>& points,
               double radius,
               unsigned int threads,
               const MemoryBudget& budget,
               std::vector<FilteredEdge>& edges,
               ComplexSize& size,
               const ProgressCallback& progress = {});

/** \brief Joins the neighbouring pixels of a depth image (an organized cloud) that
 * lie farther apart than the radius but within \a range_ratio times the range of
 * the nearer one (its distance from the sensor): the rows of a surface seen at a
 * grazing angle, which the radius graph leaves apart, while the jumps in depth at an
 * object's outline stay cut. Each pixel is compared with its 8 neighbours. Adds the
 * edges (valued by length, ends in increasing order) that are not in the graph
 * already, i.e. those longer than the radius. Deterministic.
 * \param[in] points the points, vertex v at points[v]
 * \param[in] vertex_of_pixel the vertex of every pixel, row by row (INVALID_SIMPLEX:
 * none)
 * \param[in] width the width of the image
 * \param[in] sensor the position of the sensor
 * \param[in] radius the radius of \a graph
 * \param[in] range_ratio the longest edge per unit of range (0: nothing to do)
 * \param[in,out] graph the radius graph (neighborGraph()), extended */
void
addImageNeighbors (const std::vector<Point3d>& points,
                   const std::vector<SimplexIndex>& vertex_of_pixel,
                   std::size_t width,
                   const Point3d& sensor,
                   double radius,
                   double range_ratio,
                   std::vector<FilteredEdge>& graph);

/** \brief Joins the points that have fewer than \a k neighbours in the radius graph
 * to their 3 k nearest points (NearestNeighbors), so that sparse parts of a cloud stay
 * connected: the far side of a depth frame, where rows of points lie farther apart
 * than the radius (3 k, since the k nearest may all lie along the point's row). Adds
 * the edges (valued by length, ends in increasing order) that are not in the graph
 * already (the radius graph's, and those added before, e.g. by
 * addImageNeighbors()); dense parts are left as they are.
 * Deterministic. \param[in] points the points, vertex v at points[v] \param[in] radius
 * the radius of \a graph \param[in] k the fewest neighbours of a point (0: nothing to
 * do) \param[in] threads OpenMP threads of the search (0: OpenMP's default); the
 * result does not depend on them \param[in,out] graph the radius graph
 * (neighborGraph()), extended */
void
addNearestNeighbors (const std::vector<Point3d>& points,
                     double radius,
                     std::size_t k,
                     unsigned int threads,
                     std::vector<FilteredEdge>& graph);

/** \brief The neighbour lists of a graph in compressed sparse row form: the
 * neighbours of vertex v are neighbors[offsets[v]] to neighbors[offsets[v + 1] - 1].
 */
struct NeighborLists {
  std::vector<std::size_t> offsets;
  std::vector<SimplexIndex> neighbors;
};

/** \brief The neighbour lists of \a num_vertices vertices joined by \a graph (any
 * edge order). */
NeighborLists
neighborLists (std::size_t num_vertices, const std::vector<FilteredEdge>& graph);

/** \brief Surface normals from the neighbour graph, as pcl::NormalEstimation computes
 * them with a radius search of the graph's radius, but without a second search: the
 * eigenvector of the smallest eigenvalue of the covariance of each vertex and its
 * neighbours (pcl::eigen33()), of unit length, with the sign of pcl::NormalEstimation
 * towards the viewpoint (0, 0, 0) (the sign does not matter to the comparison). NaN
 * for a vertex with fewer than two neighbours.
 * \param[in] points position of every vertex
 * \param[in] lists the neighbour lists of the graph
 * \param[in] threads OpenMP threads (0: OpenMP's default) */
std::vector<Eigen::Vector3f>
neighborNormals (const std::vector<Point3d>& points,
                 const NeighborLists& lists,
                 unsigned int threads);

/** \brief Colours with the noise filtered out and the borders kept: each vertex'
 * CIELAB colour replaced by the median, channel by channel, of the colours of the
 * vertex and of those of its neighbours in the graph that lie on its side of any
 * border: within a limit of its own colour. The limit is \a max_change or, if
 * larger, 3 times the noise (the median change of a colour by the median of its
 * whole neighbourhood, over every 8th vertex). Within a region the median removes the
 * sensor noise; at a border the neighbours across it are left out, so that the point is
 * smoothed by its own side and no blend of the two sides forms along the border (a
 * median over every neighbour would take the other side's colour where most neighbours
 * lie across). A vertex whose median is farther than the limit from its colour keeps
 * its own.
 * \param[in] colors CIELAB colour of every vertex
 * \param[in] lists the neighbour lists of the graph
 * \param[in] max_change the smallest limit, in Delta E76
 * \param[in] threads OpenMP threads (0: OpenMP's default) */
std::vector<LabColor>
medianSmoothedColors (const std::vector<LabColor>& colors,
                      const NeighborLists& lists,
                      float max_change,
                      unsigned int threads);

/** \brief Values every edge of \a graph by the Delta E76 of the colours of its ends,
 * or by infinity when \a normals are given (one unit normal per vertex) and the
 * angle between the normals of its ends is above the threshold: |u . v| <
 * \a min_cos_angle (on |u . v|, so that the sign of a normal does not matter); an
 * end without a finite normal is compared by colour only. The
 * infinite edges are kept, since the regions they separate are still neighbours
 * (for the merging of small regions).
 * \param[in,out] graph the neighbour graph, revalued
 * \param[in] colors CIELAB colour of every vertex
 * \param[in] normals unit normal of every vertex, or empty for colours only
 * \param[in] min_cos_angle cosine of the angle threshold (unused without normals)
 * \param[in] threads OpenMP threads (0: OpenMP's default) */
void
valueByHomogeneity (std::vector<FilteredEdge>& graph,
                    const std::vector<LabColor>& colors,
                    const std::vector<Eigen::Vector3f>& normals,
                    double min_cos_angle,
                    unsigned int threads);

} // namespace tda
} // namespace pcl
