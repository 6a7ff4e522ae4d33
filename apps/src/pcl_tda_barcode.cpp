// pcl_tda_barcode: the H0 and H1 persistence diagrams of a point cloud's
// Vietoris-Rips filtration up to a radius, as CSV and as barcode pictures.

#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/tda/apps/coordinate_check.h>
#include <pcl/tda/apps/svg_png.h>
#include <pcl/tda/apps/tool_console.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/apps/voxel_grid_filter.h>
#include <pcl/tda/common/diagram_io.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/persistence_engines.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/tda/common/phat_io.h>
#include <pcl/tda/common/progress_bar.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/gpu/vietoris_rips_builder.h>
#include <pcl/tda/search/clique_persistence.h>
#include <pcl/tda/search/radius_edges.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <cstdio>
#include <limits>
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
  long dimension = 1;
  double leaf = 0.0;
  std::size_t memory_limit = pcl::tda::defaultMemoryLimit();
  bool json = false;
  bool gpu = false;
  bool png = false;
};

/** Seconds spent in each phase, for the -json summary. */
struct PhaseSeconds {
  double load = 0, build = 0, h0 = 0, h1 = 0, write = 0, total = 0;
};

void
printHelp (const char* program)
{
  print_info ("Syntax is: %s input.pcd output.csv -radius R <options>\n", program);
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
  print_info (
      "                     -gpu         = build the complex with "
      "pcl::tda::gpu::VietorisRipsBuilder:\n"
      "                                    on a CUDA device when built with CUDA "
      "and one is\n"
      "                                    present, else on the OpenMP backend "
      "(same complex)\n");
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
  print_info ("                     -png         = also write each SVG picture as PNG "
              "beside it\n"
              "                                    (F.png for F.svg)\n");
  print_info ("                     -json        = end with one JSON line of sizes and "
              "timings\n");
  print_info ("  Outputs are written only when the whole run succeeds.\n");
}

/** Reads the command line into \a options.
 * \throws pcl::BadArgumentException naming the option at fault */
void
parseOptions (int argc, char** argv, Options& options)
{
  pcl::tda::ToolCommandLine command_line;
  command_line.addNumber (
      "-radius", options.radius, pcl::tda::NumberRange::above (0.0), true);
  command_line.addInteger ("-dim", options.dimension, 0, 1);
  // PCL's voxel grid takes a float leaf; the limit in bytes is a std::size_t.
  command_line.addNumber (
      "-leaf",
      options.leaf,
      pcl::tda::NumberRange::atLeast (0.0, std::numeric_limits<float>::max()));
  command_line.addMemory ("-memory", options.memory_limit);
  std::string engine_name = pcl::tda::engineName (options.engine);
  command_line.addText ("-engine", engine_name);
  command_line.addText ("-export-phat", options.phat_matrix);
  command_line.addText ("-svg", options.barcode_svg);
  command_line.addText ("-diagram", options.diagram_svg);
  command_line.addSwitch ("-json", options.json);
  command_line.addSwitch ("-gpu", options.gpu);
  command_line.addSwitch ("-png", options.png);
  const std::vector<std::string> files = command_line.parse (argc, argv);
  pcl::tda::checkArguments (files, {{"input", ".pcd"}, {"output", ".csv"}});
  options.input = files[0];
  options.output = files[1];
  if (!pcl::tda::parseEngineName (engine_name, options.engine))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Unknown engine " << engine_name
                                           << ": use cohomology, fip, incremental or "
                                              "standard.");
  if (options.png && options.barcode_svg.empty() && options.diagram_svg.empty())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "-png has no use without -svg or -diagram.");
  pcl::tda::checkOptionExtension ("-svg", options.barcode_svg, ".svg");
  pcl::tda::checkOptionExtension ("-diagram", options.diagram_svg, ".svg");
}

/** True when H1 comes from the edges alone (computeCliqueH1Persistence()): the
 * default engine, when nothing needs the triangles listed (-export-phat does). */
bool
triangleFree (const Options& options)
{
  return options.dimension == 1 &&
         options.engine == pcl::tda::PersistenceEngine::COHOMOLOGY &&
         options.phat_matrix.empty();
}

/** The PNG picture of -png beside the SVG picture \a svg; "" for none. */
std::string
pngOutput (const Options& options, const std::string& svg)
{
  return options.png && !svg.empty() ? pcl::tda::pngBesideSVG (svg) : "";
}

