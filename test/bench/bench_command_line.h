#pragma once

#include <pcl/console/print.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/exceptions.h>

#include <cstdio>
#include <optional>

namespace pcl {
namespace tda {
namespace bench {

/** \brief The command line of a benchmark program: with -h, prints the usage to
 * stdout; otherwise parses it into \a options with \a parse (parse(argc, argv,
 * options), which throws a pcl::PCLException on a bad option: the message and the
 * usage go to stderr) and quiets PCL's console.
 * \return the exit code when the program should stop (0 after -h, 1 on a bad
 * option), nothing when it should run */
template <typename Options, typename Parse, typename PrintUsage>
std::optional<int>
parseCommandLine (
    int argc, char** argv, Options& options, Parse parse, PrintUsage print_usage)
{
  if (helpRequested (argc, argv)) {
    print_usage (stdout);
    return 0;
  }
  try {
    parse (argc, argv, options);
  }
  catch (const pcl::PCLException& error) {
    std::fprintf (stderr, "%s\n", errorMessage (error).c_str());
    print_usage (stderr);
    return 1;
  }
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);
  return std::nullopt;
}

} // namespace bench
} // namespace tda
} // namespace pcl
