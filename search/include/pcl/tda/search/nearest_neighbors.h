#pragma once

#include <pcl/tda/common/point3d.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The k nearest points of many query points at once, over a fixed set of 3D
 * points, on a FLANN k-d tree (the tree and metric of pcl::KdTreeFLANN, so the same
 * neighbours and distances).
 *
 * pcl::KdTreeFLANN searches one query per call, and FLANN opens an OpenMP parallel
 * region for each call: on small clouds that costs more than the search. Here the
 * queries go to FLANN in one batch, searched in parallel. The result does not depend
 * on the number of threads. */
class NearestNeighbors {
public:
  /** \brief Builds the tree over the points of \a xyz (x, y, z of point i at 3i, 3i
   * + 1, 3i + 2), which must all be finite. The tree depends on their order. */
  explicit NearestNeighbors (std::vector<float> xyz);
  ~NearestNeighbors();
  NearestNeighbors (const NearestNeighbors&) = delete;
  NearestNeighbors&
  operator= (const NearestNeighbors&) = delete;

  /** \brief Number of points of the set. */
  std::size_t
  size () const;

  /** \brief The k nearest points of the set to each query point (x, y, z of query q
   * at 3q, 3q + 1, 3q + 2 of \a queries; a query that is a point of the set is among
   * its own neighbours), with k = min(\a k, size()). Row q of \a neighbors and
   * \a squared_distances (k entries from q k) holds those of query q, nearest
   * first. Searched with \a threads OpenMP threads (0: OpenMP's default). */
  void
  search (std::vector<float> queries,
          std::size_t k,
          unsigned int threads,
          std::vector<std::uint32_t>& neighbors,
          std::vector<float>& squared_distances) const;

private:
  struct Tree;
  std::vector<float> xyz_;
  std::unique_ptr<Tree> tree_;
};

/** \brief The coordinates of \a points as NearestNeighbors takes them: x, y, z of
 * each point in turn, rounded to float. */
std::vector<float>
floatCoordinates (const std::vector<Point3d>& points);

/** \brief The coordinates of the points of \a points listed in \a indices, in that
 * order, as NearestNeighbors takes them. */
std::vector<float>
floatCoordinates (const std::vector<Point3d>& points,
                  const std::vector<std::uint32_t>& indices);

} // namespace tda
} // namespace pcl
