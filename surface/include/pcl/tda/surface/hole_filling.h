#pragma once

#include <pcl/search/kdtree.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/features/hole_rims.h>
#include <pcl/tda/features/projected_polygon.h>
#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Fills the holes that HoleBoundaryEstimation found: new points inside each
 * rim, the input points kept unchanged and in order (thesis Sec 5.6).
 *
 * Two modes:
 * - CENTROID, the thesis' filling: one point per hole, at the mean of its rim's
 *   points. Good for small, convex holes.
 * - SURFACE: new points on a surface fitted to the hole's surroundings, spaced like
 *   the cloud, only inside the rim, so that large and non-convex holes are filled
 *   too. The surroundings are the input points within three spacings of a rim
 *   point; in the plane of the rim (ProjectedPolygon) they give a quadratic height
 *   field h(u, v) = a + b u + c v + d u^2 + e u v + f v^2 by least squares. The new
 *   points are the nodes of a square grid of one spacing in that plane that lie
 *   inside the rim and at least 0.7 spacing from every surrounding point, lifted to
 *   the height field.
 *
 * A new point copies the fields of the rim point nearest to it (colour, intensity,
 * label, ...) and takes its own x, y, z. The whole input cloud is filled: indices
 * (setIndices()) are refused.
 *
 * \code
 * pcl::tda::HoleFilling<pcl::PointXYZ> filler;
 * filler.setInputCloud (cloud);
 * filler.setHoles (estimation.getHoles ());
 * pcl::PointCloud<pcl::PointXYZ> filled;
 * filler.reconstruct (filled);   // cloud's points, then the new ones
 * \endcode */
template <typename PointT>
class HoleFilling : public pcl::PCLBase<PointT> {
public:
  using Ptr = shared_ptr<HoleFilling<PointT>>;
  using ConstPtr = shared_ptr<const HoleFilling<PointT>>;

  /** \brief How holes are filled (see the class). */
  enum class Mode { CENTROID, SURFACE };

  /** \brief Sets the holes to fill: rims of input point indices, as
   * HoleBoundaryEstimation::getHoles() gives them for the same cloud. */
  void
  setHoles (const std::vector<HoleRim>& holes)
  {
    holes_ = holes;
  }

  const std::vector<HoleRim>&
  getHoles () const
  {
    return holes_;
  }

  /** \brief Sets the mode (default SURFACE). */
  void
  setMode (Mode mode)
  {
    mode_ = mode;
  }

  Mode
  getMode () const
  {
    return mode_;
  }

  /** \brief Sets the spacing of the new points; 0 (the default): the surface spacing
   * of the input (surfaceSpacing()). */
  void
  setSpacing (double spacing)
  {
    spacing_ = spacing;
  }

  double
  getSpacing () const
  {
    return spacing_;
  }

  /** \brief Writes the input points followed by the new points to \a output. On
   * failure (no input, a rim index out of range, a bad spacing, or in SURFACE mode a
   * spacing so fine for the holes that their grids would take more than the default
   * memory limit, defaultMemoryLimit(): refused before they are allocated) prints a
   * PCL_ERROR and leaves \a output empty.
   * \return true on success */
  bool
  reconstruct (pcl::PointCloud<PointT>& output);

  /** \brief The number of new points per hole of the last reconstruct(). */
  const std::vector<std::size_t>&
  getNewPointCounts () const
  {
    return new_point_counts_;
  }

  /** \brief For each new point of the last reconstruct(), in the order of the
   * output, the index of the input point whose fields it copies (the nearest point of
   * its rim): to carry fields a point type does not hold, as a tool that reads any
   * PCD file does. */
  const pcl::Indices&
  getNewPointSources () const
  {
    return new_point_sources_;
  }

  /** \brief The class name, as PCL's classes report it in their messages. */
  const std::string&
  getClassName () const
  {
    return class_name_;
  }

protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

private:
  /** \brief The rim of \a hole as a polygon in its plane: \a rim_points its points
   * in rim order, \a low and \a high the corners of its box in the plane. */
  ProjectedPolygon
  rimPolygon (const HoleRim& hole,
              std::vector<Point3d>& rim_points,
              Eigen::Vector2d& low,
              Eigen::Vector2d& high) const;

  /** \brief Whether the SURFACE grids of spacing \a spacing fit the default memory
   * limit: the largest hole's distance grid (a quarter spacing) and the new points of
   * all holes (at most one per node of the grid of one spacing); false after a
   * PCL_ERROR giving the sizes. */
  bool
  gridsFitMemory (double spacing) const;

  /** \brief The input's positions divided by \a scale, a power of two
   * (powerOfTwoScale() of their largest magnitude), in a k-d tree: its float
   * distances neither overflow nor underflow, in any unit. */
  struct ScaledSearch {
    double scale = 1.0;
    pcl::search::KdTree<pcl::PointXYZ> tree;
  };

  /** \brief Builds \a search over the input. */
  void
  buildScaledSearch (ScaledSearch& search) const;

  /** \brief The new points of one hole, appended to \a output, and the input points
   * they copy to new_point_sources_. In SURFACE mode \a search searches the input and
   * \a taken (one 0 per input point, left all 0) marks the surroundings already seen.
   */
  void
  fillHole (const HoleRim& hole,
            double spacing,
            const ScaledSearch& search,
            std::vector<std::uint8_t>& taken,
            pcl::PointCloud<PointT>& output);

  std::vector<HoleRim> holes_;
  Mode mode_ = Mode::SURFACE;
  double spacing_ = 0.0;
  std::vector<std::size_t> new_point_counts_;
  pcl::Indices new_point_sources_;
  std::string class_name_ = "HoleFilling";
};

} // namespace tda
} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl/tda/surface/impl/hole_filling.hpp>
#endif
