#include <pcl/tda/common/diagram_io.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

using pcl::tda::PersistenceDiagram;
using pcl::tda::PersistenceInterval;

constexpr double INF = std::numeric_limits<double>::infinity();

std::uint64_t
bits (double value)
{
  std::uint64_t result;
  std::memcpy (&result, &value, sizeof (result));
  return result;
}

PersistenceDiagram
sortedByValue (PersistenceDiagram diagram)
{
  std::sort (diagram.begin(),
             diagram.end(),
             [] (const PersistenceInterval& a, const PersistenceInterval& b) {
               return std::tie (a.dimension, a.birth, a.death) <
                      std::tie (b.dimension, b.birth, b.death);
             });
  return diagram;
}

PersistenceDiagram
roundTrip (const PersistenceDiagram& diagram)
{
  std::stringstream stream;
  pcl::tda::writeDiagramCSV (stream, diagram);
  return pcl::tda::readDiagram (stream);
}

/** Expects \a read to hold the intervals of \a written in sorted order, bit for bit. */
void
expectBitwiseEqual (const PersistenceDiagram& written, const PersistenceDiagram& read)
{
  const PersistenceDiagram expected = sortedByValue (written);
  ASSERT_EQ (expected.size(), read.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ (expected[i].dimension, read[i].dimension) << "interval " << i;
    EXPECT_EQ (bits (expected[i].birth), bits (read[i].birth))
        << "interval " << i << ": " << expected[i].birth << " read as "
        << read[i].birth;
    EXPECT_EQ (bits (expected[i].death), bits (read[i].death))
        << "interval " << i << ": " << expected[i].death << " read as "
        << read[i].death;
  }
}

std::string
readErrorOf (const std::string& text)
{
  std::istringstream stream (text);
  try {
    pcl::tda::readDiagram (stream);
  }
  catch (const pcl::IOException& e) {
    return e.what();
  }
  return "no exception";
}

/** A fresh empty folder, removed with its content at the end of the test. */
class TemporaryFolder {
public:
  TemporaryFolder()
  : path_ (std::filesystem::path (::testing::TempDir()) /
           ("pcl_tda_test_diagram_io_" + std::to_string (::getpid())))
  {
    std::filesystem::remove_all (path_);
    std::filesystem::create_directory (path_);
  }

  ~TemporaryFolder() { std::filesystem::remove_all (path_); }

  const std::filesystem::path&
  path () const
  {
    return path_;
  }

  std::size_t
  numFiles () const
  {
    const std::filesystem::directory_iterator files (path_);
    return std::distance (begin (files), end (files));
  }

private:
  std::filesystem::path path_;
};

TEST (DiagramIO, WritesSortedCSVWithShortestExactValues)
{
  const PersistenceDiagram diagram = {
      {1, 0.25, 1.0}, {0, 0.0, INF}, {0, 0.0, 0.5}, {1, 0.1, 0.30000000000000004}};
  std::ostringstream out;
  pcl::tda::writeDiagramCSV (out, diagram);
  EXPECT_EQ ("dim,birth,death\n"
             "0,0,0.5\n"
             "0,0,inf\n"
             "1,0.1,0.30000000000000004\n"
             "1,0.25,1\n",
             out.str());
}

TEST (DiagramIO, WritesHeaderOnlyForEmptyDiagram)
{
  std::ostringstream out;
  pcl::tda::writeDiagramCSV (out, {});
  EXPECT_EQ ("dim,birth,death\n", out.str());
  EXPECT_TRUE (roundTrip ({}).empty());
}

TEST (DiagramIO, RoundTripKeepsExtremeValuesBitwise)
{
  const double max = std::numeric_limits<double>::max();
  const double denorm = std::numeric_limits<double>::denorm_min();
  const double tiny = std::numeric_limits<double>::min();
  const PersistenceDiagram diagram = {{0, -0.0, 1.0 / 3.0},
                                      {0, 0.0, INF},
                                      {1, denorm, tiny},
                                      {1, std::nextafter (1.0, 2.0), max},
                                      {2, -max, -1e-300},
                                      {2, 0.1, 0.1},
                                      {7, 123456789.123456789, INF}};
  expectBitwiseEqual (diagram, roundTrip (diagram));
}

