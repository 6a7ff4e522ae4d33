#pragma once

#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/point3d.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The fewest angle bins of a star polygon (starPolygonAround()). */
constexpr std::size_t MIN_STAR_POLYGON_BINS = 8;
/** \brief How far, in edges, a star polygon around a hole reaches beyond the hole's
 * radius, and one around a border beyond the border. */
constexpr int STAR_POLYGON_MARGIN_EDGES = 2;

/** \brief The vertices reached from \a start (itself included, in the order found)
 * through paths of at most \a max_steps edges of \a adjacency whose vertices
 * \a admit accepts, using \a seen (one flag per vertex, all 0 on entry and on
 * return) as scratch. */
template <typename Admit>
std::vector<SimplexIndex>
reachFrom (const std::vector<SimplexIndex>& start,
           const EdgeAdjacency& adjacency,
           std::vector<std::uint8_t>& seen,
           int max_steps,
           Admit admit)
{
  std::vector<SimplexIndex> reached = start;
  for (const SimplexIndex v : start)
    seen[v] = 1;
  std::size_t ring_begin = 0;
  for (int step = 0; step < max_steps && ring_begin < reached.size(); ++step) {
    const std::size_t ring_end = reached.size();
    for (std::size_t k = ring_begin; k < ring_end; ++k)
      for (const auto& entry : adjacency.neighbors (reached[k]))
        if (!seen[entry.neighbor] && admit (entry.neighbor)) {
          seen[entry.neighbor] = 1;
          reached.push_back (entry.neighbor);
        }
    ring_begin = ring_end;
  }
  for (const SimplexIndex v : reached)
    seen[v] = 0;
  return reached;
}

/** \brief A star polygon: the farthest of \a vertices from \a centre in each of
 * \a bins angle bins around it, in the plane of \a axes (columns 0 and 1), in angle
 * order (ties by the smaller vertex id). Used as the initial cycle of a search for
 * the holes around a point (minimalCycles()). */
std::vector<SimplexIndex>
starPolygon (const std::vector<SimplexIndex>& vertices,
             const std::vector<Point3d>& positions,
             const Eigen::Vector3d& centre,
             const Eigen::Matrix3d& axes,
             std::size_t bins);

/** \brief The star polygon around a point of a hole: the vertices reached from
 * \a start (through edges of \a adjacency, the start included) within \a reach of
 * \a centre, in their least-squares plane, one per angle bin about an edge
 * (\a edge_length) wide on the circle of radius \a reach (at least
 * MIN_STAR_POLYGON_BINS). With \a reach beyond the hole's edge it goes around the
 * whole hole. \a seen: as for reachFrom(). */
std::vector<SimplexIndex>
starPolygonAround (const Eigen::Vector3d& centre,
                   double reach,
                   const std::vector<SimplexIndex>& start,
                   const std::vector<Point3d>& positions,
                   const EdgeAdjacency& adjacency,
                   double edge_length,
                   std::vector<std::uint8_t>& seen);

} // namespace tda
} // namespace pcl
