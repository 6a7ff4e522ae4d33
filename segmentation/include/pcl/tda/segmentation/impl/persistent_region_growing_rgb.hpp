#pragma once

#include <pcl/common/colors.h>
#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/index_check.h>
#include <pcl/tda/common/persistent_components.h>
#include <pcl/tda/common/spanning_forest.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/segmentation/persistent_region_growing_rgb.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace pcl {
namespace tda {

template <typename PointT, typename NormalT>
bool
PersistentRegionGrowingRGB<PointT, NormalT>::checkParameters() const
{
  const char* name = getClassName().c_str();
  if (!indicesAreValid (getClassName() + "::extract", input_->size(), *indices_))
    return false;
  if (filtration_ != Filtration::COLOR && filtration_ != Filtration::DISTANCE) {
    PCL_ERROR ("[pcl::tda::%s::extract] Unknown filtration %d: COLOR or DISTANCE.\n",
               name,
               static_cast<int> (filtration_));
    return false;
  }
  if (normals_ && normals_->size() != input_->size()) {
    PCL_ERROR ("[pcl::tda::%s::extract] The normals (%zu) are not one per input point "
               "(%zu).\n",
               name,
               static_cast<std::size_t> (normals_->size()),
               static_cast<std::size_t> (input_->size()));
    return false;
  }
  if (!(max_distance_ > 0.0) || !std::isfinite (max_distance_)) {
    PCL_ERROR ("[pcl::tda::%s::extract] The max distance must be positive and finite, "
               "not %g: call setMaxDistance().\n",
               name,
               max_distance_);
    return false;
  }
  if (!(image_neighbor_ratio_ >= 0.0) || !std::isfinite (image_neighbor_ratio_)) {
    PCL_ERROR ("[pcl::tda::%s::extract] The image neighbour ratio must be finite and "
               "at least 0, not %g.\n",
               name,
               image_neighbor_ratio_);
    return false;
  }
  if (!(color_threshold_ > 0.0) || !std::isfinite (color_threshold_)) {
    PCL_ERROR ("[pcl::tda::%s::extract] The colour threshold must be a positive Delta "
               "E, not %g.\n",
               name,
               color_threshold_);
    return false;
  }
  if ((normals_ || estimate_normals_) &&
      !(normal_angle_ > 0.0 && normal_angle_ <= 90.0)) {
    PCL_ERROR ("[pcl::tda::%s::extract] The normal angle threshold must be in (0, 90] "
               "degrees, not %g.\n",
               name,
               normal_angle_);
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
  if (!(region_color_threshold_ >= 0.0) || !std::isfinite (region_color_threshold_) ||
      (auto_color_threshold_ && region_color_threshold_ == 0.0)) {
    PCL_ERROR ("[pcl::tda::%s::extract] The region colour threshold must be a finite "
               "Delta E, positive with the automatic threshold (its upper bound) and "
               "at least 0 otherwise, not %g.\n",
               name,
               region_color_threshold_);
    return false;
  }
  if (!(max_merge_color_difference_ > 0.0)) {
    PCL_ERROR ("[pcl::tda::%s::extract] The max merge colour difference must be a "
               "positive Delta E (infinity: no limit), not %g.\n",
               name,
               max_merge_color_difference_);
    return false;
  }
  if (auto_color_threshold_ && !(gap_ratio_ > 1.0 && std::isfinite (gap_ratio_))) {
    PCL_ERROR ("[pcl::tda::%s::extract] The auto gap ratio must be a finite number "
               "above 1, not %g.\n",
               name,
               gap_ratio_);
    return false;
  }
  if (auto_color_threshold_ &&
      !(auto_min_color_threshold_ > 0.0 && std::isfinite (auto_min_color_threshold_))) {
    PCL_ERROR ("[pcl::tda::%s::extract] The auto min colour threshold must be a "
               "positive finite Delta E, not %g.\n",
               name,
               auto_min_color_threshold_);
    return false;
  }
  return true;
}

template <typename PointT, typename NormalT>
void
PersistentRegionGrowingRGB<PointT, NormalT>::gatherVertices (
    HomogeneityVertices& vertices, pcl::Indices& point_of)
{
  point_of.clear();
  for (const auto index : *indices_) {
    if (!pcl::isXYZFinite ((*input_)[index]))
      continue;
    if (normals_ && !isUsableNormal ((*normals_)[index]))
      continue;
    point_of.push_back (index);
  }
  num_skipped_points_ = indices_->size() - point_of.size();
  // The canonical order (x, y, z, then colour): nothing depends on the input order.
  std::sort (point_of.begin(), point_of.end(), [this] (pcl::index_t a, pcl::index_t b) {
    const PointT& p = (*input_)[a];
    const PointT& q = (*input_)[b];
    return std::tie (p.x, p.y, p.z, p.r, p.g, p.b, a) <
           std::tie (q.x, q.y, q.z, q.r, q.g, q.b, b);
  });
  vertices.points.resize (point_of.size());
  vertices.colors.resize (point_of.size());
  vertices.normals.resize (normals_ ? point_of.size() : 0);
  for (std::size_t v = 0; v < point_of.size(); ++v) {
    const PointT& point = (*input_)[point_of[v]];
    vertices.points[v] = {point.x, point.y, point.z};
    vertices.colors[v] = rgbToLab (point.r, point.g, point.b);
    if (normals_)
      vertices.normals[v] =
          (*normals_)[point_of[v]].getNormalVector3fMap().normalized();
  }
}

template <typename PointT, typename NormalT>
void
PersistentRegionGrowingRGB<PointT, NormalT>::extract (
    std::vector<pcl::PointIndices>& regions)
{
  regions.clear();
  last_regions_.clear();
  extracted_cloud_.reset();
  diagram_.clear();
  lifetimes_.clear();
  region_barcode_.clear();
  chosen_region_threshold_ = 0.0;
  auto_threshold_is_clear_ = false;
  num_edges_ = 0;
  num_skipped_points_ = 0;
  const char* name = getClassName().c_str();
  if (!input_) {
    PCL_ERROR ("[pcl::tda::%s::extract] No input cloud: call setInputCloud().\n", name);
    return;
  }
  if (!initCompute())
    return;
  if (!checkParameters()) {
    deinitCompute();
    return;
  }
  HomogeneityVertices vertices;
  pcl::Indices point_of;
  gatherVertices (vertices, point_of);
  if (point_of.empty()) {
    PCL_ERROR (
        "[pcl::tda::%s::extract] The input has no point with a finite position%s "
        "(%zu points).\n",
        name,
        normals_ ? " and a finite, non-zero normal" : "",
        indices_->size());
    deinitCompute();
    return;
  }
  if (num_skipped_points_ > 0)
    PCL_DEBUG (
        "[pcl::tda::%s::extract] %zu points without a finite position%s are left "
        "out.\n",
        name,
        num_skipped_points_,
        normals_ ? " or normal" : "");

  // The neighbour graph, then every edge valued by its Delta E.
  const std::size_t n = point_of.size();
  const MemoryBudget budget{memory_limit_, BYTES_PER_EDGE, 0};
  std::vector<FilteredEdge> graph;
  ComplexSize size;
  bool fits = false;
  try {
    fits = neighborGraph (
        vertices.points, max_distance_, threads_, budget, graph, size, progress_);
  }
  catch (const pcl::PCLException& error) {
    PCL_ERROR ("[pcl::tda::%s::extract] %s\n", name, errorMessage (error).c_str());
    deinitCompute();
    return;
  }
  if (!fits) {
    PCL_ERROR (
        "[pcl::tda::%s::extract] The neighbour graph of max distance %g would "
        "have %s%.0f edges, %s%s, over the memory limit of %s. Use a smaller max "
        "distance, a voxel grid, or a larger limit (setMemoryLimit()).\n",
        name,
        max_distance_,
        size.exact ? "" : "about ",
        size.edges,
        size.exact ? "" : "about ",
        formatBytes (budget.bytes (size.edges, 0.0)).c_str(),
        formatBytes (static_cast<double> (memory_limit_)).c_str());
    deinitCompute();
    return;
  }
  if (image_neighbor_ratio_ > 0.0 && input_->isOrganized() && input_->width > 1) {
    std::vector<SimplexIndex> vertex_of_pixel (input_->size(), INVALID_SIMPLEX);
    for (std::size_t v = 0; v < n; ++v)
      vertex_of_pixel[point_of[v]] = static_cast<SimplexIndex> (v);
    const Eigen::Vector4f& sensor = input_->sensor_origin_;
    addImageNeighbors (vertices.points,
                       vertex_of_pixel,
                       input_->width,
                       {sensor[0], sensor[1], sensor[2]},
                       max_distance_,
                       image_neighbor_ratio_,
                       graph);
  }
  addNearestNeighbors (vertices.points, max_distance_, min_neighbors_, threads_, graph);
  const bool estimate_normals = estimate_normals_ && !normals_;
  if (color_smoothing_ || estimate_normals) {
    const NeighborLists lists = neighborLists (n, graph);
    if (estimate_normals)
      vertices.normals = neighborNormals (vertices.points, lists, threads_);
    if (color_smoothing_)
      vertices.colors =
          medianSmoothedColors (vertices.colors,
                                lists,
                                static_cast<float> (SMOOTHING_RANGE * color_threshold_),
                                threads_);
  }
  valueByHomogeneity (graph,
                      vertices.colors,
                      vertices.normals,
                      std::cos (normal_angle_ * M_PI / 180.0),
                      threads_);
  num_edges_ = graph.size();

  // H0 of the homogeneity filtration, and the threshold.
  std::vector<FilteredEdge> forest = homogeneityForest (n, graph);
  const FilteredComplex complex =
      FilteredComplex::adoptValidParts (n, forest, {}, point_of);
  const PersistenceResult h0 = computeH0Persistence (complex);
  // The first filtration: patches of similar neighbours.
  const double threshold = color_threshold_;
  ColorRegions found = regionsAtThreshold (n, forest, threshold, min_pts_per_cluster_);
  region_barcode_ = found.bars;
  if (merge_small_regions_) {
    const std::vector<std::uint32_t> isolated =
        mergeSmallRegions (graph,
                           forest,
                           vertices.colors,
                           threshold,
                           min_pts_per_cluster_,
                           max_merge_color_difference_,
                           found);
    attachIsolatedPoints (vertices.points,
                          vertices.colors,
                          isolated,
                          ISOLATED_NEIGHBORS,
                          threads_,
                          found);
  }

  // The second: adjacent patches of similar mean colour.
  chosen_region_threshold_ = region_color_threshold_;
  if (auto_color_threshold_ || region_color_threshold_ > 0.0) {
    const std::vector<FilteredEdge> patch_forest =
        regionColorForest (graph, vertices.colors, found);
    const std::size_t num_patches = found.lifetimes.size();
    if (auto_color_threshold_) {
      const ColorThresholdChoice choice = chooseColorThreshold (
          regionsAtThreshold (num_patches, patch_forest, 0.0, 1).bars,
          auto_min_color_threshold_,
          region_color_threshold_,
          gap_ratio_,
          DEFAULT_REGION_COLOR_THRESHOLD);
      chosen_region_threshold_ = choice.threshold;
      auto_threshold_is_clear_ = choice.clear;
      if (choice.num_regions == 0)
        PCL_WARN ("[pcl::tda::%s::extract] No region reaches the minimum size at any "
                  "colour threshold: the default region colour threshold %g is "
                  "used.\n",
                  name,
                  chosen_region_threshold_);
      else if (!choice.clear)
        PCL_WARN (
            "[pcl::tda::%s::extract] The region barcode shows no clear gap (the "
            "step taken: %zu region%s from Delta E %g to %g): the automatic "
            "region colour threshold %g is a guess. Check the barcode, or set the "
            "threshold.\n",
            name,
            choice.num_regions,
            choice.num_regions == 1 ? "" : "s",
            choice.low,
            choice.high,
            chosen_region_threshold_);
    }
    found = mergeSimilarRegions (found, patch_forest, chosen_region_threshold_);
    region_barcode_ = found.bars;
  }

  if (filtration_ == Filtration::COLOR)
    diagram_ = steppedH0Diagram (complex, h0, threshold, filtration_steps_);
  else {
    // The thesis' filtration: the similar pairs, valued by their length.
    std::vector<FilteredEdge> similar;
    for (const FilteredEdge& edge : graph)
      if (edge.value <= threshold)
        similar.push_back (
            {edge.source,
             edge.target,
             distance (vertices.points[edge.source], vertices.points[edge.target])});
    graph = {};
    const FilteredComplex by_distance = FilteredComplex::adoptValidParts (
        n, minimumSpanningForest (n, similar), {}, point_of);
    diagram_ = steppedH0Diagram (by_distance,
                                 computeH0Persistence (by_distance),
                                 max_distance_,
                                 filtration_steps_);
  }

  // The regions, in their order (largest first), without the oversized ones.
  std::vector<pcl::Indices> members (found.lifetimes.size());
  for (std::size_t v = 0; v < n; ++v)
    if (found.region_of[v] != NO_REGION)
      members[found.region_of[v]].push_back (point_of[v]);
  std::size_t num_oversized = 0, largest_oversized = 0;
  for (std::size_t k = 0; k < members.size(); ++k) {
    if (members[k].size() > max_pts_per_cluster_) {
      ++num_oversized;
      largest_oversized = std::max (largest_oversized, members[k].size());
      continue;
    }
    pcl::PointIndices region;
    region.header = input_->header;
    region.indices = std::move (members[k]);
    std::sort (region.indices.begin(), region.indices.end());
    regions.push_back (std::move (region));
    lifetimes_.push_back (found.lifetimes[k]);
  }
  if (num_oversized > 0)
    PCL_WARN ("[pcl::tda::%s::extract] %zu regions have more than the max cluster size "
              "of %zu points (the largest %zu) and are left out.\n",
              name,
              num_oversized,
              static_cast<std::size_t> (max_pts_per_cluster_),
              largest_oversized);
  last_regions_ = regions;
  extracted_cloud_ = input_;
  deinitCompute();
}

template <typename PointT, typename NormalT>
pcl::PointCloud<pcl::PointXYZRGB>::Ptr
PersistentRegionGrowingRGB<PointT, NormalT>::getColoredCloud() const
{
  if (!extracted_cloud_)
    return nullptr;
  const pcl::PointCloud<PointT>& cloud = *extracted_cloud_;
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr colored (
      new pcl::PointCloud<pcl::PointXYZRGB>);
  colored->header = cloud.header;
  colored->width = cloud.width;
  colored->height = cloud.height;
  colored->is_dense = cloud.is_dense;
  colored->resize (cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    pcl::PointXYZRGB& point = (*colored)[i];
    point.getVector3fMap() = cloud[i].getVector3fMap();
    point.r = point.g = point.b = 255;
  }
  for (std::size_t k = 0; k < last_regions_.size(); ++k) {
    const pcl::RGB color = pcl::GlasbeyLUT::at (k % pcl::GlasbeyLUT::size());
    for (const auto index : last_regions_[k].indices) {
      (*colored)[index].r = color.r;
      (*colored)[index].g = color.g;
      (*colored)[index].b = color.b;
    }
  }
  return colored;
}

} // namespace tda
} // namespace pcl

#define PCL_INSTANTIATE_PersistentRegionGrowingRGB(T, NT)                              \
  template class PCL_EXPORTS pcl::tda::PersistentRegionGrowingRGB<T, NT>;
