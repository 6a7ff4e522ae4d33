#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/progress.h>
#include <pcl/tda/gpu/device_backend.h>
#include <pcl/tda/search/vietoris_rips_checks.h>
#include <pcl/tda/search/vietoris_rips_phases.h>
#include <pcl/tda/search/vietoris_rips_settings.h>
#include <pcl/pcl_base.h>

#include <cstddef>
#include <string>
#include <vector>

namespace pcl {
namespace tda {
namespace gpu {

/** \brief The parameters of buildVietorisRipsComplex(). */
struct DeviceBuildSettings {
  /** The class named in the messages: "[pcl::tda::<class_name>::compute] ...". */
  std::string class_name = "gpu::VietorisRipsBuilder";
  /** The radius r of VR_r (> 0, finite). */
  double radius = 0.0;
  /** 1 (edges only) or 2 (triangles too). */
  int max_dimension = 2;
  /** The largest dimension whose simplices the memory limit bounds (at least
   * max_dimension; VietorisRipsSettings::getLimitedDimension()). */
  int limited_dimension = 2;
  /** The bytes the complex may take (device memory on CUDA). */
  std::size_t memory_limit = 0;
  /** OpenMP threads of the OpenMP backend and of the host's copies (0: OpenMP's
   * default). */
  unsigned int threads = 0;
  /** Told the progress in thousandths, when set. */
  ProgressCallback progress;
};

/** \brief Builds the parts of VR_r of points in canonical order with the phases of
 * Ch. 3 on \a backend (Thrust primitives: points sorted by grid cell, edge count,
 * prefix sum and fill, sort into filtration order, triangle count, prefix sum and
 * fill), behind the memory guard of the CPU builder (countEdgesWithinBudget(), with
 * its sampled estimate). The parts are those of pcl::tda::VietorisRipsBuilder on the
 * same points, bit for bit.
 * \param[in] xyz vertex v at (xyz[3v], xyz[3v + 1], xyz[3v + 2]), all finite
 * \param[out] edges the edges in filtration order
 * \param[out] triangles the triangles in filtration order (dimension 2)
 * \param[out] timings the seconds of the phases
 * \return false, after a PCL_ERROR, when the complex is over the limits or the
 * device fails (e.g. out of memory) */
bool
buildVietorisRipsComplex (const std::vector<float>& xyz,
                          const DeviceBuildSettings& settings,
                          DeviceBackend backend,
                          std::vector<FilteredEdge>& edges,
                          std::vector<FilteredTriangle>& triangles,
                          VietorisRipsTimings& timings);

/** \brief The Vietoris-Rips complex VR_r of a point cloud up to dimension 2, built
 * by the phases of Ch. 3 written once with Thrust: on an NVIDIA GPU when the library
 * is built with CUDA and a device is present, otherwise on all cores through
 * Thrust's OpenMP system (with a PCL_WARN when a CUDA build finds no device).
 *
 * It mirrors pcl::tda::VietorisRipsBuilder: the same setters, and exactly the same
 * FilteredComplex (vertices in canonical order, edges and triangles in filtration
 * order with the same ids and values, the same skipped non-finite points), the same
 * memory limit and the same refusals. It has no setSearchMethod(): the neighbours
 * come from its own uniform grid of cell size r.
 *
 * \code
 * pcl::tda::gpu::VietorisRipsBuilder<pcl::PointXYZ> builder;
 * builder.setInputCloud (cloud);
 * builder.setRadius (0.01);
 * pcl::tda::FilteredComplex complex;
 * builder.compute (complex);
 * \endcode
 */
template <typename PointT>
class VietorisRipsBuilder : public pcl::PCLBase<PointT>, public VietorisRipsSettings {
public:
  using Ptr = shared_ptr<VietorisRipsBuilder<PointT>>;
  using ConstPtr = shared_ptr<const VietorisRipsBuilder<PointT>>;
  using PointCloud = pcl::PointCloud<PointT>;

  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  /** \brief Bytes per edge and per triangle checked against the memory limit: the
   * CPU builder's. */
  static constexpr std::size_t BYTES_PER_EDGE = VIETORIS_RIPS_BYTES_PER_EDGE;
  static constexpr std::size_t BYTES_PER_TRIANGLE = VIETORIS_RIPS_BYTES_PER_TRIANGLE;

  /** \brief Builds the complex of the input points (or of the indexed ones).
   * On failure (no input, no finite point, radius <= 0, dimension not 1 or 2,
   * complex over the memory limit, device failure) prints a PCL_ERROR and leaves
   * \a complex empty.
   * \return true on success */
  bool
  compute (FilteredComplex& complex);

  /** \brief Number of non-finite points skipped by the last compute(). */
  std::size_t
  getNumSkippedPoints () const
  {
    return skipped_points_;
  }

  /** \brief Phase timings of the last compute(). */
  const VietorisRipsTimings&
  getTimings () const
  {
    return timings_;
  }

  /** \brief The backend the last compute() ran on. */
  DeviceBackend
  getBackend () const
  {
    return backend_;
  }

protected:
  /** \brief The class name, as PCL's classes report it in their messages. */
  const std::string&
  getClassName () const
  {
    return class_name_;
  }

private:
  std::size_t skipped_points_ = 0;
  VietorisRipsTimings timings_;
  DeviceBackend backend_ = DeviceBackend::OPENMP;
  bool fallback_reported_ = false;
  std::string class_name_ = "gpu::VietorisRipsBuilder";
};

} // namespace gpu
} // namespace tda
} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl/tda/gpu/impl/vietoris_rips_builder.hpp>
#endif
