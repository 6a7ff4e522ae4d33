#pragma once

// Oracles for cluster extraction, shared by the tests and the benchmark:
// pcl::EuclideanClusterExtraction in our output order, and the object-level scores
// of clusters against ground-truth labels.

#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/PointIndices.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <vector>

namespace pcl {
namespace tda {
namespace test {

/** Sorts clusters as PersistentEuclideanClusterExtraction does: largest first, equal
 * sizes by smallest index, each cluster sorted. */
inline void
sortClusters (std::vector<pcl::PointIndices>& clusters)
{
  for (auto& cluster : clusters)
    std::sort (cluster.indices.begin(), cluster.indices.end());
  std::sort (clusters.begin(),
             clusters.end(),
             [] (const pcl::PointIndices& a, const pcl::PointIndices& b) {
               return a.indices.size() != b.indices.size()
                          ? a.indices.size() > b.indices.size()
                          : a.indices[0] < b.indices[0];
             });
}

/** The clusters of pcl::EuclideanClusterExtraction (k-d tree search), sorted. */
template <typename PointT>
std::vector<pcl::PointIndices>
pclEuclideanClusters (
    const typename pcl::PointCloud<PointT>::ConstPtr& cloud,
    double tolerance,
    pcl::uindex_t min_size = 1,
    pcl::uindex_t max_size = std::numeric_limits<pcl::uindex_t>::max())
{
  pcl::EuclideanClusterExtraction<PointT> extraction;
  extraction.setInputCloud (cloud);
  extraction.setSearchMethod (
      typename pcl::search::KdTree<PointT>::Ptr (new pcl::search::KdTree<PointT>));
  extraction.setClusterTolerance (tolerance);
  extraction.setMinClusterSize (min_size);
  extraction.setMaxClusterSize (max_size);
  std::vector<pcl::PointIndices> clusters;
  extraction.extract (clusters);
  sortClusters (clusters);
  return clusters;
}

/** True when both lists hold the same clusters in the same order. */
inline bool
sameClusters (const std::vector<pcl::PointIndices>& a,
              const std::vector<pcl::PointIndices>& b)
{
  return std::equal (a.begin(),
                     a.end(),
                     b.begin(),
                     b.end(),
                     [] (const pcl::PointIndices& x, const pcl::PointIndices& y) {
                       return x.indices == y.indices;
                     });
}

/** Object-level matching of clusters against ground-truth labels: a cluster finds
 * an object when their intersection over union is at least 0.5 (so at most one). */
struct ObjectScores {
  std::size_t objects = 0;      // ground-truth objects (labels >= first_object)
  std::size_t clusters = 0;     // clusters
  std::size_t matched = 0;      // objects found by a cluster with IoU >= 0.5
  std::vector<double> best_iou; // per object, in label order

  void
  add (const ObjectScores& other)
  {
    objects += other.objects;
    clusters += other.clusters;
    matched += other.matched;
    best_iou.insert (best_iou.end(), other.best_iou.begin(), other.best_iou.end());
  }

  double
  f1 () const
  {
    return objects + clusters == 0 ? 1.0 : 2.0 * matched / (objects + clusters);
  }
};

inline ObjectScores
scoreObjects (const std::vector<std::uint32_t>& labels,
              const std::vector<pcl::PointIndices>& clusters,
              std::uint32_t first_object)
{
  std::map<std::uint32_t, std::size_t> object_sizes;
  for (const auto label : labels)
    if (label >= first_object)
      ++object_sizes[label];
  ObjectScores scores;
  scores.objects = object_sizes.size();
  scores.clusters = clusters.size();
  for (const auto& [label, size] : object_sizes) {
    double best = 0.0;
    for (const auto& cluster : clusters) {
      std::size_t common = 0;
      for (const auto index : cluster.indices)
        common += labels[index] == label;
      best = std::max (best,
                       static_cast<double> (common) /
                           (size + cluster.indices.size() - common));
    }
    scores.best_iou.push_back (best);
    scores.matched += best >= 0.5;
  }
  return scores;
}

} // namespace test
} // namespace tda
} // namespace pcl
