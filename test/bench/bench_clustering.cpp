// pcl_tda_bench_clustering: pcl::tda::PersistentEuclideanClusterExtraction (which
// also delivers the full H0 diagram) against pcl::EuclideanClusterExtraction on the
// same clouds with the same tolerance and size limits, each with its default search
// structure (ours: a uniform grid; PCL's: a k-d tree, built inside extract()):
// medians of several runs, min and max, the ratio, whether the clusters agree
// (identical with PCL's distance test option, and with our default test). Then the
// columns of thesis Table 4.1 (points, distance, simplices, time) for generated
// tabletop scenes after plane removal.
//
// Usage: pcl_tda_bench_clustering [data_dir] [-runs N]
// The readable report goes to stdout as markdown tables; the last stdout line is one
// JSON object. Exit status: 0 when all clusters agree, 2 when some differ, 1 on error.

#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/io/pcd_io.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/tda/apps/scene_preprocessing.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/tda/segmentation/persistent_euclidean_cluster_extraction.h>
#include <pcl/point_types.h>

#include "bench_command_line.h"
#include "segmentation/cluster_oracles.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Extraction = pcl::tda::PersistentEuclideanClusterExtraction<pcl::PointXYZ>;

struct Timing {
  double median = 0.0, min = 0.0, max = 0.0;
};

/** Runs \a work \a runs times (after one warm-up run) and returns the wall-clock
 * median, min and max in seconds. */
Timing
timeRuns (const std::function<void()>& work, int runs)
{
  work();
  std::vector<double> seconds;
  for (int run = 0; run < runs; ++run) {
    const auto start = std::chrono::steady_clock::now();
    work();
    seconds.push_back (
        std::chrono::duration<double> (std::chrono::steady_clock::now() - start)
            .count());
  }
  std::sort (seconds.begin(), seconds.end());
  return {seconds[seconds.size() / 2], seconds.front(), seconds.back()};
}

struct Input {
  std::string name;
  Cloud::Ptr cloud;
  double tolerance;
  pcl::uindex_t min_size;
  pcl::uindex_t max_size;
};

std::vector<pcl::PointIndices>
ours (const Input& input,
      bool pcl_distance_test,
      Extraction* out = nullptr,
      unsigned int threads = 0)
{
  Extraction local;
  Extraction& extraction = out ? *out : local;
  extraction.setInputCloud (input.cloud);
  extraction.setMaxDistance (input.tolerance);
  extraction.setMinClusterSize (input.min_size);
  extraction.setMaxClusterSize (input.max_size);
  extraction.setPCLDistanceTest (pcl_distance_test);
  extraction.setNumberOfThreads (threads);
  std::vector<pcl::PointIndices> clusters;
  extraction.extract (clusters);
  return clusters;
}

/** pcl::EuclideanClusterExtraction as a user runs it: a fresh k-d tree each time. */
std::vector<pcl::PointIndices>
theirs (const Input& input)
{
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> extraction;
  extraction.setInputCloud (input.cloud);
  extraction.setSearchMethod (
      pcl::search::KdTree<pcl::PointXYZ>::Ptr (new pcl::search::KdTree<pcl::PointXYZ>));
  extraction.setClusterTolerance (input.tolerance);
  extraction.setMinClusterSize (input.min_size);
  extraction.setMaxClusterSize (input.max_size);
  std::vector<pcl::PointIndices> clusters;
  extraction.extract (clusters);
  return clusters;
}

Cloud::Ptr
finitePoints (const Cloud& cloud)
{
  Cloud::Ptr finite (new Cloud);
  for (const auto& point : cloud)
    if (pcl::isXYZFinite (point))
      finite->push_back (point);
  return finite;
}

Cloud::Ptr
loadFinite (const std::string& path)
{
  Cloud cloud;
  if (pcl::io::loadPCDFile (path, cloud) < 0)
    throw std::runtime_error ("cannot read " + path);
  return finitePoints (cloud);
}

/** A generated tabletop scene (labels dropped). */
Cloud::Ptr
tabletop (float spacing, std::size_t objects, std::uint64_t seed, bool remove_table)
{
  pcl::tda::TabletopParameters parameters;
  parameters.seed = seed;
  parameters.num_objects = objects;
  parameters.point_spacing = spacing;
  parameters.noise_sigma = 0.001f;
  const pcl::tda::TabletopScene scene = pcl::tda::generateTabletopScene (parameters);
  Cloud::Ptr xyz (new Cloud);
  pcl::copyPointCloud (*scene.cloud, *xyz);
  if (!remove_table)
    return xyz;
  pcl::tda::ScenePreprocessing options;
  options.plane_distance = 0.01;
  return pcl::tda::preprocessScene (*xyz, options);
}

std::string
fixed (double value, int digits)
{
  char text[64];
  std::snprintf (text, sizeof text, "%.*f", digits, value);
  return text;
}

} // namespace