TEST (DiagramIO, RoundTripOfRandomDiagramsIsExact)
{
  std::mt19937 generator (20240917);
  std::uniform_int_distribution<int> size_distribution (0, 60);
  std::uniform_int_distribution<int> dimension_distribution (0, 3);
  std::uniform_int_distribution<std::uint64_t> bit_distribution;
  std::uniform_real_distribution<double> unit (0.0, 1.0);
  // A finite double drawn from all bit patterns, or a value in [0, 10).
  const auto randomValue = [&] () {
    if (unit (generator) < 0.5)
      return 10.0 * unit (generator);
    for (;;) {
      const std::uint64_t pattern = bit_distribution (generator);
      double value;
      std::memcpy (&value, &pattern, sizeof (value));
      if (std::isfinite (value))
        return value;
    }
  };
  for (int trial = 0; trial < 500; ++trial) {
    PersistenceDiagram diagram (size_distribution (generator));
    for (auto& interval : diagram) {
      const double a = randomValue(), b = randomValue();
      interval.dimension = dimension_distribution (generator);
      interval.birth = std::min (a, b);
      interval.death = unit (generator) < 0.1 ? INF : std::max (a, b);
    }
    if (trial % 2 == 1) { // a sorted first part, as the engines give H0
      PersistenceDiagram first (diagram.begin(), diagram.begin() + diagram.size() / 2);
      first = sortedByValue (first);
      std::copy (first.begin(), first.end(), diagram.begin());
    }
    SCOPED_TRACE ("trial " + std::to_string (trial));
    expectBitwiseEqual (diagram, roundTrip (diagram));
    if (HasFailure())
      return;
  }
}

TEST (DiagramIO, ReadsRipserOutput)
{
  std::istringstream ripser ("point cloud with 5 points in dimension 2\n"
                             "value range: [1,7.07107]\n"
                             "distance matrix with 5 points, using threshold at "
                             "enclosing radius 5.65685\n"
                             "persistence intervals in dim 0:\n"
                             " [0,0.0123)\n"
                             " [0,1)\n"
                             " [0,5.65685)\n"
                             " [0, )\n"
                             "persistence intervals in dim 1:\n"
                             " [1,1.41421)\n"
                             " [0.1,0.1)\n"
                             " [2.5e-05,inf)\n"
                             "persistence intervals in dim 2:\n");
  const PersistenceDiagram diagram = pcl::tda::readDiagram (ripser);
  const PersistenceDiagram expected = {{0, 0.0, 0.0123},
                                       {0, 0.0, 1.0},
                                       {0, 0.0, 5.65685},
                                       {0, 0.0, INF},
                                       {1, 1.0, 1.41421},
                                       {1, 0.1, 0.1},
                                       {1, 2.5e-05, INF}};
  ASSERT_EQ (expected.size(), diagram.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ (expected[i].dimension, diagram[i].dimension) << "interval " << i;
    EXPECT_EQ (expected[i].birth, diagram[i].birth) << "interval " << i;
    EXPECT_EQ (expected[i].death, diagram[i].death) << "interval " << i;
  }
}

TEST (DiagramIO, ReadsOutputOfInstalledRipser)
{
  if (std::string (RIPSER_EXECUTABLE).empty())
    GTEST_SKIP() << "ripser is not installed";
  const TemporaryFolder folder;
  const std::string points = (folder.path() / "points.txt").string();
  const std::string output = (folder.path() / "ripser.txt").string();
  {
    std::ofstream out (points);
    out << "0 0\n1 0\n0 1\n1 1\n5 5\n";
  }
  const std::string command = std::string (RIPSER_EXECUTABLE) +
                              " --format point-cloud --dim 1 " + points + " > " +
                              output;
  ASSERT_EQ (0, std::system (command.c_str()));
  const PersistenceDiagram diagram = pcl::tda::loadDiagram (output);
  const PersistenceDiagram expected = {{0, 0.0, 1.0},
                                       {0, 0.0, 1.0},
                                       {0, 0.0, 1.0},
                                       {0, 0.0, 5.65685},
                                       {0, 0.0, INF},
                                       {1, 1.0, 1.41421}};
  expectBitwiseEqual (expected, diagram);
}

TEST (DiagramIO, ReadsRipserOutputStartingAtIntervals)
{
  std::istringstream ripser ("persistence intervals in dim 1:\n [0.5,0.75)\n");
  const PersistenceDiagram diagram = pcl::tda::readDiagram (ripser);
  ASSERT_EQ (1u, diagram.size());
  EXPECT_EQ (1, diagram[0].dimension);
  EXPECT_EQ (0.5, diagram[0].birth);
  EXPECT_EQ (0.75, diagram[0].death);
}

