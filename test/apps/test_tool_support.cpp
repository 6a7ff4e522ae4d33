// Tests of the tools' shared support: the strict command line, the output files
// committed together (links and permission bits kept), and the voxel grid check.

#include <pcl/tda/apps/data_set_folder.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/apps/voxel_grid_check.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>
#include <stdexcept>

using namespace pcl::tda;

namespace {

/** A fresh folder of its own for the running test. */
std::string
testFolder ()
{
  const std::string folder =
      testing::TempDir() + "tool_support_" +
      testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::remove_all (folder);
  std::filesystem::create_directories (folder);
  return folder;
}

std::string
contentOf (const std::string& path)
{
  std::ostringstream text;
  text << std::ifstream (path).rdbuf();
  return text.str();
}

/** The options of a tool like pcl_tda_barcode. */
struct Parsed {
  double radius = 0.0, leaf = 0.0;
  long dimension = 1;
  std::size_t memory = 7; // bytes; kept when -memory is not given
  std::string svg;
  bool json = false;
  std::vector<std::string> files;
};

/** Parses \a arguments; returns the error message, "" when they are valid. */
std::string
parse (const std::vector<std::string>& arguments, Parsed& parsed)
{
  ToolCommandLine command_line;
  command_line.addNumber ("-radius", parsed.radius, NumberRange::above (0.0), true);
  command_line.addNumber ("-leaf", parsed.leaf, NumberRange::atLeast (0.0));
  command_line.addInteger ("-dim", parsed.dimension, 0, 1);
  command_line.addMemory ("-memory", parsed.memory);
  command_line.addText ("-svg", parsed.svg);
  command_line.addSwitch ("-json", parsed.json);
  std::vector<const char*> argv{"tool"};
  for (const std::string& argument : arguments)
    argv.push_back (argument.c_str());
  try {
    parsed.files = command_line.parse (static_cast<int> (argv.size()), argv.data());
  }
  catch (const pcl::BadArgumentException& error) {
    return errorMessage (error);
  }
  return "";
}

} // namespace

TEST (ToolCommandLine, ParsesValuesSwitchesAndFiles)
{
  Parsed parsed;
  ASSERT_EQ (parse ({"in.pcd",
                     "-radius",
                     "1e-2",
                     "out.csv",
                     "-dim",
                     "0",
                     "-json",
                     "-leaf",
                     "0",
                     "-svg",
                     "b.svg"},
                    parsed),
             "");
  EXPECT_EQ (parsed.radius, 0.01);
  EXPECT_EQ (parsed.dimension, 0);
  EXPECT_EQ (parsed.leaf, 0.0);
  EXPECT_EQ (parsed.svg, "b.svg");
  EXPECT_TRUE (parsed.json);
  EXPECT_EQ (parsed.files, (std::vector<std::string>{"in.pcd", "out.csv"}));
  EXPECT_EQ (parsed.memory, 7u);
  ASSERT_EQ (parse ({"-radius", "1", "-memory", "1.5"}, parsed), "");
  EXPECT_EQ (parsed.memory, 1572864u); // 1.5 MiB in bytes
}

