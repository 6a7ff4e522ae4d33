#pragma once

// The check the feature classes' initCompute() make of a length setting that 0
// makes automatic (a radius, a band width).

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

} // namespace tda
} // namespace pcl
