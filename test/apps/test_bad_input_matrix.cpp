// The bad-input matrix of the tools: every malformed input file, option and output
// path, for every tool that takes it, must give a non-zero exit and a message that
// names the problem on a line of its own, and must leave every file as it was (no
// output created or changed, no temporary file left). Also -h, and outputs that are
// links or have their own permission bits.

#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/generators/shapes.h>

#include <gtest/gtest.h>

#include "apps/pcd_test_files.h"
#include "tool_runner.h"
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

using pcl::tda::test::run;
using pcl::tda::test::RunResult;
using pcl::tda::test::writeFile;

namespace {

/** What a folder holds: per entry, its kind, permission bits and content (or link
 * target). */
using FolderState = std::map<std::string, std::string>;

FolderState
stateOf (const std::string& folder)
{
  FolderState state;
  for (const auto& entry : std::filesystem::directory_iterator (folder)) {
    const std::string path = entry.path().string();
    struct stat status;
    ::lstat (path.c_str(), &status);
    std::ostringstream description;
    description << std::oct << status.st_mode << " ";
    if (entry.is_symlink())
      description << "-> " << std::filesystem::read_symlink (entry.path()).string();
    else if (entry.is_regular_file())
      description << std::ifstream (path, std::ios::binary).rdbuf();
    state[entry.path().filename().string()] = description.str();
  }
  return state;
}

std::string
tool (const std::string& name)
{
  return std::string (PCL_TDA_BIN_DIR) + "/pcl_tda_" + name;
}

/** A folder with a small valid cloud, existing outputs, a folder named like a PCD
 * file and a FIFO, removed at the end. */
class BadInputMatrix : public ::testing::Test {
protected:
  void
  SetUp () override
  {
    folder_ = pcl::tda::test::temporaryFolder ("bad_input_matrix");
    std::filesystem::create_directories (folder_ + "/x.pcd");
    pcl::tda::CircleParameters circle;
    circle.num_points = 200;
    const auto points = pcl::tda::generateCircle (circle).cloud;
    pcl::io::savePCDFileBinary (path ("good.pcd"), *points);
    // The same points in two colours, for pcl_tda_regions.
    pcl::PointCloud<pcl::PointXYZRGB> coloured;
    pcl::copyPointCloud (*points, coloured);
    for (std::size_t i = 0; i < coloured.size(); ++i) {
      coloured[i].r = i % 2 ? 200 : 40;
      coloured[i].g = 90;
      coloured[i].b = 60;
    }
    pcl::io::savePCDFileBinary (path ("colour.pcd"), coloured);
    pcl::PointCloud<pcl::PointXYZ> plain;
    pcl::copyPointCloud (*points, plain);
    pcl::io::savePCDFileBinary (path ("plain.pcd"), plain);
    for (const char* output : {"out.csv", "out.pcd", "old.svg"})
      writeFile (path (output), "old content\n");
    ASSERT_EQ (::mkfifo (path ("fifo.pcd").c_str(), 0600), 0);
  }

  void
  TearDown () override
  {
    std::filesystem::remove_all (folder_);
  }

  std::string
  path (const std::string& name) const
  {
    return folder_ + "/" + name;
  }

  /** Runs \a tool_name with \a arguments, expecting a refusal that says \a message
   * and changes nothing in the folder. */
  void
  expectRefusal (const std::string& tool_name,
                 const std::string& arguments,
                 const std::string& message) const
  {
    const FolderState before = stateOf (folder_);
    const RunResult result =
        run ("cd " + folder_ + " && timeout 60 " + tool (tool_name) + " " + arguments);
    const std::string context =
        "pcl_tda_" + tool_name + " " + arguments + "\n" + result.output;
    EXPECT_NE (result.exit_code, 0) << context;
    const auto at = result.output.find (message);
    EXPECT_NE (at, std::string::npos) << "expected: " << message << "\n" << context;
    // The error comes after the step lines ("> Loading x.pcd "), on a line of its
    // own.
    const auto last_step = result.output.rfind ("\n> ");
    const auto line_start = result.output.rfind ('\n', at);
    if (at != std::string::npos && last_step != std::string::npos) {
      EXPECT_GT (at, last_step) << context;
      EXPECT_NE (result.output.compare (line_start + 1, 2, "> "), 0) << context;
    }
    EXPECT_EQ (stateOf (folder_), before) << context;
  }

  std::string folder_;
};

} // namespace

