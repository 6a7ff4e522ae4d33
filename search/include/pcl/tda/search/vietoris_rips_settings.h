#pragma once

#include <pcl/tda/common/progress.h>
#include <pcl/tda/common/resource_settings.h>

#include <cstddef>

namespace pcl {
namespace tda {

/** \brief The settings of a Vietoris-Rips build, with PCL-style setters: one set
 * for this module's VietorisRipsBuilder and the gpu/ module's
 * gpu::VietorisRipsBuilder, which take the same settings and build the same
 * complex from them. */
class VietorisRipsSettings : public ResourceSettings {
public:
  /** \brief Sets the radius r of VR_r: the largest edge length (> 0). */
  void
  setRadius (double radius)
  {
    radius_ = radius;
  }

  double
  getRadius () const
  {
    return radius_;
  }

  /** \brief Sets the largest simplex dimension: 1 (edges, enough for H0) or 2
   * (triangles too, needed for H1). Default 2. */
  void
  setMaxDimension (int max_dimension)
  {
    max_dimension_ = max_dimension;
  }

  int
  getMaxDimension () const
  {
    return max_dimension_;
  }

  /** \brief At dimension 1, whether the memory limit bounds the triangles of the
   * complex too, as at dimension 2, although they are not listed (default false):
   * for H1 from the edges alone (computeCliqueH1Persistence()), whose time and
   * stored columns grow with the triangles it goes through. The triangles are
   * bounded from the count pass of the edges and estimated from a sample when the
   * bound is over the limit, and the complex is refused when the estimate is over
   * twice the limit, in bounded time (not with setSearchMethod(), whose edges
   * alone are checked). */
  void
  setTrianglesInMemoryLimit (bool limited)
  {
    triangles_in_memory_limit_ = limited;
  }

  bool
  getTrianglesInMemoryLimit () const
  {
    return triangles_in_memory_limit_;
  }

  /** \brief The largest dimension whose simplices the memory limit bounds: the max
   * dimension, or 2 with setTrianglesInMemoryLimit(). */
  int
  getLimitedDimension () const
  {
    return triangles_in_memory_limit_ ? 2 : max_dimension_;
  }

  /** \brief Sets a callback told the progress of a build in thousandths (done,
   * 1000), from one thread, e.g. to drive a ProgressBar: long builds are not
   * silent. */
  void
  setProgressCallback (const ProgressCallback& progress)
  {
    progress_ = progress;
  }

protected:
  double radius_ = 0.0;
  int max_dimension_ = 2;
  bool triangles_in_memory_limit_ = false;
  ProgressCallback progress_;
};

} // namespace tda
} // namespace pcl
