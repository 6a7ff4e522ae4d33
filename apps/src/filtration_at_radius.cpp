#include <pcl/tda/apps/filtration_at_radius.h>
#include <pcl/tda/common/persistent_components.h>

#include <algorithm>
#include <utility>

namespace pcl {
namespace tda {

FiltrationAtRadius::FiltrationAtRadius (FilteredComplex complex,
                                        PersistenceResult result)
: complex_ (std::move (complex)), result_ (std::move (result))
{
  diagram_ = result_.diagram (complex_, 1);
}

RadiusCounts
FiltrationAtRadius::countsAt (double radius) const
{
  // Edges and triangles are sorted by value.
  RadiusCounts counts;
  const auto& edges = complex_.edges();
  counts.edges = static_cast<std::size_t> (
      std::upper_bound (
          edges.begin(),
          edges.end(),
          radius,
          [] (double r, const FilteredEdge& edge) { return r < edge.value; }) -
      edges.begin());
  const auto& triangles = complex_.triangles();
  counts.triangles = static_cast<std::size_t> (
      std::upper_bound (triangles.begin(),
                        triangles.end(),
                        radius,
                        [] (double r, const FilteredTriangle& triangle) {
                          return r < triangle.value;
                        }) -
      triangles.begin());
  const BettiNumbers betti = computeBettiNumbersAt (complex_, result_, radius);
  counts.beta_0 = betti[0];
  counts.beta_1 = betti[1];
  return counts;
}

std::vector<std::uint32_t>
FiltrationAtRadius::componentLabels (double radius, std::size_t num_points) const
{
  std::vector<std::uint32_t> labels (num_points, 0);
  const std::vector<pcl::Indices> components =
      persistentComponents (complex_, result_, radius);
  for (std::size_t k = 0; k < components.size() && components[k].size() > 1; ++k)
    for (const auto index : components[k])
      labels[static_cast<std::size_t> (index)] = static_cast<std::uint32_t> (k + 1);
  return labels;
}

} // namespace tda
} // namespace pcl