TEST_F (BadInputMatrix, MalformedInputFiles)
{
  for (const auto& [content, message] : pcl::tda::test::malformedPCDFiles()) {
    writeFile (path ("bad.pcd"), content);
    expectRefusal ("barcode", "bad.pcd out.csv -radius 0.1", message);
    expectRefusal ("segment", "bad.pcd out.pcd -radius 0.1 -plane 0", message);
    expectRefusal ("regions", "bad.pcd out.pcd -radius 0.1", message);
    expectRefusal ("holes", "bad.pcd out.pcd -radius 0.1", message);
    expectRefusal ("stpp", "out.csv bad.pcd", message);
  }
  const std::vector<std::pair<std::string, std::string>> inputs{
      {"x.pcd", "x.pcd is a directory, not a PCD file"},
      {"fifo.pcd", "fifo.pcd is not a regular file"},
      {"missing.pcd", "cannot open missing.pcd: No such file or directory"},
  };
  for (const auto& [input, message] : inputs) {
    expectRefusal ("barcode", input + " out.csv -radius 0.1", message);
    expectRefusal ("segment", input + " out.pcd -radius 0.1", message);
    expectRefusal ("regions", input + " out.pcd", message);
    expectRefusal ("holes", input + " out.pcd", message);
    expectRefusal ("stpp", "out.csv " + input, message);
  }
  expectRefusal (
      "regions", "plain.pcd out.pcd", "plain.pcd has no colour (no rgb or rgba field)");
  // Colours stored otherwise than PCL's packed rgb, which PCL read as black: one byte
  // per channel, or a double.
  const std::string points = "0 0 0 85 90 103 255\n0.01 0 0 85 90 103 255\n";
  writeFile (path ("bytes.pcd"),
             "VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 1\nTYPE F F F U\nCOUNT 1 1 1 "
             "4\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n" +
                 points);
  expectRefusal ("regions",
                 "bytes.pcd out.pcd",
                 "bytes.pcd's rgb field holds 4 value(s) of 1 byte(s) (U) per point: "
                 "pcl_tda_regions reads PCL's packed colour");
  writeFile (path ("double.pcd"),
             "VERSION 0.7\nFIELDS x y z rgba\nSIZE 4 4 4 8\nTYPE F F F F\nCOUNT 1 1 1 "
             "1\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n0 0 0 1\n0.01 0 0 1\n");
  writeFile (path ("no_points.pcd"),
             "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH "
             "0\nHEIGHT 1\nPOINTS 0\nDATA ascii\n");
  expectRefusal ("holes", "no_points.pcd out.pcd", "Hole detection failed (see above)");
  expectRefusal ("regions",
                 "double.pcd out.pcd",
                 "double.pcd's rgba field holds 1 value(s) of 8 byte(s) (F) per point");
  // Normals in the file, one of them NaN at a finite point; all of them zero.
  pcl::PointCloud<pcl::PointXYZRGBNormal> with_normals;
  pcl::io::loadPCDFile (path ("colour.pcd"), with_normals);
  for (auto& point : with_normals)
    point.normal_x = 0.0f, point.normal_y = 0.0f, point.normal_z = 1.0f;
  with_normals[5].normal_z = std::nanf ("");
  pcl::io::savePCDFileBinary (path ("nan_normal.pcd"), with_normals);
  expectRefusal ("regions",
                 "nan_normal.pcd out.pcd",
                 "1 points with a finite position have a non-finite or zero normal");
  for (auto& point : with_normals)
    point.normal_z = 0.0f;
  pcl::io::savePCDFileBinary (path ("zero_normals.pcd"), with_normals);
  expectRefusal ("regions",
                 "zero_normals.pcd out.pcd",
                 "200 points with a finite position have a non-finite or zero normal");
}

