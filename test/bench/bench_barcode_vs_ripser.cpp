// pcl_tda_bench_barcode: end-to-end time of pcl_tda_barcode (PCD file to H0 + H1
// diagram) against Ripser in point-cloud mode on the same points and radius, in the
// same run; medians of several runs, their ratio, and whether the diagrams agree.
// Usage: pcl_tda_bench_barcode input.pcd radius [runs]
// The last stdout line is one JSON object.

#include <pcl/io/pcd_io.h>
#include <pcl/tda/common/diagram_comparison.h>
#include <pcl/tda/common/diagram_io.h>
#include <pcl/point_types.h>

#include "bench_command_line.h"
#include "bench_statistics.h"
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace {

using pcl::tda::bench::median;

/** Wall-clock seconds of running \a command through the shell; -1 if it failed. */
double
timeCommand (const std::string& command)
{
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system (command.c_str());
  const std::chrono::duration<double> elapsed =
      std::chrono::steady_clock::now() - start;
  return status == 0 ? elapsed.count() : -1.0;
}

struct Options {
  std::string input;
  double radius = 0.0;
  int runs = 5;
};

void
printUsage (std::FILE* stream)
{
  std::fprintf (stream,
                "Usage: pcl_tda_bench_barcode input.pcd radius [runs]\n"
                "  Times pcl_tda_barcode (PCD file to H0 + H1 diagram) against Ripser "
                "in\n  point-cloud mode on the same points and radius; runs: per "
                "tool, medians\n  reported (default 5).\n");
}

/** \throws pcl::BadArgumentException on a bad command line */
void
parseOptions (int argc, char** argv, Options& options)
{
  const std::vector<std::string> arguments =
      pcl::tda::ToolCommandLine().parse (argc, argv);
  if (arguments.size() < 2 || arguments.size() > 3)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Give the input file, the radius and optionally the runs.");
  options.input = arguments[0];
  options.radius = pcl::tda::bench::positiveNumber (arguments[1], "radius", false);
  if (arguments.size() == 3)
    options.runs =
        static_cast<int> (pcl::tda::bench::positiveNumber (arguments[2], "runs", true));
}

} // namespace

int
main (int argc, char** argv)
{
  Options options;
  if (const auto stop = pcl::tda::bench::parseCommandLine (
          argc, argv, options, parseOptions, printUsage))
    return *stop;
  const std::string& input = options.input;
  const double radius = options.radius;
  const int runs = options.runs;

  pcl::PointCloud<pcl::PointXYZ> cloud;
  if (pcl::io::loadPCDFile (input, cloud) < 0)
    return 1;
  const std::string scratch =
      "/tmp/pcl_tda_bench_barcode_" + std::to_string (::getpid());
  const std::string points = scratch + "_points.txt", ours = scratch + "_ours.csv",
                    theirs = scratch + "_ripser.txt";
  {
    FILE* out = std::fopen (points.c_str(), "w");
    if (!out)
      return 1;
    for (const auto& p : cloud)
      std::fprintf (out, "%.9g %.9g %.9g\n", p.x, p.y, p.z);
    std::fclose (out);
  }
  const std::string self (argv[0]);
  const std::string bin_dir = self.substr (0, self.rfind ('/') + 1);
  std::ostringstream our_command, ripser_command;
  our_command.precision (17);
  ripser_command.precision (17);
  our_command << bin_dir << "pcl_tda_barcode " << input << " " << ours << " -radius "
              << radius << " > /dev/null 2>&1";
  ripser_command << "ripser --format point-cloud --dim 1 --threshold " << radius << " "
                 << points << " > " << theirs;

  std::vector<double> our_times, ripser_times;
  for (int run = 0; run < runs; ++run) {
    our_times.push_back (timeCommand (our_command.str()));
    ripser_times.push_back (timeCommand (ripser_command.str()));
    if (our_times.back() < 0 || ripser_times.back() < 0) {
      std::fprintf (
          stderr, "a run failed: %s\n", our_times.back() < 0 ? "ours" : "ripser");
      return 1;
    }
  }
  const auto comparison = pcl::tda::compareDiagrams (
      pcl::tda::loadDiagram (ours), pcl::tda::loadDiagram (theirs), 1e-5);
  std::remove (points.c_str());
  std::remove (ours.c_str());
  std::remove (theirs.c_str());

  const double our_median = median (our_times), ripser_median = median (ripser_times);
  const auto [our_min, our_max] =
      std::minmax_element (our_times.begin(), our_times.end());
  const auto [ripser_min, ripser_max] =
      std::minmax_element (ripser_times.begin(), ripser_times.end());
  std::printf (
      "| input | points | radius | runs | pcl_tda_barcode s (min-max) | ripser s "
      "(min-max) | speed-up | diagrams |\n");
  std::printf (
      "| %s | %zu | %g | %d | %.3f (%.3f-%.3f) | %.3f (%.3f-%.3f) | %.1fx | %s |\n",
      input.substr (input.rfind ('/') + 1).c_str(),
      cloud.size(),
      radius,
      runs,
      our_median,
      *our_min,
      *our_max,
      ripser_median,
      *ripser_min,
      *ripser_max,
      ripser_median / our_median,
      comparison.equal ? "equal" : "DIFFER");
  if (!comparison.equal)
    std::printf ("%s\n", comparison.summary().c_str());
  std::printf ("{\"input\": \"%s\", \"points\": %zu, \"radius\": %.9g, \"runs\": %d, "
               "\"ours_median_s\": %.6f, \"ripser_median_s\": %.6f, \"ratio\": %.3f, "
               "\"diagrams_agree\": %s}\n",
               input.c_str(),
               cloud.size(),
               radius,
               runs,
               our_median,
               ripser_median,
               ripser_median / our_median,
               comparison.equal ? "true" : "false");
  return comparison.equal ? 0 : 2;
}
