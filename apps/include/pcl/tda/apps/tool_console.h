#pragma once

#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/tda/common/atomic_file.h>

#include <initializer_list>
#include <string>

namespace pcl {
namespace tda {

/** \brief Prints the timing line of PCL's tools: "[done, 12.3 ms : what]". */
inline void
printDone (const pcl::console::TicToc& timer, const std::string& what)
{
  pcl::console::print_info ("[done, ");
  pcl::console::print_value ("%g", timer.toc());
  pcl::console::print_info (" ms : %s]\n", what.c_str());
}

/** \brief True, with an error printed, when one of \a outputs (empty ones are
 * skipped) names the file \a input, directly or through a link: tools never
 * overwrite their input. */
inline bool
overwritesInput (const std::string& input, std::initializer_list<std::string> outputs)
{
  for (const std::string& output : outputs)
    if (!output.empty() && (output == input || isSameFile (output, input))) {
      pcl::console::print_error ("Refusing to overwrite the input file %s.\n",
                                 input.c_str());
      return true;
    }
  return false;
}

} // namespace tda
} // namespace pcl
