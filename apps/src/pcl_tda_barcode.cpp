// pcl_tda_barcode: the H0 and H1 persistence diagrams of a point cloud's
// Vietoris-Rips filtration up to a radius, as CSV and as barcode pictures.

#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/scene_preprocessing.h>
#include <pcl/tda/apps/tool_console.h>
#include <pcl/tda/common/atomic_file.h>
#include <pcl/tda/common/diagram_io.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/persistence_engines.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/tda/common/phat_io.h>
#include <pcl/tda/common/progress_bar.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

using namespace pcl::console;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

namespace {

struct Options {
  std::string input, output, barcode_svg, diagram_svg, phat_matrix;
  pcl::tda::PersistenceEngine engine = pcl::tda::PersistenceEngine::COHOMOLOGY;
  double radius = 0.0;
  int dimension = 1;
  double leaf = 0.0;
  double memory_mib = 0.0;
  bool json = false;
};

/** Seconds spent in each phase, for the -json summary. */
struct PhaseSeconds {
  double load = 0, build = 0, h0 = 0, h1 = 0, write = 0, total = 0;
};

void
printHelp (const char* program)
{
  print_error ("Syntax is: %s input.pcd output.csv -radius R <options>\n", program);
  print_info ("  Writes the persistence diagram of the Vietoris-Rips filtration of the "
              "input's\n  points up to radius R (CSV: dim,birth,death; inf for "
              "essential classes).\n");
  print_info ("  where options are:\n");
  print_info (
      "                     -radius R    = largest edge length of the filtration "
      "(required, > 0)\n");
  print_info (
      "                     -dim 0|1     = highest homology dimension (default: ");
  print_value ("1");
  print_info (")\n");
  print_info ("                     -leaf L      = voxel grid leaf size applied first "
              "(default: 0 = off)\n");
  print_info ("                     -memory M    = refuse complexes over M MiB "
              "(default: half of the memory)\n");
  print_info ("                     -engine E    = H1 engine: cohomology (default, "
              "fastest), fip,\n"
              "                                    incremental or standard\n");
  print_info (
      "                     -export-phat F = also write the complex as a PHAT "
      "boundary matrix\n"
      "                                    (binary if F ends in .bin, else ASCII)\n");
  print_info ("                     -svg F.svg   = also draw the barcode\n");
  print_info (
      "                     -diagram F.svg = also draw the persistence diagram\n");
  print_info ("                     -json        = end with one JSON line of sizes and "
              "timings\n");
}

bool
parseOptions (int argc, char** argv, Options& options)
{
  const std::vector<int> pcd_files = parse_file_extension_argument (argc, argv, ".pcd");
  const std::vector<int> csv_files = parse_file_extension_argument (argc, argv, ".csv");
  if (pcd_files.size() != 1 || csv_files.size() != 1) {
    print_error ("Need one input PCD file and one output CSV file.\n");
    return false;
  }
  options.input = argv[pcd_files[0]];
  options.output = argv[csv_files[0]];
  if (parse_argument (argc, argv, "-radius", options.radius) < 0) {
    print_error ("The -radius R option is required.\n");
    return false;
  }
  parse_argument (argc, argv, "-dim", options.dimension);
  parse_argument (argc, argv, "-leaf", options.leaf);
  parse_argument (argc, argv, "-svg", options.barcode_svg);
  parse_argument (argc, argv, "-diagram", options.diagram_svg);
  parse_argument (argc, argv, "-memory", options.memory_mib);
  parse_argument (argc, argv, "-export-phat", options.phat_matrix);
  std::string engine_name;
  if (parse_argument (argc, argv, "-engine", engine_name) >= 0 &&
      !pcl::tda::parseEngineName (engine_name, options.engine)) {
    print_error ("Unknown engine %s: use cohomology, fip, incremental or standard.\n",
                 engine_name.c_str());
    return false;
  }
  options.json = find_switch (argc, argv, "-json");
  if (!(options.radius > 0.0) || !std::isfinite (options.radius)) {
    print_error ("The radius must be a positive number, not %g.\n", options.radius);
    return false;
  }
  if (options.dimension != 0 && options.dimension != 1) {
    print_error ("-dim must be 0 or 1, not %d.\n", options.dimension);
    return false;
  }
  if (!(options.memory_mib >= 0.0)) {
    print_error ("-memory must be >= 0, not %g.\n", options.memory_mib);
    return false;
  }
  if (!(options.leaf >= 0.0)) {
    print_error ("-leaf must be >= 0, not %g.\n", options.leaf);
    return false;
  }
  return !pcl::tda::overwritesInput (
      options.input,
      {options.output, options.barcode_svg, options.diagram_svg, options.phat_matrix});
}

int
run (const Options& options)
{
  TicToc total, timer;
  PhaseSeconds seconds;
  total.tic();

  timer.tic();
  Cloud::Ptr cloud (new Cloud);
  if (!pcl::tda::loadToolInput (options.input, *cloud))
    return 1;
  if (options.leaf > 0.0) {
    cloud = pcl::tda::voxelGridFilter<pcl::PointXYZ> (cloud, options.leaf);
  }
  seconds.load = timer.toc() / 1000.0;
  pcl::tda::printDone (timer, std::to_string (cloud->size()) + " points");

  timer.tic();
  print_highlight ("Building the Vietoris-Rips complex of radius ");
  print_value ("%g ", options.radius);
  pcl::tda::VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (options.radius);
  builder.setMaxDimension (options.dimension + 1);
  if (options.memory_mib > 0.0)
    builder.setMemoryLimit (static_cast<std::size_t> (options.memory_mib * 1048576.0));
  pcl::tda::FilteredComplex complex;
  if (!builder.compute (complex))
    return 1;
  seconds.build = timer.toc() / 1000.0;
  pcl::tda::printDone (timer,
                       std::to_string (complex.numVertices()) + " points, " +
                           std::to_string (complex.numEdges()) + " edges, " +
                           std::to_string (complex.numTriangles()) + " triangles");

  timer.tic();
  print_highlight ("Computing H0 ");
  pcl::tda::PersistenceResult result = pcl::tda::computeH0Persistence (complex);
  const std::size_t h0_intervals = result.diagram (complex, 0).size();
  seconds.h0 = timer.toc() / 1000.0;
  pcl::tda::printDone (timer, std::to_string (h0_intervals) + " intervals");

  if (options.dimension == 1) {
    timer.tic();
    print_highlight ("Computing H1 (%s) ",
                     pcl::tda::engineName (options.engine).c_str());
    pcl::tda::ProgressBar progress ("  reducing");
    pcl::tda::addH1Persistence (complex,
                                options.engine,
                                result,
                                [&progress] (std::size_t done, std::size_t total) {
                                  progress.update (done, total);
                                });
    progress.finish();
    seconds.h1 = timer.toc() / 1000.0;
  }
  const pcl::tda::PersistenceDiagram diagram =
      result.diagram (complex, options.dimension);
  const std::size_t h1_intervals = diagram.size() - h0_intervals;
  if (options.dimension == 1)
    pcl::tda::printDone (timer, std::to_string (h1_intervals) + " intervals");

  timer.tic();
  print_highlight ("Saving ");
  print_value ("%s ", options.output.c_str());
  try {
    pcl::tda::saveDiagramCSV (options.output, diagram);
    if (!options.phat_matrix.empty())
      pcl::tda::savePHATBoundaryMatrix (
          options.phat_matrix,
          complex,
          options.phat_matrix.size() > 4 &&
                  options.phat_matrix.compare (
                      options.phat_matrix.size() - 4, 4, ".bin") == 0
              ? pcl::tda::PHATFormat::BINARY
              : pcl::tda::PHATFormat::ASCII);
    pcl::tda::PlotOptions plot;
    std::ostringstream title;
    title << options.input << ", radius " << options.radius;
    plot.title = title.str();
    plot.max_value = options.radius;
    if (!options.barcode_svg.empty())
      pcl::tda::saveBarcodeSVG (options.barcode_svg, diagram, plot);
    if (!options.diagram_svg.empty())
      pcl::tda::savePersistenceDiagramSVG (options.diagram_svg, diagram, plot);
  }
  catch (const std::exception& error) {
    print_error ("\n%s\n", pcl::tda::errorMessage (error).c_str());
    return 1;
  }
  seconds.write = timer.toc() / 1000.0;
  pcl::tda::printDone (timer, std::to_string (diagram.size()) + " intervals");
  for (const std::string& picture :
       {options.barcode_svg, options.diagram_svg, options.phat_matrix})
    if (!picture.empty()) {
      print_info ("Written: ");
      print_value ("%s\n", picture.c_str());
    }

  seconds.total = total.toc() / 1000.0;
  if (options.json)
    std::printf ("{\"points\": %zu, \"skipped_points\": %zu, \"edges\": %zu, "
                 "\"triangles\": %zu, \"intervals\": {\"0\": %zu, \"1\": %zu}, "
                 "\"seconds\": {\"load\": %.6f, \"build\": %.6f, \"h0\": %.6f, "
                 "\"h1\": %.6f, \"write\": %.6f, \"total\": %.6f}}\n",
                 complex.numVertices(),
                 builder.getNumSkippedPoints(),
                 complex.numEdges(),
                 complex.numTriangles(),
                 h0_intervals,
                 h1_intervals,
                 seconds.load,
                 seconds.build,
                 seconds.h0,
                 seconds.h1,
                 seconds.write,
                 seconds.total);
  return 0;
}

} // namespace

int
main (int argc, char** argv)
{
  print_info (
      "Persistence barcodes of a point cloud. For more information, use: %s -h\n",
      argv[0]);
  if (argc < 3 || find_switch (argc, argv, "-h") ||
      find_switch (argc, argv, "--help")) {
    printHelp (argv[0]);
    return argc < 3 ? 1 : 0;
  }
  Options options;
  if (!parseOptions (argc, argv, options))
    return 1;
  return run (options);
}
