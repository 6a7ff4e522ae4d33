#pragma once

#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/features/minimal_cycles.h>

#include <vector>

namespace pcl {
namespace tda {

/** \brief Polygons around the borders of a sampled surface, searched for the holes
 * that homology cannot tell apart (minimalCycles()).
 *
 * On a closed surface with k holes only k - 1 hole classes are independent, and the
 * initial cycle of a class that also goes around a handle lies across the surface.
 * Every hole has a border, though: its rim points see their neighbours on one side
 * only.
 * - A vertex is on a border when the directions to its neighbours in \a adjacency,
 *   in the plane fitted to it and them, leave a gap wider than 135 degrees. At the
 *   rim of a round hole of empty radius rho, the gap is 2 acos(r / (2 rho)) for
 *   neighbours within r: 120 degrees at rho = r, 137 at rho = 3 h with the
 *   automatic r = 2.2 h (the spacing h). A smaller angle, such as
 *   pcl::BoundaryEstimation's 90 degrees, flags half the points of a jittered
 *   sampling at r = 1.6 h.
 * - The border vertices, joined through paths of up to two edges (so that rim
 *   points with narrower gaps do not cut their rim), form components. One with
 *   fewer than 2 pi \a min_clearance / \a radius vertices is too short to go around
 *   a hole whose empty disk has radius \a min_clearance (a sampling irregularity):
 *   it is skipped.
 * - Around each other component, in order of its first vertex, a polygon. The
 *   line from each border vertex along the middle of its gap points into the empty
 *   side; where the lines of a component meet (least squares), on the gap side and
 *   within the component's extent, is the centre of its hole, even when the
 *   component is only a part of the rim. The polygon is then the farthest vertex, in
 *   each angle bin around that centre, of the vertices reached from the component
 *   within the hole's radius (the median distance of the component) plus two edges
 *   of the centre: it goes around the whole hole. When the lines do not meet (a
 *   straight or outer border, scattered noise), it is built the same way around the
 *   component's centroid from the vertices within two edges of it.
 *
 * An outer border or the open end of a tube gives a polygon too; the search finds
 * no empty region inside the former, and holeRims() drops the latter's rim, which
 * stands across its surface.
 * \param[in] positions the position of every vertex
 * \param[in] adjacency the neighbours of every vertex (the edges of the complex)
 * \param[in] radius the radius of the complex: the longest edge
 * \param[in] min_clearance the radius of the smallest empty disk of a hole
 * \param[in] threads OpenMP threads of the border test (0: OpenMP's default); the
 * result does not depend on it */
std::vector<InitialCycle>
borderPolygons (const std::vector<Point3d>& positions,
                const EdgeAdjacency& adjacency,
                double radius,
                double min_clearance,
                unsigned int threads = 0);

} // namespace tda
} // namespace pcl