/** What building the complex reports: the skipped points and the builder that ran. */
struct BuildReport {
  std::size_t skipped_points = 0;
  std::string builder = "cpu";
};

/** Builds the complex of \a cloud with \a builder (the CPU builder or the gpu/ one,
 * which have the same setters), showing its progress.
 * \return false when the builder refused (it said why) */
template <typename Builder>
bool
buildComplex (Builder& builder,
              const Options& options,
              const Cloud::ConstPtr& cloud,
              pcl::tda::FilteredComplex& complex,
              BuildReport& report)
{
  builder.setInputCloud (cloud);
  builder.setRadius (options.radius);
  builder.setMaxDimension (
      triangleFree (options) ? 1 : static_cast<int> (options.dimension) + 1);
  // The default engine goes through the triangles it does not list: they are refused
  // over -memory as the listed ones are (a complete graph's ran for hours).
  builder.setTrianglesInMemoryLimit (triangleFree (options));
  builder.setMemoryLimit (options.memory_limit);
  pcl::tda::ProgressBar building ("  building");
  builder.setProgressCallback ([&building] (std::size_t done, std::size_t total) {
    building.update (done, total);
  });
  const bool built = builder.compute (complex);
  if (built)
    building.finish();
  report.skipped_points = builder.getNumSkippedPoints();
  return built;
}

/** Writes the diagram and the pictures and matrix asked for, to the temporary files
 * of \a outputs. */
