#pragma once

#include <pcl/common/point_tests.h>
#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/index_check.h>
#include <pcl/tda/features/border_polygons.h>
#include <pcl/tda/features/hole_boundary_estimation.h>
#include <pcl/tda/features/minimal_cycles.h>
#include <pcl/tda/features/setting_checks.h>
#include <pcl/tda/search/clique_persistence.h>
#include <pcl/tda/search/vietoris_rips_builder.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace pcl {
namespace tda {

template <typename PointInT, typename PointOutT>
bool
HoleBoundaryEstimation<PointInT, PointOutT>::initCompute()
{
  clearResults();
  if (!checkFeatureInput (pcl::PCLBase<PointInT>::initCompute(),
                          getClassName(),
                          this->search_radius_,
                          this->k_,
                          this->tree_ != nullptr,
                          this->surface_ && this->surface_ != input_))
    return false;
  if (!indicesAreValid (getClassName() + "::compute", input_->size(), *indices_) ||
      !checkOptionalLength (radius_, getClassName(), "radius", "to choose it"))
    return false;
  if (!(max_tilt_degrees_ >= 0.0 && max_tilt_degrees_ <= 90.0)) {
    PCL_ERROR ("[pcl::tda::%s::compute] The max tilt angle must be in [0, 90] degrees "
               "(got %g).\n",
               getClassName().c_str(),
               max_tilt_degrees_);
    return false;
  }
  return checkOptionalLength (spacing_, getClassName(), "spacing", "to measure it") &&
         checkOptionalLength (
             min_hole_radius_, getClassName(), "min hole radius", "for the default") &&
         checkOptionalLength (
             band_width_, getClassName(), "rim band width", "to choose it");
}

template <typename PointInT, typename PointOutT>
void
HoleBoundaryEstimation<PointInT, PointOutT>::clearResults()
{
  holes_.clear();
  diagram_.clear();
  rim_band_labels_.clear();
  complex_ = FilteredComplex();
  search_counts_ = SearchCounts();
  used_radius_ = used_persistence_radius_ = used_band_width_ = 0.0;
}

template <typename PointInT, typename PointOutT>
bool
HoleBoundaryEstimation<PointInT, PointOutT>::findHoles()
{
  const double spacing =
      spacing_ > 0.0 ? spacing_
                     : surfaceSpacing (pcl::PointCloud<PointInT> (*input_, *indices_),
                                       DEFAULT_SPACING_SAMPLES,
                                       threads_);
  if (!(spacing > 0.0)) {
    PCL_ERROR ("[pcl::tda::%s::compute] The input has fewer than %zu distinct finite "
               "points (%zu indexed): there is no surface.\n",
               getClassName().c_str(),
               SURFACE_SPACING_NEIGHBORS + 1,
               indices_->size());
    return false;
  }
  used_radius_ = radius_ > 0.0 ? radius_ : AUTO_RADIUS_PER_SPACING * spacing;
  if (used_radius_ > MAX_RADIUS_PER_SPACING * spacing) {
    PCL_ERROR ("[pcl::tda::%s::compute] The radius %g is %.0f times the point spacing "
               "%g, over %g times: at that radius the complex fills every hole "
               "narrower than about %g (radius / sqrt(3)), and the work of finding "
               "holes grows as the fourth power of the radius. Use a radius of about "
               "%g times the spacing (the default), at most %g; to keep only large "
               "holes, set the smallest hole radius instead.\n",
               getClassName().c_str(),
               used_radius_,
               used_radius_ / spacing,
               spacing,
               MAX_RADIUS_PER_SPACING,
               used_radius_ / std::sqrt (3.0),
               AUTO_RADIUS_PER_SPACING,
               MAX_RADIUS_PER_SPACING * spacing);
    return false;
  }
  used_band_width_ = band_width_ > 0.0
                         ? band_width_
                         : std::min (AUTO_BAND_PER_SPACING * spacing, used_radius_);
  if (used_band_width_ > used_radius_) {
    PCL_ERROR ("[pcl::tda::%s::compute] The rim band width (%g) must not exceed the "
               "radius (%g): the band is searched within two edges of a rim.\n",
               getClassName().c_str(),
               used_band_width_,
               used_radius_);
    return false;
  }

  const double min_clearance = min_hole_radius_ > 0.0
                                   ? min_hole_radius_
                                   : DEFAULT_MIN_HOLE_RADIUS_PER_SPACING * spacing;
  used_persistence_radius_ = std::max (used_radius_,
                                       PERSISTENCE_RADIUS_PER_MIN_HOLE_RADIUS *
                                           std::min (min_clearance, used_radius_));

  // Progress in quarters: the complex, its H1, then two for the search of classes.
  const auto quarters = [this] (std::size_t first, std::size_t count) {
    return [this, first, count] (std::size_t done, std::size_t total) {
      progress_ ((first * total + count * done) * (PROGRESS_UNITS / 2) / total,
                 2 * PROGRESS_UNITS);
    };
  };
  VietorisRipsBuilder<PointInT> builder;
  builder.setInputCloud (input_);
  builder.setIndices (indices_);
  builder.setRadius (used_persistence_radius_);
  builder.setMaxDimension (1);
  builder.setNumberOfThreads (threads_);
  builder.setMemoryLimit (memory_limit_);
  if (progress_)
    builder.setProgressCallback (quarters (0, 1));
  if (!builder.compute (complex_)) {
    PCL_ERROR ("[pcl::tda::%s::compute] Cannot build the complex of radius %g (see "
               "above).\n",
               getClassName().c_str(),
               used_persistence_radius_);
    return false;
  }
  const PersistenceResult h0 = computeH0Persistence (complex_);
  const CliqueH1Persistence h1 = computeCliqueH1Persistence (
      complex_, h0, threads_, progress_ ? quarters (1, 1) : ProgressCallback{});
  diagram_ = h0.diagram (complex_, 0);
  diagram_.insert (diagram_.end(), h1.diagram.begin(), h1.diagram.end());

  // The cycles are searched in VR_r: the edges up to r, a prefix of the list.
  const auto& edges = complex_.edges();
  const auto within_radius =
      static_cast<SimplexIndex> (std::partition_point (edges.begin(),
                                                       edges.end(),
                                                       [this] (const FilteredEdge& e) {
                                                         return e.value <= used_radius_;
                                                       }) -
                                 edges.begin());
  // The first triangle kills a 1-class, so VR_r has one iff a class dies by r.
  bool has_triangle = false;
  for (SimplexIndex e = 0; e < within_radius && !has_triangle; ++e)
    has_triangle = h0.edge_positive[e] && h1.edge_death[e] <= used_radius_;
  if (!has_triangle) {
    PCL_ERROR ("[pcl::tda::%s::compute] The complex of radius %g has no triangle "
               "(%zu points, %u edges, point spacing %g): the radius is too small to "
               "make a surface. Use a radius of about %g times the spacing.\n",
               getClassName().c_str(),
               used_radius_,
               complex_.numVertices(),
               within_radius,
               spacing,
               AUTO_RADIUS_PER_SPACING);
    return false;
  }

  std::vector<Point3d> positions (complex_.numVertices());
  const pcl::Indices& point_indices = complex_.pointIndices();
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const PointInT& p = (*input_)[point_indices[v]];
    positions[v] = {p.x, p.y, p.z};
  }
  const EdgeAdjacency adjacency = buildEdgeAdjacency (
      complex_.numVertices(), edges, [within_radius] (SimplexIndex e) {
        return e < within_radius;
      });
  // The classes that persist, then the borders, where a hole of a closed surface
  // may have no class of its own.
  std::vector<InitialCycle> initial =
      classCycles (complex_,
                   h0.edge_positive,
                   persistentClassEdges (edges,
                                         h0.edge_positive,
                                         h1.edge_death,
                                         used_radius_,
                                         used_persistence_radius_));
  search_counts_.edges = within_radius;
  search_counts_.triangles = h1.num_triangles;
  search_counts_.open_classes =
      persistentClassEdges (
          edges, h0.edge_positive, h1.edge_death, used_radius_, used_radius_)
          .size();
  search_counts_.persistent_classes = initial.size();
  std::vector<InitialCycle> borders =
      borderPolygons (positions, adjacency, used_radius_, min_clearance, threads_);
  search_counts_.border_polygons = borders.size();
  std::move (borders.begin(), borders.end(), std::back_inserter (initial));
  const std::vector<MinimalCycle> cycles =
      minimalCycles (complex_,
                     initial,
                     positions,
                     adjacency,
                     min_clearance,
                     threads_,
                     progress_ ? quarters (2, 2) : ProgressCallback{});
  holes_ = holeRims (cycles,
                     positions,
                     adjacency,
                     max_tilt_degrees_,
                     max_cycle_length_,
                     min_clearance,
                     min_hole_radius_ > 0.0
                         ? std::vector<double>{}
                         : cycleSparseness (cycles, positions, spacing, threads_));
  const std::vector<std::uint32_t> vertex_band =
      rimBand (holes_, positions, adjacency, used_band_width_, spacing);
  rim_band_labels_.assign (input_->size(), 0);
  for (std::size_t v = 0; v < positions.size(); ++v)
    rim_band_labels_[point_indices[v]] = vertex_band[v];
  for (HoleRim& hole : holes_)
    for (SimplexIndex& v : hole.rim)
      v = static_cast<SimplexIndex> (point_indices[v]);
  return true;
}

template <typename PointInT, typename PointOutT>
void
HoleBoundaryEstimation<PointInT, PointOutT>::computeFeature (PointCloudOut& output)
{
  if (!findHoles()) {
    clearResults();
    output.width = output.height = 0;
    output.clear();
    return;
  }
  for (std::size_t i = 0; i < indices_->size(); ++i)
    output[i].boundary_point = rim_band_labels_[(*indices_)[i]] != 0 ? 1 : 0;
}

} // namespace tda
} // namespace pcl

#define PCL_INSTANTIATE_HoleBoundaryEstimation(T, OutT)                                \
  template class PCL_EXPORTS pcl::tda::HoleBoundaryEstimation<T, OutT>;