TEST_F (BadInputMatrix, BadOptions)
{
  const std::string barcode = "good.pcd out.csv -radius 0.3 ";
  const std::vector<std::pair<std::string, std::string>> barcode_cases{
      {"good.pcd out.csv", "Option -radius is required."},
      {"good.pcd out.csv -radius abc", "Option -radius needs a number > 0, not 'abc'."},
      {"good.pcd out.csv -radius 0", "Option -radius needs a number > 0, not '0'."},
      {"good.pcd out.csv -radius -0.5",
       "Option -radius needs a number > 0, not '-0.5'."},
      {"good.pcd out.csv -radius nan", "Option -radius needs a number > 0, not 'nan'."},
      {barcode + "-dim abc", "Option -dim needs an integer from 0 to 1, not 'abc'."},
      {barcode + "-dim 2", "Option -dim needs an integer from 0 to 1, not '2'."},
      {barcode + "-leaf abc",
       "Option -leaf needs a number >= 0 and <= 3.40282e+38, not 'abc'."},
      {barcode + "-leaf -1",
       "Option -leaf needs a number >= 0 and <= 3.40282e+38, not '-1'."},
      {barcode + "-memory abc",
       "Option -memory needs a number > 0 and <= 1e+12, not 'abc'."},
      {barcode + "-memory 1MB",
       "Option -memory needs a number > 0 and <= 1e+12, not '1MB'."},
      {barcode + "-memory 1e20",
       "Option -memory needs a number > 0 and <= 1e+12, not '1e20'."},
      {barcode + "-memory 0",
       "Option -memory needs a number > 0 and <= 1e+12, not '0'."},
      {barcode + "-leaf 1e300",
       "Option -leaf needs a number >= 0 and <= 3.40282e+38, not '1e300'."},
      {barcode + "-engine ripser", "Unknown engine ripser"},
      {barcode + "-svg", "Option -svg needs a value."},
      {barcode + "-diagram", "Option -diagram needs a value."},
      {barcode + "-foo", "Unknown option -foo"},
      {"good.pcd out.csv --radius 0.3", "Unknown option --radius"},
      {barcode + "-radius 0.2", "Option -radius is given twice."},
      {barcode + "-gpu -gpu", "Option -gpu is given twice."},
      {barcode + "extra.csv",
       "Need the input .pcd file and the output .csv file, not 3 arguments."},
      {"good.pcd -radius 0.3",
       "Need the input .pcd file and the output .csv file, not 1 argument."},
      {"good.txt out.csv -radius 0.3", "The input good.txt must be a .pcd file."},
      {"good.pcd out.txt -radius 0.3", "The output out.txt must be a .csv file."},
      {barcode + "-leaf 2e-5", "-leaf 2e-05 is too small for the points' extent"},
      {barcode + "-leaf 1e-50", "too coarse for -leaf 1e-50 (at most 1/100 of it)"},
  };
  for (const auto& [arguments, message] : barcode_cases)
    expectRefusal ("barcode", arguments, message);
  // A name longer than a folder takes: refused before the work, not after it.
  expectRefusal ("barcode",
                 "good.pcd " + std::string (252, 'a') + ".csv -radius 0.3",
                 "its file name has 256 bytes, the folder takes 255 at most");

  const std::string segment = "good.pcd out.pcd -radius 0.3 -plane 0 ";
  const std::vector<std::pair<std::string, std::string>> segment_cases{
      {"good.pcd out.pcd", "Option -radius is required."},
      {"good.pcd out.pcd -radius abc", "Option -radius needs a number > 0, not 'abc'."},
      {segment + "-min abc",
       "Option -min needs an integer from 1 to 2147483647, not "
       "'abc'."},
      {segment + "-min 0", "Option -min needs an integer from 1 to 2147483647"},
      {segment + "-max 5000000000",
       "Option -max needs an integer from 1 to 2147483647"},
      {segment + "-min 10 -max 5", "Need 1 <= -min <= -max, not 10 and 5."},
      {"good.pcd out.pcd -radius 0.3 -plane yes",
       "Option -plane needs an integer from 0 to 1, not 'yes'."},
      {"good.pcd out.pcd -radius 0.3 -plane 2",
       "Option -plane needs an integer from 0 to 1, not '2'."},
      {segment + "-plane_dist 0", "Option -plane_dist needs a number > 0, not '0'."},
      {segment + "-auto -piece 1",
       "Option -piece needs a number >= 0 and < 1, not '1'."},
      {segment + "-auto -piece -0.1",
       "Option -piece needs a number >= 0 and < 1, not '-0.1'."},
      {segment + "-piece 0.3", "-piece has no use without -auto."},
      {segment + "-range -1", "Option -range needs a number >= 0, not '-1'."},
      {segment + "-leaf abc",
       "Option -leaf needs a number >= 0 and <= 3.40282e+38, not 'abc'."},
      {segment + "-leaf 2e-5", "-leaf 2e-05 is too small for the points' extent"},
      {segment + "-auto 1",
       "Need the input .pcd file and the output .pcd file, not 3 arguments."},
      {segment + "-svg", "Option -svg needs a value."},
      {segment + "-foo", "Unknown option -foo"},
      {"good.pcd out.csv -radius 0.3", "The output out.csv must be a .pcd file."},
  };
  for (const auto& [arguments, message] : segment_cases)
    expectRefusal ("segment", arguments, message);

  const std::string regions = "colour.pcd out.pcd ";
  const std::vector<std::pair<std::string, std::string>> regions_cases{
      {regions + "-radius 0",
       "Option -radius needs a number > 0 and <= 1e+09, not '0'."},
      {regions + "-radius abc",
       "Option -radius needs a number > 0 and <= 1e+09, not 'abc'."},
      {regions + "-color 0", "Option -color needs a number > 0 and <= 1000, not '0'."},
      {regions + "-color -3",
       "Option -color needs a number > 0 and <= 1000, not '-3'."},
      {regions + "-point-color nan",
       "Option -point-color needs a number > 0 and <= 1000, not 'nan'."},
      {regions + "-image-ratio -0.5",
       "Option -image-ratio needs a number >= 0 and <= 1, not '-0.5'."},
      {regions + "-angle 0", "Option -angle needs a number > 0 and <= 90, not '0'."},
      {regions + "-angle 91", "Option -angle needs a number > 0 and <= 90, not '91'."},
      {regions + "-min 0", "Option -min needs an integer from 1 to 2147483647"},
      {regions + "-color 5 -auto", "-color and -auto exclude each other: give one."},
      {regions + "-angle 10 -no-normals", "-angle has no use with -no-normals."},
      {regions + "-png", "Option -png needs a value."},
      {regions + "-foo", "Unknown option -foo"},
      {"colour.pcd out.csv", "The output out.csv must be a .pcd file."},
  };
  for (const auto& [arguments, message] : regions_cases)
    expectRefusal ("regions", arguments, message);

  const std::string holes = "plain.pcd out.pcd ";
  const std::vector<std::pair<std::string, std::string>> holes_cases{
      {holes + "-radius 0", "Option -radius needs a number > 0 and <= 1e+09, not '0'."},
      {holes + "-radius nan",
       "Option -radius needs a number > 0 and <= 1e+09, not 'nan'."},
      {holes + "-min-hole -1",
       "Option -min-hole needs a number > 0 and <= 1e+09, not '-1'."},
      {holes + "-max-cycle 2",
       "Option -max-cycle needs an integer from 3 to 2147483647, not '2'."},
      {holes + "-fill f.pcd -fill-mode cube",
       "-fill-mode must be surface or centroid (got 'cube')."},
      {holes + "-fill-mode centroid", "-fill-mode has no use without -fill."},
      {holes + "-fill f.csv", "-fill needs a .pcd file (got 'f.csv')."},
      {holes + "-memory -1", "Option -memory needs a number > 0"},
      {holes + "-png", "Option -png needs a value."},
      {holes + "-foo", "Unknown option -foo"},
      {"plain.pcd out.csv", "The output out.csv must be a .pcd file."},
  };
  for (const auto& [arguments, message] : holes_cases)
    expectRefusal ("holes", arguments, message);

  const std::vector<std::pair<std::string, std::string>> generate_cases{
      {"cube out.pcd", "Unknown kind 'cube'"},
      {"circle out.csv", "The output out.csv must be a .pcd file."},
      {"circle out.pcd -n 2000000000",
       "Option -n needs an integer from 1 to 10000000, not '2000000000'."},
      {"circle out.pcd -n abc", "Option -n needs an integer from 1 to 10000000"},
      {"circle out.pcd -n 0", "Option -n needs an integer from 1 to 10000000"},
      {"circle out.pcd -n", "Option -n needs a value."},
      {"circle out.pcd -noise abc",
       "Option -noise needs a number >= 0 and <= 3.40282e+38, not 'abc'."},
      {"circle out.pcd -seed -1", "Option -seed needs an integer >= 0, not '-1'."},
      {"tabletop out.pcd -objects 99", "Option -objects needs an integer from 0 to 8"},
      {"tabletop out.pcd -n 1749",
       "Option -n needs at least 1750 samples on the table top for tabletop (a point "
       "per 2 cm x 2 cm), not '1749'."},
      {"regions out.pcd -n 10",
       "Option -n needs at least 1750 samples on the table top for regions"},
      {"shapes set -instances 1000 -views 1000",
       "-instances 1000 x -views 1000 x 12 categories would be 12000000 views (files), "
       "over 1000000: use fewer instances or views."},
      {"circle out.pcd -objects 2",
       "Option -objects applies to tabletop, regions and depth-regions only."},
      {"circle out.pcd -radius 2", "Unknown option -radius"},
      {"circle out.pcd extra.pcd",
       "Need the kind and the output .pcd file, not 3 arguments."},
      {"holes out.pcd -surface cube",
       "Option -surface needs plane, sphere, cylinder, torus or heightfield, not "
       "'cube'."},
      {"holes out.pcd -hole-radii 3,,5",
       "Option -hole-radii needs numbers >= 1 separated by commas (radii in units of "
       "the spacing), not '3,,5'."},
      {"holes out.pcd -hole-radii 200",
       "generateHoleSurface: cannot place 1 hole of radius 200"},
      {"holes out.pcd -noise 1",
       "Option -noise needs a number >= 0 and < 1 for holes (in units of the "
       "spacing), not '1'."},
      {"holes out.pcd -remove 0.9",
       "Option -remove needs a number >= 0 and < 0.9, not '0.9'."},
      {"holes out.pcd -n 999",
       "Option -n needs an integer from 1000 to 10000000 for holes, not '999'."},
      {"holes out.pcd -removed r.pcd", "Option -removed needs -remove F with F > 0."},
      {"holes out.pcd -remove 0.1 -removed r.csv",
       "The -removed file r.csv must be a .pcd file."},
      {"circle out.pcd -surface plane", "Option -surface applies to holes only."},
  };
  for (const auto& [arguments, message] : generate_cases)
    expectRefusal ("generate", arguments, message);
}

