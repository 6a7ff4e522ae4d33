#pragma once

// The parts of the STPP descriptor (thesis Ch. 6) that do not depend on the point
// type: the coarse copies of a cloud, the values one level of the signature takes
// from its persistence, and the thesis' raw pairing vector.

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/features/signature_types.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Which homology an STPP descriptor is made of (thesis Experiment 2). */
enum class STPPHomology {
  /** The 0-cycles (components) only: the complex needs no triangles. */
  BETTI_0,
  /** The 1-cycles only. */
  BETTI_1,
  /** Both (the default). */
  BETTI_0_1
};

/** \brief Entry of the raw pairing vector for a positive simplex that nothing
 * destroys: a k-dimensional hole at the radius (thesis Fig 6.2). */
constexpr std::int64_t STPP_UNPAIRED = -1;
/** \brief Entry of the raw pairing vector for a negative edge: it creates no class,
 * it destroys a component (the thesis leaves this entry open). */
constexpr std::int64_t STPP_NEGATIVE = -2;

/** \brief The thesis' raw STPP vector (Sec 6.3.2, Fig 6.2) of a complex and its
 * persistence: one entry per vertex (BETTI_0), per edge (BETTI_1) or both, in
 * filtration order. A vertex's entry is the index (in filtration order) of the edge
 * that destroys its component, an edge's the index of the triangle that destroys
 * its 1-cycle; STPP_UNPAIRED for an essential class, STPP_NEGATIVE for a negative
 * edge. \a result must hold H1 unless \a homology is BETTI_0. */
std::vector<std::int64_t>
pairingVector (const FilteredComplex& complex,
               const PersistenceResult& result,
               STPPHomology homology);

/** \brief The size of a cloud: twice the root mean square distance of its points
 * from their centroid (the diameter of a sphere sampled on its surface). The sums
 * run in the given order: pass the points in a canonical order for a value that
 * does not depend on the input order. */
double
cloudSize (const std::vector<Point3d>& points);

/** \brief \a count of the positions 0..size-1 (all of them when there are no
 * more), chosen by a hash of the position: a uniform random sample of a cloud of
 * \a size points. Given the points in a canonical order, it is the same for any
 * input order, and for a moved or scaled copy of the cloud.
 * \return the chosen positions, increasing */
std::vector<std::size_t>
hashedSample (std::size_t size, std::size_t count);

/** \brief A coarse copy of a cloud: the points of \a points (taken in the given
 * order) that are at least \a spacing from every point kept before them. No two of
 * its points are closer than \a spacing and every point of the cloud is closer than
 * \a spacing to one of them, so, unlike a voxel grid, it has no gaps that the cloud
 * does not have. Pass the points in a canonical order for a copy that does not
 * depend on the input order. */
std::vector<Point3d>
coarseCopy (const std::vector<Point3d>& points, double spacing);

/** \brief Writes the Betti-0 values of one level of an STPP signature from the
 * H0 persistence of the level's complex VR_r (r = \a radius, n vertices), into
 * \a values[0, STPP_BETTI0_PER_LEVEL):
 * - STPP_CURVE_SAMPLES values beta_0(t_j) / n at t_j = s + j (r - s) /
 *   STPP_CURVE_SAMPLES, j = 1..STPP_CURVE_SAMPLES, s = \a curve_start: the
 *   fraction of points still apart at t_j;
 * - log2(1 + beta_0(r)): the number of components at r. */
void
betti0LevelValues (const FilteredComplex& complex,
                   const PersistenceResult& result,
                   double curve_start,
                   double radius,
                   float* values);

/** \brief Writes the Betti-1 values of one level of an STPP signature from the
 * persistence of the level's complex VR_r, into \a values[0, STPP_BETTI1_PER_LEVEL):
 * - STPP_CURVE_SAMPLES values beta_1(t_j) / n at t_j in (s, r] as for Betti 0:
 *   the 1-cycles alive at t_j per point;
 * - log2(1 + e): e the number of essential 1-cycles (open at r);
 * - log2(1 + l): l the number of long-lived 1-cycles, whose life within [0, r]
 *   (death capped at r) is at least r / 2: holes rather than gaps of the sampling.
 */
void
betti1LevelValues (const FilteredComplex& complex,
                   const PersistenceResult& result,
                   double curve_start,
                   double radius,
                   float* values);

/** \brief \a points as a PCL cloud (single precision, as they were read). */
pcl::PointCloud<pcl::PointXYZ>::Ptr
toPointCloud (const std::vector<Point3d>& points);

/** \brief The complex VR_r of \a points (edges, and triangles unless \a homology
 * is BETTI_0) and its persistence (H0, and H1 unless BETTI_0), built with the given
 * memory limit and threads; false, with the builder's PCL_ERROR, when the complex is
 * refused. */
bool
levelPersistence (const std::vector<Point3d>& points,
                  double radius,
                  STPPHomology homology,
                  std::size_t memory_limit,
                  unsigned int threads,
                  FilteredComplex& complex,
                  PersistenceResult& result);

/** \brief The values of \a signature that describe \a homology: the Betti-0 part,
 * the Betti-1 part or both, followed by the size value. */
std::vector<float>
stppSignatureValues (const STPPSignature& signature, STPPHomology homology);

} // namespace tda
} // namespace pcl
