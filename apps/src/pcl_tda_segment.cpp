// pcl_tda_segment: object segmentation of a tabletop frame by topological
// persistence (thesis Sec 4.1 and 4.4.1): depth cut-off, table plane removal,
// voxel grid, persistent Euclidean clustering; writes the labelled points and the
// H0 barcode.

#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/scene_preprocessing.h>
#include <pcl/tda/apps/tool_console.h>
#include <pcl/tda/common/atomic_file.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/tda/segmentation/persistent_euclidean_cluster_extraction.h>
#include <pcl/point_types.h>

#include <array>
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
  int min_size = 1;
  int max_size = std::numeric_limits<int>::max();
  bool automatic = false;
};

void
printHelp (const char* program)
{
  print_error ("Syntax is: %s input.pcd output.pcd -radius R <options>\n", program);
  print_info ("  Segments the objects of a tabletop frame: the preprocessed points, "
              "labelled by\n  cluster (label 0: in no cluster; 1, 2, ... by "
              "decreasing size, one colour each).\n");
  print_info ("  where options are:\n");
  print_info ("    -radius R   = largest distance within a cluster, the filtration's "
              "end (required, > 0)\n");
  print_info ("    -auto       = choose the distance from the H0 diagram, up to R\n");
  print_info ("    -min N      = smallest cluster, in points (default 1)\n");
  print_info ("    -max N      = largest cluster, in points (default: no limit; larger "
              "ones are dropped)\n");
  print_info ("    -range Z    = drop points of depth z > Z first (default 0 = off)\n");
  print_info ("    -plane 0|1  = remove the dominant plane by RANSAC (default 1)\n");
  print_info ("    -plane_dist D = distance to the plane of removed points (default "
              "0.01)\n");
  print_info ("    -leaf L     = voxel grid leaf applied last (default 0 = off)\n");
  print_info ("    -svg F.svg  = also draw the H0 barcode\n");
}

bool
parseOptions (int argc, char** argv, Options& options)
{
  const std::vector<int> pcd_files = parse_file_extension_argument (argc, argv, ".pcd");
  if (pcd_files.size() != 2) {
    print_error ("Need one input and one output PCD file.\n");
    return false;
  }
  options.input = argv[pcd_files[0]];
  options.output = argv[pcd_files[1]];
  if (parse_argument (argc, argv, "-radius", options.radius) < 0) {
    print_error ("The -radius R option is required.\n");
    return false;
  }
  int plane = 1;
  parse_argument (argc, argv, "-plane", plane);
  parse_argument (argc, argv, "-plane_dist", options.preprocessing.plane_distance);
  parse_argument (argc, argv, "-range", options.preprocessing.max_depth);
  parse_argument (argc, argv, "-leaf", options.preprocessing.leaf);
  parse_argument (argc, argv, "-min", options.min_size);
  parse_argument (argc, argv, "-max", options.max_size);
  parse_argument (argc, argv, "-svg", options.barcode_svg);
  options.automatic = find_switch (argc, argv, "-auto");
  options.preprocessing.remove_plane = plane != 0;
  if (!(options.radius > 0.0) || !std::isfinite (options.radius)) {
    print_error ("The radius must be a positive number, not %g.\n", options.radius);
    return false;
  }
  if (plane != 0 && plane != 1) {
    print_error ("-plane must be 0 or 1, not %d.\n", plane);
    return false;
  }
  if (!(options.preprocessing.max_depth >= 0.0) ||
      !(options.preprocessing.leaf >= 0.0) ||
      !(options.preprocessing.plane_distance > 0.0)) {
    print_error ("-range and -leaf must be >= 0 and -plane_dist > 0.\n");
    return false;
  }
  if (options.min_size < 1 || options.max_size < options.min_size) {
    print_error (
        "Need 1 <= -min <= -max, not %d and %d.\n", options.min_size, options.max_size);
    return false;
  }
  return !pcl::tda::overwritesInput (options.input,
                                     {options.output, options.barcode_svg});
}

