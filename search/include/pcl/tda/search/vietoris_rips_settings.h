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
  ProgressCallback progress_;
};

} // namespace tda
} // namespace pcl
