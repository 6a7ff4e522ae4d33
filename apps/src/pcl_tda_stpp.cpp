/** pcl_tda_stpp: the topological descriptor (STPP, its Betti-0 or Betti-1 part, or
 * the topological covariance descriptor) of each of many PCD files, one CSV row per
 * file, for a classifier or a spreadsheet. */

#include <pcl/console/print.h>
#include <pcl/tda/apps/csv_fields.h>
#include <pcl/tda/apps/tool_console.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/apps/view_files.h>
#include <pcl/tda/common/atomic_file.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/resource_settings.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/exceptions.h>

#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using namespace pcl::console;

namespace {

/** The descriptors this tool writes. */
const std::vector<std::string> DESCRIPTORS{"stpp", "stpp0", "stpp1", "covariance"};

void
printHelp (const char* program)
{
  print_info ("Syntax is: %s out.csv in1.pcd [in2.pcd ...] <options>\n", program);
  print_info ("  Writes one row per input: its path as given, then the values of its "
              "descriptor\n  (header path,f0,f1,...). A file that cannot be read or "
              "described is reported\n  and left out, and the tool then exits with "
              "1; the CSV holds the others.\n");
  print_info ("  where options are:\n");
  print_info ("    -list F.txt    = also the files listed in F.txt, one path per "
              "line (relative to\n                     the folder of F.txt; # starts "
              "a comment line)\n");
  print_info ("    -descriptor D  = stpp (default: Betti 0 and 1), stpp0 (Betti 0), "
              "stpp1 (Betti 1)\n                     or covariance (the topological "
              "covariance descriptor; normals\n                     estimated)\n");
  print_info ("    -radius R      = radius of STPP's level 0 or of the covariance's "
              "filtration (default:\n                     chosen from each cloud's "
              "spacing)\n");
  print_info ("    -memory M      = refuse complexes over M MiB, shared by the files "
              "described at\n                     once (default: half of the "
              "memory)\n");
  print_info ("    -threads N     = threads (default: all)\n");
}

struct Options {
  std::string output, list, descriptor = "stpp";
  std::vector<std::string> inputs;
  double radius = 0.0;
  std::size_t memory_limit = pcl::tda::defaultMemoryLimit();
  long threads = 0;
};

/** The paths of the list file \a list, one per line, without the spaces around
 * them; relative paths are relative to the list's folder (as those of
 * pcl_tda_classify's manifest). Blank lines and lines that start with # are
 * skipped.
 * \throws pcl::IOException when it cannot be read */
std::vector<std::string>
readList (const std::string& list)
{
  std::ifstream in (list);
  if (!in)
    PCL_THROW_EXCEPTION (pcl::IOException, "cannot read the list " << list);
  pcl::tda::skipByteOrderMark (in);
  const std::filesystem::path folder = std::filesystem::path (list).parent_path();
  constexpr const char* SPACES = " \t\r";
  std::vector<std::string> paths;
  for (std::string line; std::getline (in, line);) {
    const auto first = line.find_first_not_of (SPACES);
    if (first == std::string::npos || line[first] == '#')
      continue;
    const std::filesystem::path path =
        line.substr (first, line.find_last_not_of (SPACES) + 1 - first);
    paths.push_back ((path.is_absolute() ? path : folder / path).string());
  }
  return paths;
}

void
parseOptions (int argc, char** argv, Options& options)
{
  pcl::tda::ToolCommandLine command_line;
  command_line.addText ("-list", options.list);
  command_line.addText ("-descriptor", options.descriptor);
  command_line.addNumber (
      "-radius", options.radius, pcl::tda::NumberRange::above (0.0));
  command_line.addMemory ("-memory", options.memory_limit);
  command_line.addInteger ("-threads", options.threads, 1, pcl::tda::MAX_THREADS);
  const std::vector<std::string> arguments = command_line.parse (argc, argv);
  if (arguments.empty())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException, "Missing the output CSV file.");
  std::vector<pcl::tda::ToolArgument> expected{{"output", ".csv"}};
  for (std::size_t i = 1; i < arguments.size(); ++i)
    expected.push_back ({"input", ".pcd"});
  pcl::tda::checkArguments (arguments, expected);
  options.output = arguments[0];
  options.inputs.assign (arguments.begin() + 1, arguments.end());
  if (std::find (DESCRIPTORS.begin(), DESCRIPTORS.end(), options.descriptor) ==
      DESCRIPTORS.end())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-descriptor must be stpp, stpp0, stpp1 or covariance (got '"
                             << options.descriptor << "').");
  if (!options.list.empty())
    for (const std::string& path : readList (options.list))
      options.inputs.push_back (path);
  if (options.inputs.empty())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "No input: give PCD files or -list with at least one.");
}

int
run (const Options& options, pcl::tda::ToolConsole& console)
{
  std::vector<std::string> never_written = options.inputs;
  if (!options.list.empty())
    never_written.push_back (options.list);
  pcl::tda::ToolOutputs outputs (never_written, {{"output", options.output}});
  if (options.threads > 0)
    omp_set_num_threads (static_cast<int> (options.threads));

  console.beginStep ("Describing",
                     std::to_string (options.inputs.size()) + " files by " +
                         options.descriptor + ", " +
                         std::to_string (omp_get_max_threads()) + " threads");
  pcl::tda::TopologicalSettings topological;
  topological.radius = options.radius;
  topological.memory_limit = options.memory_limit;
  const std::vector<pcl::tda::DescribedFile> described = pcl::tda::describeViewFiles (
      options.inputs, options.inputs, {options.descriptor}, topological, "  files");
  std::size_t failed = 0, size = 0;
  for (std::size_t i = 0; i < described.size(); ++i) {
    const std::string& error = described[i].error.empty()
                                   ? described[i].descriptors.front().failure
                                   : described[i].error;
    if (!error.empty()) {
      ++failed;
      console.error ("Skipping " + options.inputs[i] + ": " + error);
    }
    else
      size = described[i].descriptors.front().values.size();
  }
  console.endStep (std::to_string (described.size() - failed) + " described, " +
                   std::to_string (failed) + " failed");
  if (failed == described.size()) {
    console.error ("No file could be described: nothing written.");
    return 1;
  }

  console.beginStep ("Saving", options.output);
  try {
    pcl::tda::writeFileAtomically (
        outputs.temporary (options.output), [&] (std::ostream& out) {
          out << "path";
          for (std::size_t k = 0; k < size; ++k)
            out << ",f" << k;
          out << '\n';
          for (std::size_t i = 0; i < described.size(); ++i) {
            if (!described[i].error.empty() ||
                !described[i].descriptors.front().failure.empty())
              continue;
            out << pcl::tda::csvField (options.inputs[i]);
            for (const float value : described[i].descriptors.front().values)
              out << ',' << pcl::tda::formatNumber (value);
            out << '\n';
          }
        });
    outputs.commit();
  }
  catch (const std::exception& error) {
    console.error (outputs.message (error));
    return 1;
  }
  console.endStep (std::to_string (described.size() - failed) + " rows of " +
                   std::to_string (size) + " values");
  return failed > 0 ? 1 : 0;
}

} // namespace

int
main (int argc, char** argv)
{
  return pcl::tda::runTool<Options> (argc,
                                     argv,
                                     "Topological descriptors of point clouds.",
                                     printHelp,
                                     parseOptions,
                                     run,
                                     1);
}