TEST (ToolCommandLine, RefusesBadArgumentsNamingThem)
{
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"-radius", "abc"}, "Option -radius needs a number > 0, not 'abc'."},
      {{"-radius", "0.1x"}, "Option -radius needs a number > 0, not '0.1x'."},
      {{"-radius", " 0.1"}, "Option -radius needs a number > 0, not ' 0.1'."},
      {{"-radius", ""}, "Option -radius needs a number > 0, not ''."},
      {{"-radius", "0"}, "Option -radius needs a number > 0, not '0'."},
      {{"-radius", "inf"}, "Option -radius needs a number > 0, not 'inf'."},
      {{"-radius", "nan"}, "Option -radius needs a number > 0, not 'nan'."},
      {{"-radius", "1e999"}, "Option -radius needs a number > 0, not '1e999'."},
      {{"-radius", "0x10"}, "Option -radius needs a number > 0, not '0x10'."},
      {{"-radius", "1", "-leaf", "-1"}, "Option -leaf needs a number >= 0, not '-1'."},
      {{"-radius", "1", "-dim", "abc"},
       "Option -dim needs an integer from 0 to 1, not 'abc'."},
      {{"-radius", "1", "-dim", "1.0"},
       "Option -dim needs an integer from 0 to 1, not '1.0'."},
      {{"-radius", "1", "-dim", "2"},
       "Option -dim needs an integer from 0 to 1, not '2'."},
      {{"-radius", "1", "-dim", "99999999999999999999"},
       "Option -dim needs an integer from 0 to 1, not '99999999999999999999'."},
      {{"-radius", "1", "-memory", "0"},
       "Option -memory needs a number > 0 and <= 1e+12, not '0'."},
      {{"-radius", "1", "-memory", "2e12"},
       "Option -memory needs a number > 0 and <= 1e+12, not '2e12'."},
      {{"-radius", "1", "-memory", "1G"},
       "Option -memory needs a number > 0 and <= 1e+12, not '1G'."},
      {{"-radius", "1", "-svg"}, "Option -svg needs a value."},
      {{"-radius", "1", "-svg", "-json"}, "Option -svg needs a value, not '-json'."},
      {{"-radius", "1", "-foo"}, "Unknown option -foo (see -h)."},
      {{"--radius", "1"}, "Unknown option --radius (see -h)."},
      {{"-radius", "1", "-radius", "2"}, "Option -radius is given twice."},
      {{"-json", "-json", "-radius", "1"}, "Option -json is given twice."},
      {{"in.pcd", "out.csv"}, "Option -radius is required."},
  };
  for (const auto& [arguments, message] : cases) {
    Parsed parsed;
    EXPECT_EQ (parse (arguments, parsed), message)
        << ::testing::PrintToString (arguments);
  }
}

TEST (ToolCommandLine, HelpAndPositionalArguments)
{
  const char* help[] = {"tool", "a.pcd", "-radius", "1", "--help"};
  EXPECT_TRUE (helpRequested (5, help));
  const char* no_help[] = {"tool", "a.pcd", "-hh"};
  EXPECT_FALSE (helpRequested (3, no_help));
  const std::vector<ToolArgument> expected{{"kind", ""}, {"output", ".pcd"}};
  EXPECT_NO_THROW (checkArguments ({"circle", "dir.x/c.pcd"}, expected));
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"circle"}, "Need the kind and the output .pcd file, not 1 argument."},
      {{"circle", "c.pcd", "d.pcd"},
       "Need the kind and the output .pcd file, not 3 arguments."},
      {{"circle", "c.csv"}, "The output c.csv must be a .pcd file."},
      {{"circle", ".pcd"}, "The output .pcd must be a .pcd file."},
      {{"circle", "c.pcd.txt"}, "The output c.pcd.txt must be a .pcd file."},
      {{"circle", "cpcd"}, "The output cpcd must be a .pcd file."},
  };
  for (const auto& [arguments, message] : cases) {
    try {
      checkArguments (arguments, expected);
      ADD_FAILURE() << message;
    }
    catch (const pcl::BadArgumentException& error) {
      EXPECT_EQ (errorMessage (error), message);
    }
  }
}

// A message for people: PCL's exceptions without their function, file and line;
// std::bad_alloc as what ran out (pcl_tda_stpp printed "std::bad_alloc").
TEST (ErrorMessage, SaysWhatWentWrong)
{
  try {
    PCL_THROW_EXCEPTION (pcl::IOException, "cannot write o.csv: File too large");
  }
  catch (const pcl::IOException& error) {
    EXPECT_EQ (errorMessage (error), "cannot write o.csv: File too large");
  }
  EXPECT_EQ (errorMessage (std::bad_alloc()),
             "out of memory (under a memory limit of the system, e.g. ulimit -v?)");
  EXPECT_EQ (errorMessage (std::runtime_error ("plain")), "plain");
}

