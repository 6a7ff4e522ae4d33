#pragma once

#include <pcl/search/search.h>
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/progress.h>
#include <pcl/tda/search/complex_size.h>
#include <pcl/pcl_base.h>

#include <cstddef>
#include <string>

namespace pcl {
namespace tda {

/** \brief Wall-clock seconds of the three phases of the last
 * VietorisRipsBuilder::compute() call. */
struct VietorisRipsTimings {
  double neighbor_search = 0.0;
  double edges = 0.0;
  double triangles = 0.0;
};

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
class VietorisRipsBuilder : public pcl::PCLBase<PointT> {
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
  static constexpr std::size_t BYTES_PER_EDGE = 64;
  static constexpr std::size_t BYTES_PER_TRIANGLE = 24;

  VietorisRipsBuilder();

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

  /** \brief Sets a PCL search object for the neighbour search (phase 1). Without
   * one, a uniform grid of cell size r is used, which is faster for fixed-radius
   * search. Either way the neighbours are exactly the points within r. */
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

  /** \brief Sets the memory the complex may take, in bytes; a larger complex is
   * refused before allocation. Default: half of the physical memory (no limit where
   * it cannot be read). */
  void
  setMemoryLimit (std::size_t bytes)
  {
    memory_limit_ = bytes;
  }

  std::size_t
  getMemoryLimit () const
  {
    return memory_limit_;
  }

  /** \brief Sets the number of OpenMP threads of every phase (0: OpenMP's default);
   * the complex does not depend on it. */
  void
  setNumberOfThreads (unsigned int threads)
  {
    threads_ = threads;
  }

  unsigned int
  getNumberOfThreads () const
  {
    return threads_;
  }

  /** \brief Sets a callback told the progress of compute() in thousandths (done,
   * 1000), from one thread, e.g. to drive a ProgressBar: long builds are not
   * silent. */
  void
  setProgressCallback (const ProgressCallback& progress)
  {
    progress_ = progress;
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
  /** The ends of the phases of compute(), for its progress. */
  enum BuildPhase {
    START,
    EDGES_COUNTED,
    EDGES_LISTED,
    EDGES_SORTED,
    TRIANGLES_COUNTED,
    DONE
  };

  /** Where \a phase ends, in thousandths of the build. */
  std::size_t
  permilleAt (BuildPhase phase) const;

  /** The progress callback of a phase from \a first to \a last (none without a
   * callback). */
  ProgressCallback
  phaseProgress (BuildPhase first, BuildPhase last) const;

  /** Tells the callback that \a phase is done. */
  void
  reportPhase (BuildPhase phase) const;

  /** The memory limit with the builder's bytes per simplex. */
  MemoryBudget
  memoryBudget () const;

  /** Checks \a size against the memory limit and the 32-bit ids; false after a
   * PCL_ERROR naming the sizes. */
  bool
  fitsMemory (const ComplexSize& size) const;

  double radius_ = 0.0;
  int max_dimension_ = 2;
  SearchPtr search_;
  std::size_t memory_limit_;
  unsigned int threads_ = 0;
  ProgressCallback progress_;
  std::size_t skipped_points_ = 0;
  VietorisRipsTimings timings_;
  std::string class_name_ = "VietorisRipsBuilder";
};

} // namespace tda
} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl/tda/search/impl/vietoris_rips_builder.hpp>
#endif
