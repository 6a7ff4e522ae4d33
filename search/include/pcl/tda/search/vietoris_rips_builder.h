#pragma once

#include <pcl/search/search.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/search/vietoris_rips_checks.h>
#include <pcl/tda/search/vietoris_rips_phases.h>
#include <pcl/tda/search/vietoris_rips_settings.h>
#include <pcl/pcl_base.h>

#include <cstddef>
#include <string>

namespace pcl {
namespace tda {

/** \brief Builds the Vietoris-Rips complex VR_r of a point cloud up to dimension 2
 * as a FilteredComplex, in three parallel phases (thesis Ch. 3, Alg 3.2-3.5):
 * neighbour search, edge list and triangle list, each a count pass, a prefix sum
 * and a fill pass.
 *
 * Points are first put in canonical order (sorted by x, y, z, as in Alg 3.2), so
 * the complex does not depend on the input order or the number of threads; the
 * complex maps its vertices back to input indices. An edge enters at its Euclidean
 * length (computed in double precision) and belongs to VR_r when its length is at
 * most r; a triangle enters at its longest edge. Non-finite points are skipped.
 * A complex whose estimated size exceeds the memory limit is refused before it is
 * allocated.
 *
 * \code
 * pcl::tda::VietorisRipsBuilder<pcl::PointXYZ> builder;
 * builder.setInputCloud(cloud);
 * builder.setRadius(0.01);
 * pcl::tda::FilteredComplex complex;
 * builder.compute(complex);
 * \endcode
 */
template <typename PointT>
class VietorisRipsBuilder : public pcl::PCLBase<PointT>, public VietorisRipsSettings {
public:
  using Ptr = shared_ptr<VietorisRipsBuilder<PointT>>;
  using ConstPtr = shared_ptr<const VietorisRipsBuilder<PointT>>;
  using PointCloud = pcl::PointCloud<PointT>;
  using SearchPtr = typename pcl::search::Search<PointT>::Ptr;

  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

  /** \brief Bytes the builder needs per edge and per triangle at its peak; the
   * memory limit is checked against these before allocating. */
  static constexpr std::size_t BYTES_PER_EDGE = VIETORIS_RIPS_BYTES_PER_EDGE;
  static constexpr std::size_t BYTES_PER_TRIANGLE = VIETORIS_RIPS_BYTES_PER_TRIANGLE;

  /** \brief Sets a PCL search object for the neighbour search (phase 1). Without
   * one, a uniform grid of cell size r is used, which is faster for fixed-radius
   * search (with one, the grid still bounds and samples the complex for the memory
   * check). Either way the neighbours are exactly the points within r. */
  void
  setSearchMethod (const SearchPtr& search)
  {
    search_ = search;
  }

  SearchPtr
  getSearchMethod () const
  {
    return search_;
  }

  /** \brief Builds the complex of the input points (or of the indexed ones).
   * On failure (no input, no finite point, radius <= 0, dimension not 1 or 2,
   * complex over the memory limit) prints a PCL_ERROR and leaves \a complex empty.
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

protected:
  /** \brief The class name, as PCL's classes report it in their messages. */
  const std::string&
  getClassName () const
  {
    return class_name_;
  }

private:
  /** The memory limit with the builder's bytes per simplex. */
  MemoryBudget
  memoryBudget () const;

  /** Checks \a size against the memory limit and the 32-bit ids; false after a
   * PCL_ERROR naming the sizes. */
  bool
  fitsMemory (const ComplexSize& size) const;

  SearchPtr search_;
  std::size_t skipped_points_ = 0;
  VietorisRipsTimings timings_;
  std::string class_name_ = "VietorisRipsBuilder";
};

} // namespace tda
} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl/tda/search/impl/vietoris_rips_builder.hpp>
#endif