TEST_F (BadInputMatrix, BadOutputs)
{
  const std::string circle_link = path ("circle_link.csv");
  std::filesystem::create_symlink ("good.pcd", circle_link);
  std::filesystem::create_symlink ("good.pcd", path ("circle_link.svg"));
  std::filesystem::create_directories (path ("folder.svg"));
  const std::vector<std::pair<std::string, std::string>> barcode_cases{
      {"good.pcd out.csv -radius 0.3 -svg nodir/b.svg",
       "cannot write nodir/b.svg: the folder nodir does not exist"},
      {"good.pcd out.csv -radius 0.3 -svg folder.svg",
       "cannot write folder.svg: it is a directory"},
      {"good.pcd out.csv -radius 0.3 -svg b.txt",
       "-svg needs a .svg file (got 'b.txt')."},
      {"good.pcd out.csv -radius 0.3 -svg old.svg -diagram old.svg",
       "-svg and -diagram name the same file old.svg"},
      {"good.pcd out.csv -radius 0.3 -export-phat ./out.csv",
       "output and -export-phat name the same file ./out.csv"},
      // Files not there yet, spelled two ways.
      {"good.pcd new.csv -radius 0.3 -svg n.svg -diagram ./n.svg",
       "-svg and -diagram name the same file ./n.svg"},
      {"good.pcd out.csv -radius 0.3 -diagram circle_link.svg",
       "refusing to overwrite the input file good.pcd (-diagram)"},
      {"good.pcd circle_link.csv -radius 0.3",
       "refusing to overwrite the input file good.pcd (output)"},
  };
  for (const auto& [arguments, message] : barcode_cases)
    expectRefusal ("barcode", arguments, message);
  // A name longer than a folder takes: refused before the work, not after it.
  expectRefusal ("barcode",
                 "good.pcd " + std::string (252, 'a') + ".csv -radius 0.3",
                 "its file name has 256 bytes, the folder takes 255 at most");
  const std::vector<std::pair<std::string, std::string>> segment_cases{
      {"good.pcd nodir/out.pcd -radius 0.3 -plane 0",
       "cannot write nodir/out.pcd: the folder nodir does not exist"},
      {"good.pcd out.pcd -radius 0.3 -plane 0 -svg nodir/b.svg",
       "cannot write nodir/b.svg: the folder nodir does not exist"},
      {"good.pcd x.pcd -radius 0.3 -plane 0", "cannot write x.pcd: it is a directory"},
      {"good.pcd good.pcd -radius 0.3 -plane 0",
       "refusing to overwrite the input file good.pcd (output)"},
  };
  for (const auto& [arguments, message] : segment_cases)
    expectRefusal ("segment", arguments, message);
  const std::vector<std::pair<std::string, std::string>> regions_cases{
      {"colour.pcd nodir/out.pcd",
       "cannot write nodir/out.pcd: the folder nodir does not exist"},
      {"colour.pcd out.pcd -png nodir/r.png",
       "cannot write nodir/r.png: the folder nodir does not exist"},
      {"colour.pcd out.pcd -svg r.svg -png r.png",
       "-png and the PNG of -svg name the same file r.png"},
      {"colour.pcd out.pcd -png old.svg", "-png needs a .png file (got 'old.svg')."},
      {"colour.pcd colour.pcd",
       "refusing to overwrite the input file colour.pcd (output)"},
      {"colour.pcd out.pcd -memory 0.000001", "Region growing failed (see above)"},
  };
  for (const auto& [arguments, message] : regions_cases)
    expectRefusal ("regions", arguments, message);
  const std::vector<std::pair<std::string, std::string>> holes_cases{
      {"plain.pcd nodir/out.pcd",
       "cannot write nodir/out.pcd: the folder nodir does not exist"},
      {"plain.pcd out.pcd -fill nodir/f.pcd",
       "cannot write nodir/f.pcd: the folder nodir does not exist"},
      {"plain.pcd out.pcd -fill out.pcd",
       "output and -fill name the same file out.pcd"},
      {"plain.pcd new.pcd -fill ./new.pcd",
       "output and -fill name the same file ./new.pcd"},
      {"plain.pcd out.pcd -csv old.svg", "-csv needs a .csv file (got 'old.svg')."},
      {"plain.pcd out.pcd -fill plain.pcd",
       "refusing to overwrite the input file plain.pcd (-fill)"},
      {"plain.pcd plain.pcd",
       "refusing to overwrite the input file plain.pcd (output)"},
      {"plain.pcd out.pcd -memory 0.000001", "Hole detection failed (see above)"},
      // Over HoleBoundaryEstimation::MAX_RADIUS_PER_SPACING: refused at once (a
      // radius over the whole cloud ran for minutes before).
      {"plain.pcd out.pcd -radius 1000", "Hole detection failed (see above)"},
  };
  for (const auto& [arguments, message] : holes_cases)
    expectRefusal ("holes", arguments, message);
  expectRefusal ("generate", "circle x.pcd", "cannot write x.pcd: it is a directory");
  expectRefusal ("generate",
                 "holes out.pcd -remove 0.1 -removed x.pcd",
                 "cannot write x.pcd: it is a directory");
  expectRefusal ("generate",
                 "holes out.pcd -remove 0.1 -removed ./out.pcd",
                 "output and -removed name the same file ./out.pcd");
  expectRefusal ("generate",
                 "circle nodir/c.pcd",
                 "cannot write nodir/c.pcd: the folder nodir does not exist");
}

