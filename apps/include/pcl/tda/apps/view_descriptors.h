#pragma once

#include <pcl/tda/common/system_memory.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The radius of the normals of a view, in units of its spacing (the median
 * distance of a point to its nearest neighbour): about 28 neighbours on a surface. */
constexpr double NORMAL_RADIUS_PER_SPACING = 3.0;

/** \brief One global descriptor of one view: its values, or why it could not be
 * computed, and the time it took. */
struct ViewDescriptor {
  /** \brief The values; empty when the descriptor failed. */
  std::vector<float> values;
  /** \brief Why the descriptor failed; empty when it did not. */
  std::string failure;
  /** \brief Milliseconds of the descriptor itself. */
  double milliseconds = 0.0;
  /** \brief Milliseconds of the view's normals, when the descriptor needs them (the
   * normals are estimated once per view and counted in each such descriptor). */
  double normal_milliseconds = 0.0;
};

/** \brief The settings of the topological descriptors of a view ("stpp", "stpp0",
 * "stpp1", "covariance"). */
struct TopologicalSettings {
  /** \brief The radius of STPP's level 0 and of the covariance's filtration
   * (setRadius(); 0: chosen by them). */
  double radius = 0.0;
  /** \brief The largest complex, in bytes, one view may build (setMemoryLimit()). */
  std::size_t memory_limit = defaultMemoryLimit();
};

/** \brief The global descriptors computeViewDescriptors() knows:
 * - "vfh": pcl::VFHEstimation (308 values), the viewpoint the view's sensor origin;
 * - "esf": pcl::ESFEstimation (640), seeded (computeSeededESF());
 * - "grsd": pcl::GRSDEstimation (21), radius and cell size the normal radius;
 * - "cvfh", "ourcvfh": pcl::CVFHEstimation and pcl::OURCVFHEstimation (308): the
 *   mean of their histograms (one per smooth region, and for OUR-CVFH per reference
 *   frame); cluster tolerance and normal radius the normal radius, PCL's default
 *   angle (0.125 rad), curvature (0.03) and smallest region (50 points); OUR-CVFH
 *   keeps every point of a region (PCL's refinement of the regions can leave one of
 *   one or two points, whose reference frame PCL makes of uninitialised memory);
 * - "stpp", "stpp0", "stpp1": pcl::tda::STPPEstimation, its Betti-0 and Betti-1
 *   parts and the size value, or one part and the size value;
 * - "covariance": pcl::tda::TopologicalCovarianceEstimation (78) of the points
 *   with a normal: position, CIELAB colour (0 for a view without colour), normal
 *   and Betti-0 values at three radii.
 * The normals are pcl::NormalEstimation's, radius NORMAL_RADIUS_PER_SPACING times
 * the spacing, oriented towards the sensor origin; points without a normal (fewer
 * than 3 neighbours) are left out of the descriptors that need normals. */
const std::vector<std::string>&
viewDescriptorNames ();

/** \brief True when \a name is one of viewDescriptorNames(). */
bool
isViewDescriptor (const std::string& name);

/** \brief Computes the descriptors \a names (of viewDescriptorNames()) of \a view,
 * after dropping its non-finite points, on the calling thread. Only "covariance"
 * uses the colours. A descriptor that
 * cannot be computed (too few points, PCL gives no histogram or non-finite values)
 * gets its failure, the others are computed all the same. Deterministic: \a seed
 * seeds ESF's sampling; \a topological sets the topological descriptors.
 * \throws pcl::BadArgumentException on an unknown name */
std::vector<ViewDescriptor>
computeViewDescriptors (const pcl::PointCloud<pcl::PointXYZRGB>& view,
                        const std::vector<std::string>& names,
                        std::uint64_t seed,
                        const TopologicalSettings& topological = {});

} // namespace tda
} // namespace pcl
