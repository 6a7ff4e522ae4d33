#pragma once

#include <pcl/console/print.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/exceptions.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace pcl {
namespace tda {
namespace bench {

/** \brief Sets \a value to the one positional argument of \a arguments, if there is
 * one (\a value keeps its default otherwise).
 * \throws pcl::BadArgumentException naming \a what ("data folder", "scan") when
 * there are more */
inline void
takeOptionalArgument (const std::vector<std::string>& arguments,
                      const char* what,
                      std::string& value)
{
  if (arguments.size() > 1)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException, "Give at most one " << what << ".");
  if (!arguments.empty())
    value = arguments[0];
}

/** \brief The positive number, or with \a integer the integer from 1 to 1000, that
 * \a text spells.
 * \throws pcl::BadArgumentException naming \a what ("radius", "runs") when it is
 * not one */
inline double
positiveNumber (const std::string& text, const char* what, bool integer)
{
  const std::optional<double> value = parseWholeNumber (text);
  if (!value || !(*value > 0.0) ||
      (integer && (*value != std::floor (*value) || *value > 1000.0)))
    PCL_THROW_EXCEPTION (
        pcl::BadArgumentException,
        "The " << what << " must be "
               << (integer ? "an integer from 1 to 1000" : "a positive number")
               << ", not '" << text << "'.");
  return *value;
}

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