// The longest names a folder takes are written: the temporary files' names are cut
// short to fit (they were the name with ".tmp.<pid>" after it, too long, and a run
// failed after all its work). Past the file size limit (`ulimit -f`) a write fails
// with a message and nothing left behind (SIGXFSZ ended the tools, with a core dump
// and their temporary files left).
TEST_F (BadInputMatrix, LongestNamesAndTheFileSizeLimit)
{
  const std::string longest = std::string (251, 'b') + ".csv";
  const RunResult written =
      run ("cd " + folder_ + " && timeout 60 " + tool ("barcode") + " good.pcd " +
           longest + " -radius 0.3 -svg " + std::string (251, 'c') + ".svg -png");
  EXPECT_EQ (written.exit_code, 0) << written.output;
  FolderState expected = stateOf (folder_);
  for (const std::string& name :
       {longest, std::string (251, 'c') + ".svg", std::string (251, 'c') + ".png"}) {
    EXPECT_EQ (expected.count (name), 1u) << name << "\n" << written.output;
    expected.erase (name);
    std::filesystem::remove (path (name));
  }
  EXPECT_EQ (stateOf (folder_), expected) << "files left: " << written.output;

  const FolderState before = stateOf (folder_);
  const RunResult limited = run ("cd " + folder_ + " && ulimit -f 1 && timeout 60 " +
                                 tool ("barcode") + " good.pcd new.csv -radius 0.3");
  EXPECT_EQ (limited.exit_code, 1) << limited.output;
  EXPECT_NE (limited.output.find ("cannot write new.csv: File too large"),
             std::string::npos)
      << limited.output;
  EXPECT_EQ (stateOf (folder_), before) << limited.output;
}