TEST (ToolOutputs, RefusesUnwritableOrCollidingOutputsNamingThem)
{
  const std::string folder = testFolder();
  const std::string input = folder + "/in.pcd", link = folder + "/link.csv";
  std::ofstream (input) << "input";
  std::filesystem::create_directory (folder + "/taken.csv");
  std::filesystem::create_symlink (input, link);
  const std::vector<std::pair<std::vector<ToolOutputs::Output>, std::string>> cases{
      {{{"output", folder + "/missing/out.csv"}},
       "cannot write " + folder + "/missing/out.csv: the folder " + folder +
           "/missing does not exist"},
      {{{"output", folder + "/taken.csv"}},
       "cannot write " + folder + "/taken.csv: it is a directory"},
      {{{"output", "/dev/null"}}, "cannot write /dev/null: it is not a regular file"},
      {{{"output", input}}, "refusing to overwrite the input file " + input},
      {{{"output", folder + "/ok.csv"}, {"-svg", link}},
       "refusing to overwrite the input file " + input + " (-svg)"},
      {{{"output", folder + "/ok.csv"},
        {"-svg",
         folder + "/../" + std::filesystem::path (folder).filename().string() +
             "/./ok.csv"}},
       "output and -svg name the same file"},
  };
  for (const auto& [outputs, message] : cases) {
    try {
      ToolOutputs checked (input, outputs);
      ADD_FAILURE() << message;
    }
    catch (const pcl::IOException& error) {
      EXPECT_NE (errorMessage (error).find (message), std::string::npos)
          << errorMessage (error);
    }
  }
  EXPECT_EQ (contentOf (input), "input");
  EXPECT_EQ (std::distance (std::filesystem::directory_iterator (folder),
                            std::filesystem::directory_iterator()),
             3); // in.pcd, link.csv, taken.csv: nothing created
}

TEST (ToolOutputs, CommitsTogetherKeepingLinksAndPermissions)
{
  const std::string folder = testFolder();
  const std::string csv = folder + "/out.csv", svg = folder + "/out.svg";
  const std::string target = folder + "/target.svg";
  std::ofstream (csv) << "old csv";
  ::chmod (csv.c_str(), 0640);
  std::ofstream (target) << "old svg";
  std::filesystem::create_symlink ("target.svg", svg);
  {
    // Not committed: nothing changes and no temporary file stays.
    ToolOutputs outputs ("", {{"output", csv}, {"-svg", svg}, {"-diagram", ""}});
    std::ofstream (outputs.temporary (csv)) << "new csv";
  }
  EXPECT_EQ (contentOf (csv), "old csv");
  EXPECT_EQ (contentOf (target), "old svg");
  EXPECT_EQ (std::distance (std::filesystem::directory_iterator (folder),
                            std::filesystem::directory_iterator()),
             3);

  ToolOutputs outputs ("", {{"output", csv}, {"-svg", svg}});
  std::ofstream (outputs.temporary (csv)) << "new csv";
  std::ofstream (outputs.temporary (svg)) << "new svg";
  EXPECT_EQ (contentOf (csv), "old csv"); // until the commit
  outputs.commit();
  EXPECT_EQ (contentOf (csv), "new csv");
  EXPECT_EQ (contentOf (target), "new svg");
  EXPECT_TRUE (std::filesystem::is_symlink (svg));
  struct stat status;
  ASSERT_EQ (::stat (csv.c_str(), &status), 0);
  EXPECT_EQ (status.st_mode & 07777, 0640u);
  EXPECT_EQ (std::distance (std::filesystem::directory_iterator (folder),
                            std::filesystem::directory_iterator()),
             3);
}

