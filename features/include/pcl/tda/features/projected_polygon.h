#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/point3d.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace pcl {
namespace tda {

/** \brief A closed cycle of points seen in its own plane: the points projected onto
 * their least-squares plane, as the polygon of the point-in-polygon tests of
 * Alg 5.15 (thesis Sec 5.4.1) and the outline whose area a hole reports.
 *
 * Containment follows the even-odd rule (a ray from the point crosses the polygon an
 * odd number of times), so a cycle whose projection crosses itself still has a
 * well-defined inside. The edges are bucketed by rows of the plane, so that a test
 * looks at the edges of one row only. */
class ProjectedPolygon {
public:
  /** \param[in] points the positions of all vertices
   * \param[in] cycle the vertices of the cycle in order (at least 3); the polygon
   * closes from the last back to the first */
  ProjectedPolygon (const std::vector<Point3d>& points,
                    const std::vector<SimplexIndex>& cycle);

  /** \brief The coordinates of \a p in the plane. */
  Eigen::Vector2d
  project (const Point3d& p) const
  {
    const Eigen::Vector3d d = Eigen::Vector3d (p[0], p[1], p[2]) - centroid_;
    return {d.dot (axis_u_), d.dot (axis_v_)};
  }

  /** \brief True when \a q (plane coordinates) is inside the polygon. */
  bool
  contains (const Eigen::Vector2d& q) const
  {
    bool inside = false;
    const std::size_t row = rowOf (q.y());
    for (std::size_t k = row_offsets_[row]; k < row_offsets_[row + 1]; ++k) {
      const Eigen::Vector2d& a = row_edges_[k].a;
      const Eigen::Vector2d& b = row_edges_[k].b;
      // The edge straddles the horizontal line through q (half-open, so that a
      // vertex on the line counts once) and crosses it right of q.
      if ((a.y() > q.y()) != (b.y() > q.y()) &&
          q.x() < a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
        inside = !inside;
    }
    return inside;
  }

  /** \brief The abscissas, in increasing order, where the polygon crosses the line
   * of ordinate \a y: a point of that line is inside when an odd number of them
   * lie right of it (the rule of contains()). */
  std::vector<double>
  crossings (double y) const;

  /** \brief The area of the polygon (the absolute shoelace sum). */
  double
  area () const;

  /** \brief The mean of the cycle's points. */
  const Eigen::Vector3d&
  centroid () const
  {
    return centroid_;
  }

  /** \brief The plane's first and second axes: a point with plane coordinates
   * (a, b) is centroid() + a axisU() + b axisV(). */
  const Eigen::Vector3d&
  axisU () const
  {
    return axis_u_;
  }

  const Eigen::Vector3d&
  axisV () const
  {
    return axis_v_;
  }

  /** \brief The unit normal of the plane (sign arbitrary). */
  const Eigen::Vector3d&
  normal () const
  {
    return normal_;
  }

private:
  /** An edge of the polygon, from corner a to corner b. */
  struct Edge {
    Eigen::Vector2d a;
    Eigen::Vector2d b;
  };

  /** The row of height \a y, clamped to the rows. */
  std::size_t
  rowOf (double y) const
  {
    const double row = std::floor ((y - row_low_) / row_height_);
    return static_cast<std::size_t> (
        std::clamp (row, 0.0, static_cast<double> (num_rows_ - 1)));
  }

  Eigen::Vector3d centroid_;
  Eigen::Vector3d normal_;
  Eigen::Vector3d axis_u_;
  Eigen::Vector3d axis_v_;
  std::vector<Eigen::Vector2d> corners_;
  std::size_t num_rows_ = 1;
  double row_low_ = 0.0;
  double row_height_ = 1.0;
  /** Per row r, entries row_offsets_[r] to row_offsets_[r + 1] of row_edges_: the
   * edges whose span in y meets the row. */
  std::vector<std::size_t> row_offsets_;
  std::vector<Edge> row_edges_;
};

} // namespace tda
} // namespace pcl