// Under an address-space limit (`ulimit -v`) the default -memory is half of it: the
// complete graphs of a 13.7k-point scan (94M edges) are refused before they are
// allocated, with the limit named. They were not (the default was half of the
// physical memory), and the tools aborted with std::bad_alloc. pcl_tda_segment needs
// no more than the limit for them (Boruvka's rounds past it): one cluster.
TEST_F (BadInputMatrix, RefusedUnderAnAddressSpaceLimit)
{
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "the address sanitizer reserves more address space than the limit";
#endif
  const std::string scan = std::string (PCL_TDA_DATA_DIR) + "/milk_color.pcd";
  if (!std::filesystem::exists (scan))
    GTEST_SKIP() << "no " << scan << " (../shared/data)";
  const auto run_limited = [this] (const std::string& tool_name,
                                   const std::string& arguments) {
    return run ("cd " + folder_ + " && ulimit -v 2000000 && timeout 60 " +
                tool (tool_name) + " " + arguments); // KiB: about 1.9 GiB
  };
  for (const auto& [tool_name, arguments] :
       std::vector<std::pair<std::string, std::string>>{
           {"barcode", scan + " out.csv -radius 1e30 -dim 0"},
           {"regions", scan + " out.pcd -radius 1e9"}}) {
    const FolderState before = stateOf (folder_);
    const RunResult result = run_limited (tool_name, arguments);
    EXPECT_EQ (result.exit_code, 1) << result.output;
    EXPECT_NE (result.output.find ("over the memory limit of 976.6 MiB"),
               std::string::npos)
        << result.output;
    EXPECT_EQ (stateOf (folder_), before) << result.output;
  }
  const RunResult segment =
      run_limited ("segment", scan + " out.pcd -radius 1e30 -plane 0");
  EXPECT_EQ (segment.exit_code, 0) << segment.output;
  EXPECT_NE (segment.output.find ("1 cluster at distance 1e+30"), std::string::npos)
      << segment.output;
}

