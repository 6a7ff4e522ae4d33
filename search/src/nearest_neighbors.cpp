#include <pcl/tda/search/nearest_neighbors.h>
#include <pcl/tda/search/radius_edges.h>

#include <flann/algorithms/dist.h>
#include <flann/algorithms/kdtree_single_index.h>

#include <algorithm>

namespace pcl {
namespace tda {
namespace {

/** Points per leaf, as pcl::KdTreeFLANN builds its tree. */
constexpr int LEAF_SIZE = 15;

} // namespace

struct NearestNeighbors::Tree {
  flann::KDTreeSingleIndex<flann::L2_Simple<float>> index;
};

NearestNeighbors::NearestNeighbors (std::vector<float> xyz) : xyz_ (std::move (xyz))
{
  if (xyz_.empty())
    return;
  tree_.reset (new Tree{flann::KDTreeSingleIndex<flann::L2_Simple<float>> (
      flann::Matrix<float> (xyz_.data(), size(), 3),
      flann::KDTreeSingleIndexParams (LEAF_SIZE))});
  tree_->index.buildIndex();
}

NearestNeighbors::~NearestNeighbors() = default;

std::size_t
NearestNeighbors::size() const
{
  return xyz_.size() / 3;
}

void
NearestNeighbors::search (std::vector<float> queries,
                          std::size_t k,
                          unsigned int threads,
                          std::vector<std::uint32_t>& neighbors,
                          std::vector<float>& squared_distances) const
{
  const std::size_t num_queries = queries.size() / 3;
  k = std::min (k, size());
  neighbors.assign (num_queries * k, 0);
  squared_distances.assign (num_queries * k, 0.0f);
  if (num_queries == 0 || k == 0)
    return;
  std::vector<std::size_t> found (num_queries * k);
  flann::Matrix<std::size_t> found_matrix (found.data(), num_queries, k);
  flann::Matrix<float> distance_matrix (squared_distances.data(), num_queries, k);
  flann::SearchParams params (flann::FLANN_CHECKS_UNLIMITED, 0.0f, true);
  params.cores = static_cast<int> (resolveThreads (threads));
  tree_->index.knnSearch (flann::Matrix<float> (queries.data(), num_queries, 3),
                          found_matrix,
                          distance_matrix,
                          k,
                          params);
  std::transform (found.begin(), found.end(), neighbors.begin(), [] (std::size_t i) {
    return static_cast<std::uint32_t> (i);
  });
}

std::vector<float>
floatCoordinates (const std::vector<Point3d>& points)
{
  std::vector<float> xyz;
  xyz.reserve (3 * points.size());
  for (const Point3d& point : points)
    for (const double coordinate : point)
      xyz.push_back (static_cast<float> (coordinate));
  return xyz;
}

std::vector<float>
floatCoordinates (const std::vector<Point3d>& points,
                  const std::vector<std::uint32_t>& indices)
{
  std::vector<float> xyz;
  xyz.reserve (3 * indices.size());
  for (const std::uint32_t index : indices)
    for (const double coordinate : points[index])
      xyz.push_back (static_cast<float> (coordinate));
  return xyz;
}

} // namespace tda
} // namespace pcl
