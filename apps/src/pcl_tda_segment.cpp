// pcl_tda_segment: object segmentation of a tabletop frame by topological
// persistence (thesis Sec 4.1 and 4.4.1): depth cut-off, table plane removal,
// voxel grid, persistent Euclidean clustering; writes the labelled points and the
// H0 barcode.

#include <pcl/console/print.h>
#include <pcl/tda/apps/cloud_picture.h>
#include <pcl/tda/apps/coordinate_check.h>
#include <pcl/tda/apps/scene_preprocessing.h>
#include <pcl/tda/apps/svg_png.h>
#include <pcl/tda/apps/tool_console.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/apps/tool_outputs.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/segmentation/persistent_euclidean_cluster_extraction.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace pcl::console;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

namespace {

struct Options {
  std::string input, output, barcode_svg;
  pcl::tda::ScenePreprocessing preprocessing;
  double radius = 0.0;
  long min_size = 1;
  long max_size = std::numeric_limits<int>::max();
  bool automatic = false;
  double piece_ratio = pcl::tda::PersistentEuclideanClusterExtraction<
      pcl::PointXYZ>::DEFAULT_PIECE_RATIO;
  std::size_t memory_limit = pcl::tda::defaultMemoryLimit();
  bool png = false;
};

void
printHelp (const char* program)
{
  print_info ("Syntax is: %s input.pcd output.pcd -radius R <options>\n", program);
  print_info ("  Segments the objects of a tabletop frame: the preprocessed points, "
              "labelled by\n  cluster (label 0: in no cluster; 1, 2, ... by "
              "decreasing size, one colour each).\n");
  print_info ("  where options are:\n");
  print_info ("    -radius R   = largest distance within a cluster, the filtration's "
              "end (required, > 0)\n");
  print_info ("    -auto       = choose the distance from the H0 diagram, up to R\n");
  print_info (
      "    -piece P    = with -auto: a would-be cluster that joins one more than "
      "1/P times its\n                  size is a piece of it (default %g; 0 = "
      "none, where small objects\n                  stand next to big ones; "
      "< 1)\n",
      Options{}.piece_ratio);
  print_info ("    -min N      = smallest cluster, in points (default 1)\n");
  print_info ("    -max N      = largest cluster, in points (default: no limit; larger "
              "ones are dropped)\n");
  print_info ("    -range Z    = drop points of depth z > Z first (default 0 = off)\n");
  print_info ("    -plane 0|1  = remove the dominant plane by RANSAC (default 1)\n");
  print_info ("    -plane_dist D = distance to the plane of removed points (default "
              "0.01)\n");
  print_info ("    -leaf L     = voxel grid leaf applied last (default 0 = off)\n");
  print_info ("    -memory M   = most memory for the pairs of points listed at once, "
              "in MiB (default:\n                  half of the memory; beyond it the "
              "clusters come from slower searches)\n");
  print_info ("    -svg F.svg  = also draw the H0 barcode (with the chosen cut)\n");
  print_info (
      "    -png        = also write the SVG picture as PNG beside it (F.png)\n");
  print_info ("  Outputs are written only when the whole run succeeds.\n");
}

/** Reads the command line into \a options.
 * \throws pcl::BadArgumentException naming the option at fault */
void
parseOptions (int argc, char** argv, Options& options)
{
  const long max_int = std::numeric_limits<int>::max();
  long plane = 1;
  pcl::tda::ToolCommandLine command_line;
  command_line.addNumber (
      "-radius", options.radius, pcl::tda::NumberRange::above (0.0), true);
  command_line.addSwitch ("-auto", options.automatic);
  command_line.addNumber (
      "-piece", options.piece_ratio, pcl::tda::NumberRange::atLeastBelow (0.0, 1.0));
  command_line.addInteger ("-min", options.min_size, 1, max_int);
  command_line.addInteger ("-max", options.max_size, 1, max_int);
  command_line.addNumber (
      "-range", options.preprocessing.max_depth, pcl::tda::NumberRange::atLeast (0.0));
  command_line.addInteger ("-plane", plane, 0, 1);
  command_line.addNumber ("-plane_dist",
                          options.preprocessing.plane_distance,
                          pcl::tda::NumberRange::above (0.0));
  command_line.addNumber (
      "-leaf",
      options.preprocessing.leaf,
      pcl::tda::NumberRange::atLeast (0.0, std::numeric_limits<float>::max()));
  command_line.addMemory ("-memory", options.memory_limit);
  command_line.addText ("-svg", options.barcode_svg);
  command_line.addSwitch ("-png", options.png);
  const std::vector<std::string> files = command_line.parse (argc, argv);
  pcl::tda::checkArguments (files, {{"input", ".pcd"}, {"output", ".pcd"}});
  options.input = files[0];
  options.output = files[1];
  options.preprocessing.remove_plane = plane != 0;
  if (options.max_size < options.min_size)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "Need 1 <= -min <= -max, not " << options.min_size << " and "
                                                        << options.max_size << ".");
  if (command_line.given ("-piece") && !options.automatic)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException, "-piece has no use without -auto.");
  if (options.png && options.barcode_svg.empty())
    PCL_THROW_EXCEPTION (pcl::BadArgumentException, "-png has no use without -svg.");
  pcl::tda::checkOptionExtension ("-svg", options.barcode_svg, ".svg");
}