TEST_F (BadInputMatrix, HelpPrintsOnlyTheHelp)
{
  for (const std::string& command :
       {std::string ("barcode -h"),
        std::string ("barcode good.pcd out.csv -radius 0.3 --help"),
        std::string ("segment -h"),
        std::string ("segment good.pcd out.pcd -foo -h"),
        std::string ("regions -h"),
        std::string ("regions colour.pcd out.pcd -color 0 -h"),
        std::string ("holes -h"),
        std::string ("holes plain.pcd out.pcd -max-cycle 1 -h"),
        std::string ("generate --help"),
        std::string ("generate circle out.pcd -h")}) {
    const FolderState before = stateOf (folder_);
    const RunResult result = run ("cd " + folder_ + " && " + tool (command));
    EXPECT_EQ (result.exit_code, 0) << command << "\n" << result.output;
    EXPECT_EQ (result.output.rfind ("Syntax is: ", 0), 0u) << command;
    EXPECT_EQ (result.output.find ("\n> "), std::string::npos) << command;
    EXPECT_EQ (stateOf (folder_), before) << command;
  }
}

TEST_F (BadInputMatrix, OutputsKeepLinksAndPermissions)
{
  std::filesystem::create_symlink ("old.svg", path ("link.svg"));
  ::chmod (path ("out.csv").c_str(), 0640);
  const RunResult result = run ("cd " + folder_ + " && " + tool ("barcode") +
                                " good.pcd out.csv -radius 0.3 -svg link.svg");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_TRUE (std::filesystem::is_symlink (path ("link.svg")));
  std::ostringstream svg;
  svg << std::ifstream (path ("old.svg")).rdbuf();
  EXPECT_NE (svg.str().find ("<svg"), std::string::npos);
  struct stat status;
  ASSERT_EQ (::stat (path ("out.csv").c_str(), &status), 0);
  EXPECT_EQ (status.st_mode & 07777, 0640u);
  std::ostringstream csv;
  csv << std::ifstream (path ("out.csv")).rdbuf();
  EXPECT_EQ (csv.str().rfind ("dim,birth,death\n", 0), 0u);
}