/** A colour per label: grey for 0, then well-separated hues. */
std::array<std::uint8_t, 3>
labelColour (std::size_t label)
{
  static const std::array<std::array<std::uint8_t, 3>, 12> PALETTE{{{230, 25, 75},
                                                                    {60, 180, 75},
                                                                    {0, 130, 200},
                                                                    {245, 130, 48},
                                                                    {145, 30, 180},
                                                                    {70, 240, 240},
                                                                    {240, 50, 230},
                                                                    {210, 245, 60},
                                                                    {250, 190, 212},
                                                                    {0, 128, 128},
                                                                    {170, 110, 40},
                                                                    {128, 0, 0}}};
  if (label == 0)
    return {128, 128, 128};
  return PALETTE[(label - 1) % PALETTE.size()];
}

int
run (const Options& options)
{
  TicToc timer;
  timer.tic();
  Cloud::Ptr cloud (new Cloud);
  if (!pcl::tda::loadToolInput (options.input, *cloud))
    return 1;
  pcl::tda::printDone (timer,
                       std::to_string (cloud->size()) + " points" +
                           (cloud->isOrganized() ? " (organized)" : ""));

  timer.tic();
  print_highlight ("Preprocessing ");
  pcl::tda::PreprocessingCounts counts;
  Cloud::Ptr points;
  try {
    points = pcl::tda::preprocessScene (*cloud, options.preprocessing, &counts);
  }
  catch (const pcl::PCLException& error) {
    print_error ("\nCannot preprocess %s: %s\n",
                 options.input.c_str(),
                 pcl::tda::errorMessage (error).c_str());
    return 1;
  }
  std::ostringstream preprocessed;
  preprocessed << points->size() << " points; removed " << counts.non_finite
               << " non-finite, " << counts.beyond_depth << " beyond range, "
               << counts.plane << " on the plane";
  pcl::tda::printDone (timer, preprocessed.str());

  timer.tic();
  print_highlight ("Clustering ");
  pcl::tda::PersistentEuclideanClusterExtraction<pcl::PointXYZ> extraction;
  extraction.setInputCloud (points);
  extraction.setMaxDistance (options.radius);
  extraction.setMinClusterSize (options.min_size);
  extraction.setMaxClusterSize (options.max_size);
  extraction.setAutoMaxDistance (options.automatic);
  std::vector<pcl::PointIndices> clusters;
  extraction.extract (clusters);
  if (extraction.getPersistenceDiagram().empty()) {
    print_error ("Clustering failed (see above).\n");
    return 1;
  }
  std::ostringstream clustered;
  clustered << clusters.size() << " clusters at distance "
            << extraction.getChosenDistance() << (options.automatic ? " (chosen)" : "")
            << ", " << extraction.getNumEdges() << " edges";
  pcl::tda::printDone (timer, clustered.str());

  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  pcl::copyPointCloud (*points, labelled);
  for (auto& point : labelled) {
    point.label = 0;
    point.r = point.g = point.b = 128;
  }
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    const auto colour = labelColour (c + 1);
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
    print_info ("  cluster %zu: %zu points, centroid (%.3f, %.3f, %.3f)\n",
                c + 1,
                clusters[c].indices.size(),
                centroid[0],
                centroid[1],
                centroid[2]);
  }

  timer.tic();
  print_highlight ("Saving ");
  print_value ("%s ", options.output.c_str());
  try {
    pcl::tda::savePointCloudFile (options.output, labelled);
    if (!options.barcode_svg.empty()) {
      pcl::tda::PlotOptions plot;
      std::ostringstream title;
      title << options.input << ": H0, radius " << options.radius << ", "
            << clusters.size() << " clusters";
      plot.title = title.str();
      plot.max_value = options.radius;
      pcl::tda::saveBarcodeSVG (
          options.barcode_svg, extraction.getPersistenceDiagram(), plot);
    }
  }
  catch (const std::exception& error) {
    print_error ("\n%s\n", pcl::tda::errorMessage (error).c_str());
    return 1;
  }
  pcl::tda::printDone (timer, std::to_string (labelled.size()) + " labelled points");
  return 0;
}

} // namespace

int
main (int argc, char** argv)
{
  print_info ("Object segmentation by topological persistence. For more information, "
              "use: %s -h\n",
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