// A tool ended by a signal while it writes its outputs (removeTemporaryFilesOnSignals()
// as runTool() calls it) leaves no temporary file, and ends by that signal.
TEST (ToolOutputs, SignalsRemoveTheTemporaryFiles)
{
  const std::string folder = testFolder();
  std::ofstream (folder + "/out.csv") << "old csv";
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    const pid_t child = ::fork();
    ASSERT_GE (child, 0);
    if (child == 0) {
      std::signal (signal, SIG_DFL); // as in a terminal (a test runner may ignore it)
      removeTemporaryFilesOnSignals();
      ToolOutputs outputs (
          "", {{"output", folder + "/out.csv"}, {"-svg", folder + "/new.svg"}});
      std::ofstream (outputs.temporary (folder + "/out.csv")) << "new csv";
      // A writer's own temporary file beside the tool's, as the library's writers.
      FileReplacement nested (outputs.temporary (folder + "/new.svg"));
      std::ofstream (nested.temporary()) << "partial svg";
      std::raise (signal);
      ::_exit (0); // not reached
    }
    int status = 0;
    ASSERT_EQ (::waitpid (child, &status, 0), child);
    ASSERT_TRUE (WIFSIGNALED (status)) << signal;
    EXPECT_EQ (WTERMSIG (status), signal);
    std::vector<std::string> left;
    for (const auto& entry : std::filesystem::directory_iterator (folder))
      left.push_back (entry.path().filename().string());
    EXPECT_EQ (left, std::vector<std::string>{"out.csv"}) << signal;
    EXPECT_EQ (contentOf (folder + "/out.csv"), "old csv");
  }
}

// The staging folder of a data set written by a run killed by a signal is removed
// by the next run into the folder; that of a live process stays.
TEST (DataSetFolder, NextRunRemovesTheStagingOfAKilledRun)
{
  const std::string folder = testFolder();
  const pid_t ended = ::fork();
  ASSERT_GE (ended, 0);
  if (ended == 0)
    ::_exit (0);
  ASSERT_EQ (::waitpid (ended, nullptr, 0), ended);
  const std::string stale = folder + "/.staging." + std::to_string (ended);
  const std::string live = folder + "/.staging." + std::to_string (::getppid());
  std::filesystem::create_directories (stale);
  std::ofstream (stale + "/view_1.pcd") << "partial";
  std::filesystem::create_directories (live);
  {
    DataSetFolder data_set (folder, {"a.txt"}, "manifest.csv");
    EXPECT_FALSE (std::filesystem::exists (stale));
    EXPECT_TRUE (std::filesystem::exists (live));
  }
  EXPECT_FALSE (std::filesystem::exists (stale));
}

TEST (VoxelGridCheck, RefusesLeavesPCLWouldIgnore)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back ({0.0f, 0.0f, 0.0f});
  cloud.push_back ({1.0f, 1.0f, 1.0f});
  cloud.push_back ({NAN, NAN, NAN});
  EXPECT_NO_THROW (checkVoxelGridLeaf (cloud, 0.001)); // 1001^3 cells
  EXPECT_THROW (checkVoxelGridLeaf (cloud, 0.0007), pcl::BadArgumentException);
  EXPECT_THROW (checkVoxelGridLeaf (cloud, 1e-9), pcl::BadArgumentException);
  EXPECT_THROW (checkVoxelGridLeaf (cloud, 1e-50), pcl::BadArgumentException);
  try {
    checkVoxelGridLeaf (cloud, 1e-4);
    ADD_FAILURE() << "leaf 1e-4 accepted";
  }
  catch (const pcl::BadArgumentException& error) {
    EXPECT_NE (errorMessage (error).find ("-leaf 0.0001 is too small for the points' "
                                          "extent 1 x 1 x 1"),
               std::string::npos)
        << errorMessage (error);
  }
  pcl::PointCloud<pcl::PointXYZ> one_point;
  one_point.push_back ({5.0f, 5.0f, 5.0f});
  EXPECT_NO_THROW (checkVoxelGridLeaf (one_point, 1e-9));
}