TEST (DiagramIO, AcceptsInfinitySpellingsBlankLinesAndCRLF)
{
  std::istringstream csv ("\r\ndim,birth,death\r\n0,0,inf\r\n\r\n0,0,Inf\n0,0,INF\n"
                          "1,0.5,infinity\n1 , 0.5 , Infinity \n");
  const PersistenceDiagram diagram = pcl::tda::readDiagram (csv);
  ASSERT_EQ (5u, diagram.size());
  for (const auto& interval : diagram) {
    EXPECT_TRUE (interval.isEssential());
    EXPECT_EQ (interval.dimension == 0 ? 0.0 : 0.5, interval.birth);
  }
}

TEST (DiagramIO, MalformedInputThrowsNamingLineAndText)
{
  struct Case {
    std::string input;
    std::string expected_location;
    std::string expected_text;
  };
  const std::vector<Case> cases = {
      {"", "line 1 (end of input)", "empty input"},
      {"\n  \n", "line 3 (end of input)", "empty input"},
      {"0,0,1\n", "line 1:", "\"0,0,1\""},
      {"dim;birth;death\n0;0;1\n", "line 1:", "\"dim;birth;death\""},
      {"dim,birth,death\n0,0,1\n0,abc,1\n", "line 3:", "bad birth \"abc\""},
      {"dim,birth,death\n0,0,1x\n", "line 2:", "bad death \"1x\""},
      {"dim,birth,death\n0,0,\n", "line 2:", "bad death \"\""},
      {"dim,birth,death\n\n0,0,0x10\n", "line 3:", "\"0,0,0x10\""},
      {"dim,birth,death\n0,0,1e400\n", "line 2:", "\"1e400\""},
      {"dim,birth,death\n0,0\n", "line 2:", "expected 3 columns, found 2"},
      {"dim,birth,death\n0,0,1,2\n", "line 2:", "expected 3 columns, found 4"},
      {"dim,birth,death\n0,0,1,\n", "line 2:", "expected 3 columns, found 4"},
      {"dim,birth,death\n1,2,1\n", "line 2:", "death smaller than birth in \"1,2,1\""},
      {"dim,birth,death\n0,0,-inf\n", "line 2:", "death smaller than birth"},
      {"dim,birth,death\n0,0,1\n-1,0,1\n", "line 3:", "negative dimension"},
      {"dim,birth,death\n1.5,0,1\n", "line 2:", "bad dimension \"1.5\""},
      {"dim,birth,death\nx,0,1\n", "line 2:", "bad dimension \"x\""},
      {"dim,birth,death\n0,0,nan\n", "line 2:", "death is NaN in \"0,0,nan\""},
      {"dim,birth,death\n0,NaN,1\n", "line 2:", "birth is NaN"},
      {"dim,birth,death\n0,inf,inf\n", "line 2:", "infinite birth"},
      {"value range: [0,1]\n [0,1)\n", "line 2:", "interval before any"},
      {"persistence intervals in dim 0:\n [0,1)\n [0,abc)\n",
       "line 3:",
       "bad death \"abc\" in \" [0,abc)\""},
      {"persistence intervals in dim 0:\n [0.5,0.2)\n", "line 2:", "death smaller"},
      {"persistence intervals in dim 0:\n [0,1\n", "line 2:", "expected an interval"},
      {"persistence intervals in dim 0:\n [0,1,2)\n",
       "line 2:",
       "expected an interval"},
      {"persistence intervals in dim 0:\n [,1)\n", "line 2:", "bad birth \"\""},
      {"persistence intervals in dim 0:\n [0,nan)\n", "line 2:", "death is NaN"},
      {"persistence intervals in dim 0:\n [0,1)\nhello\n",
       "line 3:",
       "expected an interval \"[birth,death)\" in \"hello\""},
      {"persistence intervals in dim -1:\n", "line 1:", "negative dimension"},
      {"persistence intervals in dim x:\n", "line 1:", "bad dimension \"x\""},
      {"persistence intervals in dim 1\n", "line 1:", "expected \"persistence"},
      {"point cloud with 3 points in dimension 2\nvalue range: [1,2]\n",
       "line 3 (end of input)",
       "no \"persistence intervals in dim <k>:\" line"},
  };
  for (const auto& test : cases) {
    const std::string message = readErrorOf (test.input);
    EXPECT_NE (std::string::npos, message.find (test.expected_location))
        << "input \"" << test.input << "\" gave: " << message;
    EXPECT_NE (std::string::npos, message.find (test.expected_text))
        << "input \"" << test.input << "\" gave: " << message;
  }
}

