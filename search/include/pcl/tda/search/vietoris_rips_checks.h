#pragma once

#include <pcl/console/print.h>
#include <pcl/tda/search/canonical_order.h>
#include <pcl/tda/search/complex_size.h>

#include <cstddef>
#include <string>

namespace pcl {
namespace tda {

/** \brief The checks and messages that the Vietoris-Rips builders share: this
 * module's VietorisRipsBuilder and the gpu/ module's mirror refuse the same
 * settings, points and complexes with the same words. Every message starts with
 * "[pcl::tda::<class_name>::compute]". */

/** \brief Bytes a Vietoris-Rips builder needs per edge and per triangle at its peak;
 * the memory limit is checked against these before anything large is allocated. */
constexpr std::size_t VIETORIS_RIPS_BYTES_PER_EDGE = 64;
constexpr std::size_t VIETORIS_RIPS_BYTES_PER_TRIANGLE = 24;

/** \brief The memory a builder of dimension \a max_dimension (1: edges only, 2:
 * triangles too) may use under the limit \a limit in bytes. */
MemoryBudget
vietorisRipsMemoryBudget (std::size_t limit, int max_dimension);

/** \brief False, after a PCL_ERROR, when \a radius is not positive and finite or
 * \a max_dimension is not 1 or 2. */
bool
checkVietorisRipsSettings (const std::string& class_name,
                           double radius,
                           int max_dimension);

/** \brief The vertices of the complex: the canonical order of the finite points
 * among \a indices (canonicalOrder()), with a PCL_WARN naming the non-finite ones
 * skipped and a PCL_ERROR when none is left (the order is then empty).
 * \param[out] skipped the number of non-finite points */
template <typename PointT>
pcl::Indices
vietorisRipsVertices (const std::string& class_name,
                      const pcl::PointCloud<PointT>& cloud,
                      const pcl::Indices& indices,
                      std::size_t& skipped)
{
  pcl::Indices order = canonicalOrder (cloud, indices, skipped);
  if (skipped > 0)
    PCL_WARN ("[pcl::tda::%s::compute] Skipped %zu non-finite points.\n",
              class_name.c_str(),
              skipped);
  if (order.empty())
    PCL_ERROR ("[pcl::tda::%s::compute] The input has no finite point.\n",
               class_name.c_str());
  return order;
}

/** \brief Checks the sizes of a complex of radius \a radius against \a budget and the
 * 32-bit simplex ids: true when it fits, false after a PCL_ERROR that names the sizes
 * ("about ... (estimated from a sample)" when \a size is not exact), the bytes and
 * the limit. */
bool
complexFitsMemory (const std::string& class_name,
                   double radius,
                   int max_dimension,
                   const MemoryBudget& budget,
                   const ComplexSize& size);

} // namespace tda
} // namespace pcl