void
writeOutputs (const Options& options,
              const pcl::tda::ToolOutputs& outputs,
              const pcl::tda::FilteredComplex& complex,
              const pcl::tda::PersistenceDiagram& diagram)
{
  pcl::tda::saveDiagramCSV (outputs.temporary (options.output), diagram);
  if (!options.phat_matrix.empty())
    pcl::tda::savePHATBoundaryMatrix (
        outputs.temporary (options.phat_matrix),
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
  plot.unit = "m";
  if (!options.barcode_svg.empty())
    pcl::tda::saveBarcodeSVG (outputs.temporary (options.barcode_svg), diagram, plot);
  if (!options.diagram_svg.empty())
    pcl::tda::savePersistenceDiagramSVG (
        outputs.temporary (options.diagram_svg), diagram, plot);
  if (options.png)
    for (const std::string& svg : {options.barcode_svg, options.diagram_svg})
      if (!svg.empty())
        pcl::tda::renderSVGToPNG (outputs.temporary (svg),
                                  outputs.temporary (pcl::tda::pngBesideSVG (svg)));
}

int
run (const Options& options, pcl::tda::ToolConsole& console)
{
  pcl::tda::ToolOutputs outputs (options.input,
                                 {{"output", options.output},
                                  {"-svg", options.barcode_svg},
                                  {"-diagram", options.diagram_svg},
                                  {"-export-phat", options.phat_matrix},
                                  {"-png", pngOutput (options, options.barcode_svg)},
                                  {"-png", pngOutput (options, options.diagram_svg)}});
  TicToc total;
  PhaseSeconds seconds;
  total.tic();

  Cloud::Ptr cloud (new Cloud);
  if (!console.loadInput (options.input, *cloud))
    return 1;
  pcl::tda::checkToolCoordinates (*cloud, options.radius, "-radius");
  if (options.leaf > 0.0) {
    pcl::tda::checkToolCoordinates (*cloud, options.leaf, "-leaf");
    try {
      cloud = pcl::tda::voxelGridFilter<pcl::PointXYZ> (cloud, options.leaf);
    }
    catch (const pcl::PCLException& error) {
      console.error (pcl::tda::errorMessage (error));
      return 1;
    }
  }
  seconds.load = console.stepMilliseconds() / 1000.0;
  console.endStep (std::to_string (cloud->size()) + " points");

  std::ostringstream radius;
  radius << options.radius;
  console.beginStep ("Building the Vietoris-Rips complex of radius", radius.str());
  pcl::tda::FilteredComplex complex;
  BuildReport report;
  bool built;
  if (options.gpu) {
    pcl::tda::gpu::VietorisRipsBuilder<pcl::PointXYZ> builder;
    built = buildComplex (builder, options, cloud, complex, report);
    report.builder = "gpu " + pcl::tda::gpu::backendName (builder.getBackend());
  }
  else {
    pcl::tda::VietorisRipsBuilder<pcl::PointXYZ> builder;
    builder.setNumberOfThreads (pcl::tda::threadsForPoints (0, cloud->size()));
    built = buildComplex (builder, options, cloud, complex, report);
  }
  if (!built) {
    console.endLine(); // the builder said why
    print_error ("For a complex over the memory limit: set a larger one with -memory M "
                 "(MiB), or use a smaller -radius or a voxel grid (-leaf).\n");
    const std::string coincident = pcl::tda::coincidentPointsAdvice (*cloud);
    if (!coincident.empty())
      print_error ("%s\n", coincident.c_str());
    return 1;
  }
  seconds.build = console.stepMilliseconds() / 1000.0;
  console.endStep (
      std::to_string (complex.numVertices()) + " points, " +
      std::to_string (complex.numEdges()) + " edges" +
      (triangleFree (options)
           ? " (triangles enumerated by H1)"
           : ", " + std::to_string (complex.numTriangles()) + " triangles") +
      (options.gpu ? ", " + report.builder : ""));

  console.beginStep ("Computing H0");
  pcl::tda::PersistenceResult result = pcl::tda::computeH0Persistence (complex);
  pcl::tda::PersistenceDiagram diagram = result.diagram (complex, 0);
  const std::size_t h0_intervals = diagram.size();
  seconds.h0 = console.stepMilliseconds() / 1000.0;
  console.endStep (std::to_string (h0_intervals) + " intervals");

  std::uint64_t num_triangles = complex.numTriangles();
  if (options.dimension == 1) {
    console.beginStep ("Computing H1 (" + pcl::tda::engineName (options.engine) + ")");
    pcl::tda::ProgressBar progress ("  reducing");
    const pcl::tda::ProgressCallback report_progress = [&progress] (std::size_t done,
                                                                    std::size_t total) {
      progress.update (done, total);
    };
    if (triangleFree (options)) {
      const pcl::tda::CliqueH1Persistence h1 = pcl::tda::computeCliqueH1Persistence (
          complex,
          result,
          pcl::tda::threadsForPoints (0, complex.numVertices()),
          report_progress);
      diagram.insert (diagram.end(), h1.diagram.begin(), h1.diagram.end());
      num_triangles = h1.num_triangles;
    }
    else {
      pcl::tda::addH1Persistence (complex, options.engine, result, report_progress);
      diagram = result.diagram (complex, 1);
    }
    progress.finish();
    seconds.h1 = console.stepMilliseconds() / 1000.0;
  }
  const std::size_t h1_intervals = diagram.size() - h0_intervals;
  if (options.dimension == 1)
    console.endStep (std::to_string (h1_intervals) + " intervals, " +
                     std::to_string (num_triangles) + " triangles");

  console.beginStep ("Saving", options.output);
  try {
    writeOutputs (options, outputs, complex, diagram);
    outputs.commit();
  }
  catch (const std::exception& error) {
    console.error (outputs.message (error));
    return 1;
  }
  seconds.write = console.stepMilliseconds() / 1000.0;
  console.endStep (std::to_string (diagram.size()) + " intervals");
  for (const std::string& file : {options.barcode_svg,
                                  pngOutput (options, options.barcode_svg),
                                  options.diagram_svg,
                                  pngOutput (options, options.diagram_svg),
                                  options.phat_matrix})
    if (!file.empty()) {
      print_info ("Written: ");
      print_value ("%s\n", file.c_str());
    }

  seconds.total = total.toc() / 1000.0;
  if (options.json)
    std::printf ("{\"points\": %zu, \"skipped_points\": %zu, \"edges\": %zu, "
                 "\"triangles\": %zu, \"intervals\": {\"0\": %zu, \"1\": %zu}, "
                 "\"seconds\": {\"load\": %.6f, \"build\": %.6f, \"h0\": %.6f, "
                 "\"h1\": %.6f, \"write\": %.6f, \"total\": %.6f}, "
                 "\"builder\": \"%s\"}\n",
                 complex.numVertices(),
                 report.skipped_points,
                 complex.numEdges(),
                 static_cast<std::size_t> (num_triangles),
                 h0_intervals,
                 h1_intervals,
                 seconds.load,
                 seconds.build,
                 seconds.h0,
                 seconds.h1,
                 seconds.write,
                 seconds.total,
                 report.builder.c_str());
  return 0;
}

} // namespace

int
main (int argc, char** argv)
{
  return pcl::tda::runTool<Options> (argc,
                                     argv,
                                     "Persistence barcodes of a point cloud.",
                                     printHelp,
                                     parseOptions,
                                     run);
}
