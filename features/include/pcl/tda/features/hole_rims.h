#pragma once

#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/features/minimal_cycles.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief One hole of a surface: its rim, a closed minimal 1-cycle around an empty
 * region, and the rim's geometry. */
struct HoleRim {
  /** \brief The rim's points in cycle order (vertex ids of the complex, or input
   * point indices where a class hands it to users). */
  std::vector<SimplexIndex> rim;
  /** \brief The length of the closed rim. */
  double perimeter = 0.0;
  /** \brief The area inside the rim, projected onto its least-squares plane. */
  double area = 0.0;
  /** \brief The mean of the rim's points. */
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  /** \brief The radius of the largest empty disk found inside the rim. */
  double clearance = 0.0;
  /** \brief The unit normal of the rim's plane (sign arbitrary). */
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();
  /** \brief The median angle, in degrees, between the rim's plane and the surface
   * at its points: near 0 for a hole, near 90 for a loop around a handle or a tube. */
  double tilt_degrees = 0.0;
  /** \brief The filtration value at which the rim closes: the length of its
   * longest edge. */
  double birth = 0.0;
};

/** \brief The holes among minimal 1-cycles.
 *
 * A cycle is a hole when the surface around it spans it: the median, over the
 * cycle's points, of the angle between the cycle's plane and the surface's plane at
 * the point (fitted to the point and its neighbours in \a adjacency) is at most
 * \a max_tilt_degrees. A loop around a tube or a handle (the waist of a cylinder, the
 * two loops of a torus) and the open end of a tube stand across their surface, at
 * about 90 degrees, and are not holes.
 *
 * A hole must also be wider than the gaps of the sampling: its empty disk has a
 * radius (MinimalCycle::clearance) of at least \a min_clearance, times the median
 * over the rim's points of \a sparseness where it is given: where the surface is
 * sampled more sparsely, its gaps are wider by as much. Cycles around
 * the same empty region (the centre of one's empty disk inside the other's rim seen
 * along its normal, and no farther from its plane than its farthest rim point is
 * from its centroid) give one hole, with the shortest of their rims: holes that line
 * up across a tube or a closed surface stay apart.
 *
 * Holes come in decreasing order of their number of rim points, ties by their class
 * edge.
 * \param[in] cycles the minimal 1-cycles (minimalCycles())
 * \param[in] positions the position of every vertex
 * \param[in] adjacency the neighbours of every vertex (the edges of the complex)
 * \param[in] max_tilt_degrees the largest median tilt of a hole
 * \param[in] max_cycle_length the largest number of rim points (0: no limit)
 * \param[in] min_clearance the smallest radius of a hole's empty disk
 * \param[in] sparseness per vertex, how many times sparser than the surface spacing
 * the sampling around it is (at least 1; localSurfaceSpacings() over the spacing),
 * for every vertex of \a cycles; empty: 1 everywhere */
std::vector<HoleRim>
holeRims (const std::vector<MinimalCycle>& cycles,
          const std::vector<Point3d>& positions,
          const EdgeAdjacency& adjacency,
          double max_tilt_degrees,
          std::size_t max_cycle_length,
          double min_clearance,
          const std::vector<double>& sparseness = {});

/** \brief The sparseness of the sampling around the vertices of \a cycles, as
 * holeRims() takes it: per vertex of a cycle, its local surface spacing
 * (localSurfaceSpacings()) over \a spacing, at least 1; 1 for the other vertices.
 * \param[in] cycles the minimal 1-cycles
 * \param[in] positions the position of every vertex
 * \param[in] spacing the surface spacing of the whole cloud (surfaceSpacing())
 * \param[in] threads number of threads (0: OpenMP's default) */
std::vector<double>
cycleSparseness (const std::vector<MinimalCycle>& cycles,
                 const std::vector<Point3d>& positions,
                 double spacing,
                 unsigned int threads = 0);

/** \brief The rim band: per vertex, the number (1, 2, ...) of the hole of \a holes
 * whose edge it lies within \a band_width of (the first such hole), else 0. This is
 * the band pcl::BoundaryEstimation flags along a border, and the band the generated
 * ground truth labels.
 *
 * A minimal rim is the shortest cycle around the hole; it cuts corners, and may
 * pass a little outside points at the hole's very edge. So the band is measured
 * from the hole's empty region instead: in the plane of the rim, the places inside
 * the rim at least \a spacing from every point. The hole's edge lies about half a
 * spacing outside that region (measured on generated holes); a point within two
 * edges of the rim is in the band when the empty region is within
 * \a band_width + \a spacing / 2 of it. The region is opened first (eroded, then
 * widened, by half a spacing, or less in a hole too narrow for it): where two points
 * at the edge stand a little apart, it reaches out between them, and would carry the
 * band that far beyond the edge.
 * \param[in] holes the holes (rims as vertex ids)
 * \param[in] positions the position of every vertex
 * \param[in] adjacency the neighbours of every vertex (all edges of the complex)
 * \param[in] band_width the band's width
 * \param[in] spacing the sampling spacing of the surface (square root of the area
 * per point) */
std::vector<std::uint32_t>
rimBand (const std::vector<HoleRim>& holes,
         const std::vector<Point3d>& positions,
         const EdgeAdjacency& adjacency,
         double band_width,
         double spacing);

} // namespace tda
} // namespace pcl