TEST (DiagramIO, LongOffendingLineIsShortenedInMessage)
{
  const std::string message =
      readErrorOf ("dim,birth,death\n0,0," + std::string (1000, '7') + "x\n");
  EXPECT_NE (std::string::npos, message.find ("line 2: bad death"));
  EXPECT_LT (message.size(), 1500u);
}

TEST (DiagramIO, WriteRefusesDiagramItCannotReadBack)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const PersistenceInterval& bad : {PersistenceInterval{-1, 0.0, 1.0},
                                         PersistenceInterval{0, nan, 1.0},
                                         PersistenceInterval{0, 0.0, nan},
                                         PersistenceInterval{0, INF, INF},
                                         PersistenceInterval{0, 2.0, 1.0}}) {
    std::ostringstream out;
    EXPECT_THROW (pcl::tda::writeDiagramCSV (out, {{0, 0.0, 1.0}, bad}),
                  pcl::BadArgumentException)
        << bad.dimension << " " << bad.birth << " " << bad.death;
  }
}

TEST (DiagramIO, SaveAndLoadFile)
{
  const TemporaryFolder folder;
  const std::string path = (folder.path() / "diagram.csv").string();
  const PersistenceDiagram diagram = {{0, 0.0, INF}, {0, 0.0, 0.7}, {1, 0.3, 0.45}};
  pcl::tda::saveDiagramCSV (path, diagram);
  EXPECT_EQ (1u, folder.numFiles());
  expectBitwiseEqual (diagram, pcl::tda::loadDiagram (path));

  // Overwriting replaces the whole content and leaves no temporary file.
  pcl::tda::saveDiagramCSV (path, {{2, 1.5, 2.5}});
  EXPECT_EQ (1u, folder.numFiles());
  expectBitwiseEqual ({{2, 1.5, 2.5}}, pcl::tda::loadDiagram (path));
}

TEST (DiagramIO, FailedSaveLeavesOldFileAndNoTemporary)
{
  const TemporaryFolder folder;
  const std::string path = (folder.path() / "diagram.csv").string();
  pcl::tda::saveDiagramCSV (path, {{0, 0.0, 1.0}});
  EXPECT_THROW (pcl::tda::saveDiagramCSV (path, {{0, 0.0, 1.0}, {0, 1.0, 0.0}}),
                pcl::BadArgumentException);
  EXPECT_EQ (1u, folder.numFiles());
  expectBitwiseEqual ({{0, 0.0, 1.0}}, pcl::tda::loadDiagram (path));
}

TEST (DiagramIO, SaveToUnwritablePathThrowsAndCreatesNothing)
{
  const std::string path = "/nonexistent_dir_pcl_tda/x.csv";
  EXPECT_THROW (pcl::tda::saveDiagramCSV (path, {{0, 0.0, 1.0}}), pcl::IOException);
  EXPECT_FALSE (std::filesystem::exists ("/nonexistent_dir_pcl_tda"));
}

TEST (DiagramIO, LoadMissingFileThrows)
{
  const TemporaryFolder folder;
  const std::string path = (folder.path() / "missing.csv").string();
  try {
    pcl::tda::loadDiagram (path);
    FAIL() << "no exception";
  }
  catch (const pcl::IOException& e) {
    EXPECT_NE (std::string::npos, std::string (e.what()).find (path)) << e.what();
  }
}

TEST (DiagramIO, LoadErrorNamesFileAndLine)
{
  const TemporaryFolder folder;
  const std::string path = (folder.path() / "bad.csv").string();
  {
    std::ofstream out (path);
    out << "dim,birth,death\n0,0,1\n0,2,1\n";
  }
  try {
    pcl::tda::loadDiagram (path);
    FAIL() << "no exception";
  }
  catch (const pcl::IOException& e) {
    EXPECT_NE (std::string::npos, std::string (e.what()).find (path + ": line 3:"))
        << e.what();
  }
}

} // namespace