int
run (const Options& options, pcl::tda::ToolConsole& console)
{
  const std::string barcode_png =
      options.png ? pcl::tda::pngBesideSVG (options.barcode_svg) : "";
  pcl::tda::ToolOutputs outputs (options.input,
                                 {{"output", options.output},
                                  {"-svg", options.barcode_svg},
                                  {"-png", barcode_png}});
  Cloud::Ptr cloud (new Cloud);
  if (!console.loadInput (options.input, *cloud))
    return 1;
  pcl::tda::checkToolCoordinates (*cloud, options.radius, "-radius");
  if (options.preprocessing.leaf > 0.0)
    pcl::tda::checkToolCoordinates (*cloud, options.preprocessing.leaf, "-leaf");
  console.endStep (std::to_string (cloud->size()) + " points" +
                   (cloud->isOrganized() ? " (organized)" : ""));

  console.beginStep ("Preprocessing");
  pcl::tda::PreprocessingCounts counts;
  Cloud::Ptr points;
  try {
    points = pcl::tda::preprocessScene (*cloud, options.preprocessing, &counts);
  }
  catch (const pcl::PCLException& error) {
    console.error ("Cannot preprocess " + options.input + ": " +
                   pcl::tda::errorMessage (error));
    return 1;
  }
  std::ostringstream preprocessed;
  preprocessed << points->size() << " points; removed " << counts.non_finite
               << " non-finite, " << counts.beyond_depth << " beyond range, "
               << counts.plane << " on the plane";
  console.endStep (preprocessed.str());

  console.beginStep ("Clustering");
  pcl::tda::PersistentEuclideanClusterExtraction<pcl::PointXYZ> extraction;
  extraction.setInputCloud (points);
  extraction.setMaxDistance (options.radius);
  extraction.setMinClusterSize (options.min_size);
  extraction.setMaxClusterSize (options.max_size);
  extraction.setAutoMaxDistance (options.automatic);
  extraction.setAutoPieceRatio (options.piece_ratio);
  // The automatic distance never goes below the voxel grid's spacing, nor below
  // what the coordinates resolve (as the check of -radius above).
  extraction.setAutoMinDistance (
      std::max (options.preprocessing.leaf, pcl::tda::smallestResolvedScale (*points)));
  extraction.setMemoryLimit (options.memory_limit);
  std::vector<pcl::PointIndices> clusters;
  extraction.extract (clusters);
  if (extraction.getPersistenceDiagram().empty()) {
    console.error ("Clustering failed (see above).");
    return 1;
  }
  std::ostringstream clustered;
  clustered << pcl::tda::countOf (clusters.size(), "cluster") << " at distance "
            << extraction.getChosenDistance() << (options.automatic ? " (chosen)" : "")
            << ", " << extraction.getNumEdges() << " edges";
  console.endStep (clustered.str());

  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  pcl::copyPointCloud (*points, labelled);
  for (auto& point : labelled) {
    point.label = 0;
    point.r = point.g = point.b = 128;
  }
  constexpr std::size_t MAX_LINES = 30;
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    const auto colour = pcl::tda::labelColor (c + 1);
    Eigen::Vector4f centroid = Eigen::Vector4f::Zero();
    for (const auto index : clusters[c].indices) {
      auto& point = labelled[index];
      point.label = static_cast<std::uint32_t> (c + 1);
      point.r = colour[0];
      point.g = colour[1];
      point.b = colour[2];
      centroid += point.getVector4fMap();
    }
    centroid /= static_cast<float> (clusters[c].indices.size());
    if (c < MAX_LINES)
      print_info ("  cluster %zu: %zu points, centroid (%g, %g, %g)\n",
                  c + 1,
                  clusters[c].indices.size(),
                  centroid[0],
                  centroid[1],
                  centroid[2]);
  }
  if (clusters.size() > MAX_LINES)
    print_info ("  ... and %zu smaller clusters\n", clusters.size() - MAX_LINES);

  console.beginStep ("Saving", options.output);
  try {
    pcl::tda::savePointCloudFile (outputs.temporary (options.output), labelled);
    if (!options.barcode_svg.empty()) {
      pcl::tda::PlotOptions plot;
      std::ostringstream title;
      title << options.input << ": H0, radius " << options.radius << ", "
            << pcl::tda::countOf (clusters.size(), "cluster");
      plot.title = title.str();
      plot.max_value = options.radius;
      plot.unit = "m";
      plot.cut = extraction.getChosenDistance();
      pcl::tda::saveBarcodeSVG (outputs.temporary (options.barcode_svg),
                                extraction.getPersistenceDiagram(),
                                plot);
      if (options.png)
        pcl::tda::renderSVGToPNG (outputs.temporary (options.barcode_svg),
                                  outputs.temporary (barcode_png));
    }
    outputs.commit();
  }
  catch (const std::exception& error) {
    console.error (outputs.message (error));
    return 1;
  }
  console.endStep (std::to_string (labelled.size()) + " labelled points");
  return 0;
}

} // namespace

int
main (int argc, char** argv)
{
  return pcl::tda::runTool<Options> (argc,
                                     argv,
                                     "Object segmentation by topological persistence.",
                                     printHelp,
                                     parseOptions,
                                     run);
}
