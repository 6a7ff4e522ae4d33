#pragma once

#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/common/atomic_file.h>
#include <pcl/tda/common/error_message.h>

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

/** \brief Loads a tool's input PCD file, saying so on the console.
 * \return false, with the reason printed, when the file cannot be read */
template <typename PointT>
bool
loadToolInput (const std::string& path, pcl::PointCloud<PointT>& cloud)
{
  pcl::console::print_highlight ("Loading ");
  pcl::console::print_value ("%s ", path.c_str());
  try {
    loadPointCloudFile (path, cloud);
  }
  catch (const pcl::PCLException& error) {
    pcl::console::print_error ("\nCannot read the PCD file: %s\n",
                               errorMessage (error).c_str());
    return false;
  }
  return true;
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
