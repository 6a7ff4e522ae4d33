#pragma once

// The checks the feature classes' initCompute() make: of a length setting that 0
// makes automatic (a radius, a band width), and of pcl::Feature's search settings,
// which they do not use.

#include <pcl/console/print.h>

#include <cmath>
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

/** \brief The input check both feature classes' initCompute() start with: false,
 * after a PCL_ERROR naming the class \a class_name, when there is no input
 * (\a has_input: what pcl::PCLBase::initCompute() returned); else true, after a
 * PCL_WARN when pcl::Feature's search settings were given: \a search_radius
 * (setRadiusSearch()), \a k (setKSearch()) or a search tree (setSearchMethod()).
 * The classes build their own complex, of the radius set by their setRadius(), and a
 * PCL user who set these as for pcl::BoundaryEstimation would otherwise not know
 * they were ignored. */
inline bool
checkFeatureInput (bool has_input,
                   const std::string& class_name,
                   double search_radius,
                   int k,
                   bool has_search_tree)
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
  return true;
}

} // namespace tda
} // namespace pcl
