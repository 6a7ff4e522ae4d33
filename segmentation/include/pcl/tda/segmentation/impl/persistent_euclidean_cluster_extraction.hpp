#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/index_check.h>
#include <pcl/tda/common/persistent_components.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/search/radius_spanning_forest.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/tda/segmentation/persistent_euclidean_cluster_extraction.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl {
namespace tda {

template <typename PointT>
bool
PersistentEuclideanClusterExtraction<PointT>::checkParameters() const
{
  const std::string name_string = getClassName();
  const char* name = name_string.c_str();
  if (!indicesAreValid (name_string + "::extract", input_->size(), *indices_))
    return false;
  if (!(max_distance_ > 0.0) || !std::isfinite (max_distance_)) {
    PCL_ERROR ("[pcl::tda::%s::extract] The max distance must be positive and finite, "
               "not %g: call setMaxDistance().\n",
               name,
               max_distance_);
    return false;
  }
  if (min_pts_per_cluster_ > max_pts_per_cluster_) {
    PCL_ERROR ("[pcl::tda::%s::extract] The min cluster size (%zu) is above the max "
               "cluster size (%zu).\n",
               name,
               static_cast<std::size_t> (min_pts_per_cluster_),
               static_cast<std::size_t> (max_pts_per_cluster_));
    return false;
  }
  if (auto_max_distance_ && !(gap_ratio_ > 1.0 && std::isfinite (gap_ratio_))) {
    PCL_ERROR ("[pcl::tda::%s::extract] The auto gap ratio must be a finite number "
               "above 1, not %g.\n",
               name,
               gap_ratio_);
    return false;
  }
  if (auto_max_distance_ &&
      !(auto_min_distance_ >= 0.0 && std::isfinite (auto_min_distance_))) {
    PCL_ERROR ("[pcl::tda::%s::extract] The auto min distance must be a finite number "
               "of at least 0, not %g.\n",
               name,
               auto_min_distance_);
    return false;
  }
  if (auto_max_distance_ && !(piece_ratio_ >= 0.0 && piece_ratio_ < 1.0)) {
    PCL_ERROR ("[pcl::tda::%s::extract] The auto piece ratio must be at least 0 and "
               "below 1, not %g.\n",
               name,
               piece_ratio_);
    return false;
  }
  return true;
}

template <typename PointT>
bool
PersistentEuclideanClusterExtraction<PointT>::passesPCLDistanceTest (
    pcl::index_t i, pcl::index_t j) const
{
  // As pcl::EuclideanClusterExtraction: the tolerance goes through float, the k-d
  // tree (FLANN, L2_Simple) compares a float sum of float squares with float(r^2).
  const double tolerance = static_cast<float> (max_distance_);
  const auto squared_radius = static_cast<float> (tolerance * tolerance);
  const PointT& p = (*input_)[i];
  const PointT& q = (*input_)[j];
  const float dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
  float squared_distance = 0.0f;
  squared_distance += dx * dx;
  squared_distance += dy * dy;
  squared_distance += dz * dz;
  return squared_distance < squared_radius;
}

template <typename PointT>
bool
PersistentEuclideanClusterExtraction<PointT>::buildGraph (FilteredComplex& complex)
{
  // PCL's test can keep pairs up to float rounding (a few 1e-7 r) beyond r.
  const double radius =
      pcl_distance_test_ ? max_distance_ * (1.0 + 1e-6) : max_distance_;
  if (tree_) {
    VietorisRipsBuilder<PointT> builder;
    builder.setInputCloud (input_);
    builder.setIndices (indices_);
    builder.setRadius (radius);
    builder.setMaxDimension (1);
    builder.setNumberOfThreads (threads_);
    builder.setMemoryLimit (memory_limit_);
    builder.setSearchMethod (tree_);
    if (!builder.compute (complex)) {
      PCL_ERROR ("[pcl::tda::%s::extract] Cannot build the radius graph (see above).\n",
                 getClassName().c_str());
      return false;
    }
    if (pcl_distance_test_) {
      const pcl::Indices& point_of = complex.pointIndices();
      std::vector<FilteredEdge> edges;
      for (const FilteredEdge& edge : complex.edges())
        if (passesPCLDistanceTest (point_of[edge.source], point_of[edge.target]))
          edges.push_back (edge);
      complex = FilteredComplex::adoptValidParts (
          complex.numVertices(), std::move (edges), {}, point_of);
    }
    num_edges_ = complex.numEdges();
    return true;
  }

  pcl::Indices point_of;
  std::vector<Point3d> points;
  point_of.reserve (indices_->size());
  points.reserve (indices_->size());
  for (const auto index : *indices_) {
    const PointT& point = (*input_)[index];
    if (pcl::isXYZFinite (point)) {
      point_of.push_back (index);
      points.push_back ({point.x, point.y, point.z});
    }
  }
  const MemoryBudget budget{memory_limit_, BYTES_PER_EDGE, 0};
  std::vector<FilteredEdge> forest;
  try {
    if (pcl_distance_test_) {
      const auto accept = [this, &point_of] (SimplexIndex a, SimplexIndex b) {
        return passesPCLDistanceTest (point_of[a], point_of[b]);
      };
      num_edges_ =
          radiusGraphSpanningForest (points, radius, accept, threads_, budget, forest);
    }
    else
      num_edges_ = radiusGraphSpanningForest (
          points, radius, AcceptAllPairs{}, threads_, budget, forest);
  }
  catch (const pcl::PCLException& error) {
    PCL_ERROR ("[pcl::tda::%s::extract] %s\n",
               getClassName().c_str(),
               errorMessage (error).c_str());
    return false;
  }
  complex = FilteredComplex::adoptValidParts (
      points.size(), std::move (forest), {}, std::move (point_of));
  return true;
}

template <typename PointT>
void
PersistentEuclideanClusterExtraction<PointT>::extract (
    std::vector<pcl::PointIndices>& clusters)
{
  clusters.clear();
  diagram_.clear();
  chosen_distance_ = 0.0;
  auto_distance_is_clear_ = false;
  num_oversized_clusters_ = 0;
  num_edges_ = 0;
  if (!input_) {
    PCL_ERROR ("[pcl::tda::%s::extract] No input cloud: call setInputCloud().\n",
               getClassName().c_str());
    return;
  }
  if (!initCompute())
    return;
  if (!checkParameters()) {
    deinitCompute();
    return;
  }
  const bool any_finite =
      std::any_of (indices_->begin(), indices_->end(), [this] (pcl::index_t index) {
        return pcl::isXYZFinite ((*input_)[index]);
      });
  if (!any_finite) {
    PCL_ERROR ("[pcl::tda::%s::extract] The input has no finite point (%zu points, "
               "all NaN or infinite, or none).\n",
               getClassName().c_str(),
               indices_->size());
    deinitCompute();
    return;
  }

  // H0 needs only the radius graph, the 1-skeleton of VR_r, or just its minimum
  // spanning forest.
  FilteredComplex complex;
  if (!buildGraph (complex)) {
    deinitCompute();
    return;
  }

  const PersistenceResult h0 = computeH0Persistence (complex);
  diagram_ = steppedH0Diagram (complex, h0, max_distance_, filtration_steps_);
  chosen_distance_ = max_distance_;
  if (auto_max_distance_) {
    const ClusterDistanceChoice choice = chooseClusterDistance (complex,
                                                                h0,
                                                                max_distance_,
                                                                min_pts_per_cluster_,
                                                                gap_ratio_,
                                                                auto_min_distance_,
                                                                piece_ratio_);
    chosen_distance_ = choice.distance;
    auto_distance_is_clear_ = choice.clear;
    if (choice.num_clusters == 0)
      PCL_WARN ("[pcl::tda::%s::extract] No component of the minimum cluster size "
                "stands apart above the sampling scale %g and the floor "
                "(setAutoMinDistance()), up to the max distance: too few distinct "
                "points to choose a distance; the max distance %g is used.\n",
                getClassName().c_str(),
                choice.sampling_scale,
                chosen_distance_);
    else if (!choice.clear)
      PCL_WARN ("[pcl::tda::%s::extract] The H0 diagram shows no clear gap: the "
                "automatic distance %g (in a step of %zu cluster%s, pieces of larger "
                "ones not counted, from %g to %g; sampling scale %g) is a guess. Check "
                "the barcode, or set the distance.\n",
                getClassName().c_str(),
                chosen_distance_,
                choice.num_clusters,
                choice.num_clusters == 1 ? "" : "s",
                choice.low,
                choice.high,
                choice.sampling_scale);
  }

  std::vector<pcl::Indices> components = persistentComponents (
      complex,
      h0,
      auto_max_distance_ ? chosen_distance_ : std::numeric_limits<double>::infinity());
  std::size_t largest_oversized = 0;
  for (auto& component : components) {
    if (component.size() < min_pts_per_cluster_)
      continue;
    if (component.size() > max_pts_per_cluster_) {
      ++num_oversized_clusters_;
      largest_oversized = std::max (largest_oversized, component.size());
      if (!keep_oversized_clusters_)
        continue;
    }
    pcl::PointIndices cluster;
    cluster.header = input_->header;
    cluster.indices = std::move (component);
    clusters.push_back (std::move (cluster));
  }
  if (num_oversized_clusters_ > 0)
    PCL_WARN ("[pcl::tda::%s::extract] %zu components have more than the max cluster "
              "size of %zu points (the largest %zu): %s.\n",
              getClassName().c_str(),
              num_oversized_clusters_,
              static_cast<std::size_t> (max_pts_per_cluster_),
              largest_oversized,
              keep_oversized_clusters_ ? "kept as clusters"
                                       : "dropped (setKeepOversizedClusters(true) "
                                         "keeps them)");
  deinitCompute();
}

} // namespace tda
} // namespace pcl

#define PCL_INSTANTIATE_PersistentEuclideanClusterExtraction(T)                        \
  template class PCL_EXPORTS pcl::tda::PersistentEuclideanClusterExtraction<T>;