int
main (int argc, char** argv)
{
  if (pcl::tda::helpRequested (argc, argv)) {
    std::printf ("Usage: %s [data_dir] [-runs N]\n"
                 "  Times PersistentEuclideanClusterExtraction against "
                 "pcl::EuclideanClusterExtraction\n"
                 "  on the same inputs (medians of N >= 5 runs, default 7).\n",
                 argv[0]);
    return 0;
  }
  std::string data = "../shared/data";
  long runs_option = 7;
  try {
    pcl::tda::ToolCommandLine command_line;
    command_line.addInteger ("-runs", runs_option, 5, 1000);
    pcl::tda::bench::takeOptionalArgument (
        command_line.parse (argc, argv), "data folder", data);
  }
  catch (const pcl::PCLException& error) {
    std::fprintf (stderr, "%s\n", pcl::tda::errorMessage (error).c_str());
    return 1;
  }
  const int runs = static_cast<int> (runs_option);
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);

  std::vector<Input> inputs;
  try {
    Cloud raw;
    const std::string table_path = data + "/table_scene_mug_stereo_textured.pcd";
    if (pcl::io::loadPCDFile (table_path, raw) < 0)
      throw std::runtime_error ("cannot read " + table_path);
    // As PCL's cluster extraction tutorial: 1 cm voxel grid, plane removed, 2 cm.
    pcl::tda::ScenePreprocessing options;
    options.plane_distance = 0.02;
    options.leaf = 0.01;
    inputs.push_back ({"table scene (voxel 1 cm, plane removed)",
                       pcl::tda::preprocessScene (raw, options),
                       0.02,
                       100,
                       25000});
    inputs.push_back (
        {"milk.pcd", loadFinite (data + "/milk.pcd"), 0.005, 10, 1000000});
    inputs.push_back ({"car6.pcd", loadFinite (data + "/car6.pcd"), 0.2, 32, 1000000});
    // Spacing 2.7 mm on the default 1 m x 0.7 m table: about 100k points.
    inputs.push_back ({"generated tabletop (with table)",
                       tabletop (0.0027f, 6, 7, false),
                       0.006,
                       32,
                       1000000});
  }
  catch (const std::exception& error) {
    std::fprintf (stderr, "pcl_tda_bench_clustering: %s\n", error.what());
    return 1;
  }

  std::printf ("### Ours vs pcl::EuclideanClusterExtraction\n\n");
  std::printf (
      "| input | points | tolerance | min / max size | runs | ours s (min-max) | "
      "PCL s (min-max) | ours / PCL | ours 1 thread s | 1 thread / PCL | clusters | "
      "same as PCL (PCL's test) | same (our test) |\n");
  std::printf ("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  bool all_same = true;
  std::ostringstream json;
  json << "{\"runs\": " << runs << ", \"inputs\": [";
  double largest_ratio = 0.0;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const Input& input = inputs[k];
    std::vector<pcl::PointIndices> reference = theirs (input);
    pcl::tda::test::sortClusters (reference);
    const bool same_pcl_test =
        pcl::tda::test::sameClusters (ours (input, true), reference);
    const bool same_our_test =
        pcl::tda::test::sameClusters (ours (input, false), reference);
    all_same = all_same && same_pcl_test;
    const Timing our_time = timeRuns ([&] { ours (input, false); }, runs);
    const Timing pcl_time = timeRuns ([&] { theirs (input); }, runs);
    const Timing serial_time =
        timeRuns ([&] { ours (input, false, nullptr, 1); }, runs);
    const double ratio = our_time.median / pcl_time.median;
    largest_ratio = std::max (largest_ratio, ratio);
    const std::string max_size =
        input.max_size == 1000000 ? std::string ("-") : std::to_string (input.max_size);
    std::printf ("| %s | %zu | %g | %u / %s | %d | %s (%s-%s) | %s (%s-%s) | %.2f | %s "
                 "| %.2f | %zu "
                 "| %s | %s |\n",
                 input.name.c_str(),
                 input.cloud->size(),
                 input.tolerance,
                 input.min_size,
                 max_size.c_str(),
                 runs,
                 fixed (our_time.median, 4).c_str(),
                 fixed (our_time.min, 4).c_str(),
                 fixed (our_time.max, 4).c_str(),
                 fixed (pcl_time.median, 4).c_str(),
                 fixed (pcl_time.min, 4).c_str(),
                 fixed (pcl_time.max, 4).c_str(),
                 ratio,
                 fixed (serial_time.median, 4).c_str(),
                 serial_time.median / pcl_time.median,
                 reference.size(),
                 same_pcl_test ? "yes" : "DIFFER",
                 same_our_test ? "yes" : "no (rounding band)");
    json << (k ? ", " : "") << "{\"input\": \"" << input.name
         << "\", \"points\": " << input.cloud->size()
         << ", \"tolerance\": " << input.tolerance
         << ", \"ours_median_s\": " << our_time.median
         << ", \"pcl_median_s\": " << pcl_time.median << ", \"ratio\": " << ratio
         << ", \"ours_1_thread_median_s\": " << serial_time.median
         << ", \"clusters\": " << reference.size()
         << ", \"same\": " << (same_pcl_test ? "true" : "false") << "}";
  }

  std::printf ("\n### Table 4.1 columns: generated tabletop scenes, plane removed\n\n");
  std::printf ("| scene | points | distance | simplices (vertices + edges) | edges | "
               "clusters | time s (min-max) |\n|---|---|---|---|---|---|---|\n");
  int scene = 0;
  for (const float spacing : {0.01f, 0.005f, 0.0035f}) {
    ++scene;
    Input input{
        "", tabletop (spacing, 5, 20 + scene, true), 2.5 * spacing, 32, 1000000};
    Extraction extraction;
    const std::size_t clusters = ours (input, false, &extraction).size();
    const Timing time = timeRuns ([&] { ours (input, false); }, runs);
    std::printf ("| %d | %zu | %g | %zu | %zu | %zu | %s (%s-%s) |\n",
                 scene,
                 input.cloud->size(),
                 input.tolerance,
                 input.cloud->size() + extraction.getNumEdges(),
                 extraction.getNumEdges(),
                 clusters,
                 fixed (time.median, 4).c_str(),
                 fixed (time.min, 4).c_str(),
                 fixed (time.max, 4).c_str());
  }
  json << "], \"largest_ratio\": " << largest_ratio
       << ", \"all_same\": " << (all_same ? "true" : "false") << "}";
  std::printf ("\n%s\n", json.str().c_str());
  return all_same ? 0 : 2;
}