TEST_F (BadInputMatrix, DoubleAndIntegerCoordinatesGiveTheFloatDiagram)
{
  pcl::PointCloud<pcl::PointXYZ> circle;
  pcl::io::loadPCDFile (path ("good.pcd"), circle);
  std::string doubles, integers;
  for (const auto& point : circle)
    for (const float value : {point.x, point.y, point.z}) {
      const double as_double = value;
      doubles.append (reinterpret_cast<const char*> (&as_double), sizeof (double));
      const auto as_integer = static_cast<std::int32_t> (std::lround (value * 1000));
      integers.append (reinterpret_cast<const char*> (&as_integer),
                       sizeof (as_integer));
    }
  writeFile (
      path ("doubles.pcd"),
      pcl::tda::test::pcdHeader ("x y z", "8 8 8", "F F F", circle.size(), "binary") +
          doubles);
  writeFile (
      path ("integers.pcd"),
      pcl::tda::test::pcdHeader ("x y z", "4 4 4", "I I I", circle.size(), "binary") +
          integers);
  std::map<std::string, std::string> diagrams;
  for (const auto& [input, radius] :
       {std::pair<std::string, std::string> ("good", "0.3"),
        {"doubles", "0.3"},
        {"integers", "300"}}) {
    const RunResult result = run ("cd " + folder_ + " && " + tool ("barcode") + " " +
                                  input + ".pcd " + input + ".csv -radius " + radius);
    ASSERT_EQ (result.exit_code, 0) << result.output;
    EXPECT_EQ (result.output.find ("Failed to find match"), std::string::npos);
    std::ostringstream csv;
    csv << std::ifstream (path (input + ".csv")).rdbuf();
    diagrams[input] = csv.str();
  }
  EXPECT_EQ (diagrams["doubles"], diagrams["good"]);
  // The integer cloud is the circle in millimetres: as many intervals.
  EXPECT_EQ (
      std::count (diagrams["integers"].begin(), diagrams["integers"].end(), '\n'),
      std::count (diagrams["good"].begin(), diagrams["good"].end(), '\n'));
  EXPECT_GT (std::count (diagrams["good"].begin(), diagrams["good"].end(), '\n'), 100);
}

TEST_F (BadInputMatrix, CoordinatesThatCannotResolveTheRadiusAreRefused)
{
  // The circle moved to UTM-like coordinates (x + 5e6, where floats are 0.5 apart),
  // with and without colour; a cloud of NaN points; the circle with 400 copies of one
  // point (invalid pixels written as 0, 0, 0).
  pcl::PointCloud<pcl::PointXYZRGB> far, nan_points;
  pcl::io::loadPCDFile (path ("colour.pcd"), far);
  pcl::PointCloud<pcl::PointXYZ> zeros;
  pcl::io::loadPCDFile (path ("good.pcd"), zeros);
  for (auto& point : far) {
    point.x += 5e6f;
    nan_points.push_back (point);
    nan_points.back().x = std::numeric_limits<float>::quiet_NaN();
  }
  for (int i = 0; i < 400; ++i)
    zeros.push_back (pcl::PointXYZ (0.0f, 0.0f, 0.0f));
  pcl::io::savePCDFileBinary (path ("far.pcd"), far);
  pcl::io::savePCDFileBinary (path ("nan.pcd"), nan_points);
  pcl::io::savePCDFileBinary (path ("zeros.pcd"), zeros);
  const std::string too_coarse =
      "The coordinates reach 5e+06, where 32-bit floats (PCL's point coordinates) are "
      "0.5 apart: too coarse for ";
  expectRefusal ("barcode", "far.pcd out.csv -radius 0.3", too_coarse + "-radius 0.3");
  expectRefusal ("barcode",
                 "far.pcd out.csv -radius 100 -leaf 1",
                 too_coarse + "-leaf 1 (at most 1/100 of it). Move the cloud near the "
                              "origin first");
  expectRefusal ("segment", "far.pcd out.pcd -radius 0.3 -plane 0", too_coarse);
  expectRefusal ("regions", "far.pcd out.pcd", too_coarse + "the radius from");
  expectRefusal ("holes", "far.pcd out.pcd", too_coarse + "the radius from");
  expectRefusal ("viewer",
                 "far.pcd -barcode -radius 0.3 -screenshot out.png",
                 too_coarse + "-radius 0.3");
  expectRefusal ("barcode",
                 "nan.pcd out.csv -radius 0.3",
                 "The input has no finite point (all 200 are NaN or infinite).");
  expectRefusal ("barcode",
                 "zeros.pcd out.csv -radius 0.01 -memory 1",
                 "399 of the 600 points repeat the position of another");
}
