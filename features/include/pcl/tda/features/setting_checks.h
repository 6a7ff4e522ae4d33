#pragma once

// The checks the feature classes' initCompute() make: of a length setting that 0
// makes automatic (a radius, a band width), and of pcl::Feature's search settings,
// which they do not use.

#include <pcl/console/print.h>
#include <pcl/tda/search/point_spacing.h>

#include <cmath>
#include <cstddef>
#include <string>

namespace pcl {
namespace tda {

/** \brief True when \a value is a valid length setting: positive and finite, or 0
 * (which means \a zero_means, e.g. "to choose it"); else prints a PCL_ERROR naming
 * the class \a class_name and the setting \a what, and returns false. */
inline bool
checkOptionalLength (double value,
                     const std::string& class_name,
                     const char* what,
                     const char* zero_means)
{
  if (value >= 0.0 && std::isfinite (value))
    return true;
  PCL_ERROR ("[pcl::tda::%s::compute] The %s must be positive and finite, or 0 %s "
             "(got %g).\n",
             class_name.c_str(),
             what,
             zero_means,
             value);
  return false;
}

/** \brief True when \a max_points (setMaxPoints(); 0: all points) leaves a sample
 * whose spacing can be measured, as the radius needs when it is chosen (\a radius
 * 0): at least SURFACE_SPACING_NEIGHBORS + 1 points; else prints a PCL_ERROR naming
 * the class \a class_name and returns false. */
inline bool
checkMaxPoints (std::size_t max_points, double radius, const std::string& class_name)
{
  if (max_points == 0 || max_points > SURFACE_SPACING_NEIGHBORS || radius > 0.0)
    return true;
  PCL_ERROR ("[pcl::tda::%s::compute] The max points (%zu) must be 0 (all) or at "
             "least %zu when the radius is chosen from their spacing (each point's "
             "distance to its %zuth nearest); or set the radius.\n",
             class_name.c_str(),
             max_points,
             SURFACE_SPACING_NEIGHBORS + 1,
             SURFACE_SPACING_NEIGHBORS);
  return false;
}

/** \brief The input check both feature classes' initCompute() start with: false,
 * after a PCL_ERROR naming the class \a class_name, when there is no input
 * (\a has_input: what pcl::PCLBase::initCompute() returned); else true, after a
 * PCL_WARN when pcl::Feature's search settings were given: \a search_radius
 * (setRadiusSearch()), \a k (setKSearch()) or a search tree (setSearchMethod()),
 * and another when a search surface other than the input was (setSearchSurface(),
 * \a has_other_surface). The classes build their own complex of the indexed input
 * points, of the radius set by their setRadius(), and a PCL user who set these as
 * for pcl::BoundaryEstimation would otherwise not know they were ignored. */
inline bool
checkFeatureInput (bool has_input,
                   const std::string& class_name,
                   double search_radius,
                   int k,
                   bool has_search_tree,
                   bool has_other_surface)
{
  if (!has_input) {
    PCL_ERROR ("[pcl::tda::%s::compute] No input cloud: call setInputCloud().\n",
               class_name.c_str());
    return false;
  }
  if (search_radius != 0.0 || k != 0 || has_search_tree)
    PCL_WARN ("[pcl::tda::%s::compute] setRadiusSearch(), setKSearch() and "
              "setSearchMethod() are not used: the complex's radius is setRadius() "
              "(0: chosen from the point spacing).\n",
              class_name.c_str());
  if (has_other_surface)
    PCL_WARN ("[pcl::tda::%s::compute] setSearchSurface() is not used: the complex "
              "is that of the indexed input points.\n",
              class_name.c_str());
  return true;
}

} // namespace tda
} // namespace pcl
