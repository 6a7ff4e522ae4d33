#pragma once
// The filling of found holes and the distances it is scored by, shared by the hole
// benchmarks.

#include <pcl/search/kdtree.h>
#include <pcl/tda/features/hole_rims.h>
#include <pcl/tda/surface/hole_filling.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace pcl {
namespace tda {
namespace bench {

/** The new points of HoleFilling (surface mode, its defaults) in the \a holes of
 * \a cloud: the filled cloud without the input points; none when it fails. */
inline pcl::PointCloud<pcl::PointXYZ>::Ptr
fillHoles (const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
           const std::vector<HoleRim>& holes)
{
  HoleFilling<pcl::PointXYZ> filler;
  filler.setInputCloud (cloud);
  filler.setHoles (holes);
  pcl::PointCloud<pcl::PointXYZ> filled;
  pcl::PointCloud<pcl::PointXYZ>::Ptr new_points (new pcl::PointCloud<pcl::PointXYZ>);
  if (filler.reconstruct (filled))
    new_points->insert (
        new_points->end(), filled.begin() + cloud->size(), filled.end());
  return new_points;
}

/** Per point of \a queries, the distance to the nearest point of \a targets (not
 * empty). */
inline std::vector<double>
nearestDistances (const pcl::PointCloud<pcl::PointXYZ>& queries,
                  const pcl::PointCloud<pcl::PointXYZ>::Ptr& targets)
{
  pcl::search::KdTree<pcl::PointXYZ> tree;
  tree.setInputCloud (targets);
  std::vector<double> distances;
  pcl::Indices nearest (1);
  std::vector<float> squared (1);
  for (const auto& q : queries)
    if (tree.nearestKSearch (q, 1, nearest, squared) == 1)
      distances.push_back (std::sqrt (static_cast<double> (squared[0])));
  return distances;
}

/** \a value with two decimals for a table cell; "-" for NaN (nothing measured). */
inline std::string
tableCell (double value)
{
  if (std::isnan (value))
    return "-";
  char text[32];
  std::snprintf (text, sizeof text, "%.2f", value);
  return text;
}

} // namespace bench
} // namespace tda
} // namespace pcl
