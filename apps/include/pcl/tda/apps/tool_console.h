#pragma once

#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/huge_page_malloc.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/exceptions.h>

#include <cstddef>
#include <cstdio>
#include <new>
#include <string>

namespace pcl {
namespace tda {

/** \brief A count for the console: "1 hole", "3 holes" (\a noun, plural but for
 * one; regular plurals only). */
inline std::string
countOf (std::size_t count, const std::string& noun)
{
  return std::to_string (count) + " " + noun + (count == 1 ? "" : "s");
}

/** \brief The console of a tool, in the style of PCL's tools: a step prints
 * "> Doing what " and, when done, "[done, 12.3 ms : result]" on the same line. The
 * step line is flushed at once, so that messages of the work (on stderr) come after
 * it, and an error first ends an unfinished step line, so that it stands on a line
 * of its own. */
class ToolConsole {
public:
  /** \brief Prints "> \a what \a value " (the value highlighted) and starts the
   * step's timer. */
  void
  beginStep (const std::string& what, const std::string& value = "")
  {
    pcl::console::print_highlight ("%s ", what.c_str());
    if (!value.empty())
      pcl::console::print_value ("%s ", value.c_str());
    std::fflush (stdout);
    line_open_ = true;
    timer_.tic();
  }

  /** \brief Ends the step's line with "[done, t ms : \a result]". */
  void
  endStep (const std::string& result)
  {
    pcl::console::print_info ("[done, ");
    pcl::console::print_value ("%g", timer_.toc());
    pcl::console::print_info (" ms : %s]\n", result.c_str());
    line_open_ = false;
  }

  /** \brief The milliseconds since the step began. */
  double
  stepMilliseconds () const
  {
    return timer_.toc();
  }

  /** \brief Ends an unfinished step line, before output of another kind. */
  void
  endLine ()
  {
    if (line_open_)
      std::fputc ('\n', stdout);
    std::fflush (stdout);
    line_open_ = false;
  }

  /** \brief Prints \a message as an error, on a line of its own. */
  void
  error (const std::string& message)
  {
    endLine();
    pcl::console::print_error ("%s\n", message.c_str());
  }

  /** \brief Loads a tool's input PCD file as a step (loadPointCloudFile()).
   * \return false, with the reason printed, when the file cannot be read */
  template <typename PointT>
  bool
  loadInput (const std::string& path, pcl::PointCloud<PointT>& cloud)
  {
    beginStep ("Loading", path);
    try {
      loadPointCloudFile (path, cloud);
    }
    catch (const pcl::PCLException& failure) {
      error ("Cannot read the PCD file: " + errorMessage (failure));
      return false;
    }
    return true;
  }

private:
  pcl::console::TicToc timer_;
  bool line_open_ = false;
};

/** \brief The main() of a tool: "-h" or "--help" prints the help only and exits
 * with 0, fewer than \a least_arguments arguments print it, say so and exit with 1;
 * else has malloc reuse the memory the tool frees (reuseFreedMemory()) and back its
 * heap with huge pages (backHeapWithHugePages()), has the signals that end it remove
 * the temporary files of its outputs (removeTemporaryFilesOnSignals()); prints
 * \a intro, reads the options
 * with \a parse and returns the exit code of \a run. A refusal (a
 * pcl::PCLException thrown by either) prints its message and exits with 1, and so
 * does running out of memory (std::bad_alloc) instead of aborting. */
template <typename Options>
int
runTool (int argc,
         char** argv,
         const std::string& intro,
         void (*print_help) (const char* program),
         void (*parse) (int argc, char** argv, Options& options),
         int (*run) (const Options& options, ToolConsole& console),
         int least_arguments = 2)
{
  if (helpRequested (argc, argv)) {
    print_help (argv[0]);
    return 0;
  }
  const auto print_intro = [&] {
    pcl::console::print_info (
        "%s For more information, use: %s -h\n", intro.c_str(), argv[0]);
  };
  if (argc < least_arguments + 1) {
    print_intro();
    print_help (argv[0]);
    pcl::console::print_error (
        "Too few arguments: %d given, at least %d needed (the help is -h).\n",
        argc - 1,
        least_arguments);
    return 1;
  }
  reuseFreedMemory();
  backHeapWithHugePages();
  removeTemporaryFilesOnSignals();
  print_intro();
  ToolConsole console;
  try {
    Options options;
    parse (argc, argv, options);
    return run (options, console);
  }
  catch (const pcl::PCLException& error) {
    console.error (errorMessage (error));
    return 1;
  }
  catch (const std::bad_alloc&) {
    console.error ("Out of memory (under a memory limit of the system, e.g. ulimit "
                   "-v?): use a smaller radius, a voxel grid, or a smaller -memory "
                   "where the tool has it.");
    return 1;
  }
}

} // namespace tda
} // namespace pcl
