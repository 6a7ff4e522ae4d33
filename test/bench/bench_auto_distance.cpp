// pcl_tda_bench_auto_distance: validation of the automatic cluster distance of
// pcl::tda::PersistentEuclideanClusterExtraction (setAutoMaxDistance(true)) on data
// made differently from the data it was tuned on, as doc EVALUATION.md asks.
//
// Generated scenes, table removed by the ground-truth labels, NaNs dropped, optionally
// a voxel grid: our tabletop generator (the rule was tuned on it) and the independent
// depth camera generator, and scenes made of the real object scans of the data
// folder. Per generator: object F1 at IoU 0.5 of the automatic
// distance (max distance 0.1 m), of pcl::EuclideanClusterExtraction at the tolerance
// of a sweep with the best mean F1 over that generator's scenes, and of a fixed 1 cm
// for reference. Then the real scans of the data folder: the chosen distance, the
// clusters, the share of points labelled and the nearest-neighbour spacing.
//
// Usage: pcl_tda_bench_auto_distance [data_dir] [-scenes N] [-seed S] [-leaf L]
//                                    [-min M]
// The readable report goes to stdout as markdown tables; the last stdout line is one
// JSON object. Exit status: 0 after the report, 1 on bad options or errors.

#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/search/kdtree.h>
#include <pcl/tda/apps/scene_preprocessing.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/tda/segmentation/persistent_euclidean_cluster_extraction.h>
#include <pcl/point_types.h>

#include "bench_command_line.h"
#include "bench_statistics.h"
#include "segmentation/cluster_oracles.h"
#include "segmentation/real_object_scenes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using pcl::tda::bench::mean;
using pcl::tda::bench::median;

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using LabelledCloud = pcl::PointCloud<pcl::PointXYZRGBL>;
using Extraction = pcl::tda::PersistentEuclideanClusterExtraction<pcl::PointXYZ>;
using pcl::tda::test::ObjectScores;

/** Ground-truth objects with fewer visible points are not counted (EVALUATION.md). */
constexpr std::size_t MIN_VISIBLE_POINTS = 30;
/** Upper bound of the automatic distance's search, in metres. */
constexpr double AUTO_MAX_DISTANCE = 0.1;
/** The fixed reference distance, in metres. */
constexpr double FIXED_DISTANCE = 0.01;
/** The swept tolerances of pcl::EuclideanClusterExtraction, in metres. */
const std::vector<double> TOLERANCES = {0.0025,
                                        0.00375,
                                        0.005,
                                        0.00625,
                                        0.0075,
                                        0.00875,
                                        0.01,
                                        0.0125,
                                        0.015,
                                        0.0175,
                                        0.02,
                                        0.025,
                                        0.03,
                                        0.04,
                                        0.05};

struct Options {
  std::string data = PCL_TDA_DATA_DIR;
  std::size_t scenes = 60;
  std::uint64_t seed = 1000;
  double leaf = 0.0;
  pcl::uindex_t min_size = 20;
};

void
printUsage (std::FILE* stream)
{
  std::fprintf (
      stream,
      "Usage: pcl_tda_bench_auto_distance [data_dir] [options]\n"
      "  data_dir    folder of the real scans (default %s)\n"
      "  -scenes N   scenes per generator (default 60)\n"
      "  -seed S     seed of the first scene (default 1000)\n"
      "  -leaf L     voxel grid leaf on the generated scenes, metres (default 0 = "
      "off)\n"
      "  -min M      minimum cluster size (default 20)\n"
      "  -h          this help\n",
      PCL_TDA_DATA_DIR);
}

/** Parses the command line into \a options (the tools' strict parser).
 * \throws pcl::BadArgumentException naming the option at fault */
void
parseOptions (int argc, char** argv, Options& options)
{
  long scenes = static_cast<long> (options.scenes), seed = 1000, min_size = 20;
  pcl::tda::ToolCommandLine command_line;
  command_line.addInteger ("-scenes", scenes, 1, 100000);
  command_line.addInteger ("-seed", seed, 0, std::numeric_limits<long>::max());
  command_line.addNumber ("-leaf", options.leaf, pcl::tda::NumberRange::atLeast (0.0));
  command_line.addInteger ("-min", min_size, 1, std::numeric_limits<int>::max());
  pcl::tda::bench::takeOptionalArgument (
      command_line.parse (argc, argv), "data folder", options.data);
  options.scenes = static_cast<std::size_t> (scenes);
  options.seed = static_cast<std::uint64_t> (seed);
  options.min_size = static_cast<pcl::uindex_t> (min_size);
}

/** Median distance from a point to its nearest other point. */
double
medianSpacing (const Cloud::ConstPtr& cloud)
{
  pcl::search::KdTree<pcl::PointXYZ> tree;
  tree.setInputCloud (cloud);
  pcl::Indices neighbours;
  std::vector<float> squared_distances;
  std::vector<double> spacing;
  for (const auto& point : *cloud)
    if (tree.nearestKSearch (point, 2, neighbours, squared_distances) == 2)
      spacing.push_back (std::sqrt (squared_distances[1]));
  return median (spacing);
}

/** A generated scene ready for clustering: the points and the ground-truth label of
 * each (1.. the objects with at least MIN_VISIBLE_POINTS points, 0 the rest). */
struct Scene {
  Cloud::Ptr cloud;
  std::vector<std::uint32_t> labels;
  std::size_t objects = 0;
};

/** Drops the NaNs and the points labelled \a table, applies the voxel grid (labels
 * by majority), relabels the objects from 1. */
Scene
prepare (const LabelledCloud& generated,
         std::uint32_t table,
         std::uint32_t first_object,
         double leaf)
{
  LabelledCloud::Ptr kept (new LabelledCloud);
  for (const auto& point : generated)
    if (pcl::isXYZFinite (point) && point.label != table)
      kept->push_back (point);
  if (leaf > 0.0)
    kept = pcl::tda::voxelGridFilter<pcl::PointXYZRGBL> (kept, leaf);
  std::map<std::uint32_t, std::size_t> sizes;
  for (const auto& point : *kept)
    ++sizes[point.label];
  Scene scene;
  scene.cloud.reset (new Cloud);
  pcl::copyPointCloud (*kept, *scene.cloud);
  for (const auto& point : *kept)
    scene.labels.push_back (point.label >= first_object &&
                                    sizes[point.label] >= MIN_VISIBLE_POINTS
                                ? point.label - first_object + 1
                                : 0);
  for (const auto& [label, size] : sizes)
    scene.objects += label >= first_object && size >= MIN_VISIBLE_POINTS;
  return scene;
}

/** A generator of scenes, by index. */
struct Generator {
  std::string name;
  std::string description;
  std::function<Scene (std::size_t)> scene;
};

/** Scores of one method over a generator's scenes. */
struct MethodScores {
  std::vector<double> f1, precision, recall, distance, seconds;
  ObjectScores pooled;

  void
  add (const ObjectScores& scores, double chosen_distance, double time)
  {
    f1.push_back (scores.f1());
    precision.push_back (scores.clusters ? double (scores.matched) / scores.clusters
                                         : 1.0);
    recall.push_back (scores.objects ? double (scores.matched) / scores.objects : 1.0);
    distance.push_back (chosen_distance);
    seconds.push_back (time);
    pooled.add (scores);
  }
};

/** Runs \a work and returns its wall-clock seconds. */
double
timed (const std::function<void()>& work)
{
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double> (std::chrono::steady_clock::now() - start)
      .count();
}

/** Our clusters at a fixed or automatic distance; the distance used in
 * \a chosen. */
std::vector<pcl::PointIndices>
ours (const Cloud::Ptr& cloud,
      bool automatic,
      double distance,
      pcl::uindex_t min_size,
      double& chosen)
{
  Extraction extraction;
  extraction.setInputCloud (cloud);
  extraction.setAutoMaxDistance (automatic);
  extraction.setMaxDistance (distance);
  extraction.setMinClusterSize (min_size);
  std::vector<pcl::PointIndices> clusters;
  extraction.extract (clusters);
  chosen = extraction.getChosenDistance();
  return clusters;
}

std::string
fixed (double value, int digits)
{
  char text[64];
  std::snprintf (text, sizeof text, "%.*f", digits, value);
  return text;
}

/** Millimetres with one decimal. */
std::string
mm (double metres)
{
  return fixed (1000.0 * metres, 1);
}

/** A table row and a JSON object for one method. */
void
report (const std::string& method,
        const std::string& json_name,
        const MethodScores& scores,
        std::ostringstream& json)
{
  const auto perfect = std::count_if (
      scores.f1.begin(), scores.f1.end(), [] (double f) { return f == 1.0; });
  const auto [low, high] =
      std::minmax_element (scores.distance.begin(), scores.distance.end());
  std::printf ("| %s | %s (%s-%s) | %s | %s | %s | %s | %zd / %zu | %s |\n",
               method.c_str(),
               mm (median (scores.distance)).c_str(),
               mm (*low).c_str(),
               mm (*high).c_str(),
               fixed (mean (scores.f1), 3).c_str(),
               fixed (scores.pooled.f1(), 3).c_str(),
               fixed (mean (scores.precision), 3).c_str(),
               fixed (mean (scores.recall), 3).c_str(),
               static_cast<std::ptrdiff_t> (perfect),
               scores.f1.size(),
               fixed (mean (scores.seconds), 4).c_str());
  json << "\"" << json_name << "\": {\"mean_f1\": " << mean (scores.f1)
       << ", \"pooled_f1\": " << scores.pooled.f1()
       << ", \"mean_precision\": " << mean (scores.precision)
       << ", \"mean_recall\": " << mean (scores.recall)
       << ", \"median_distance\": " << median (scores.distance)
       << ", \"scenes_f1_1\": " << perfect << "}";
}

/** Runs the three methods on the scenes of \a generator and prints its table. */
void
evaluate (const Generator& generator, const Options& options, std::ostringstream& json)
{
  MethodScores automatic, reference;
  std::vector<MethodScores> sweep (TOLERANCES.size());
  std::vector<double> points, objects, spacing;
  for (std::size_t i = 0; i < options.scenes; ++i) {
    std::fprintf (
        stderr, "\r%s: scene %zu / %zu", generator.name.c_str(), i + 1, options.scenes);
    const Scene scene = generator.scene (i);
    points.push_back (static_cast<double> (scene.cloud->size()));
    objects.push_back (static_cast<double> (scene.objects));
    spacing.push_back (medianSpacing (scene.cloud));
    double chosen = 0.0;
    std::vector<pcl::PointIndices> clusters;
    double seconds = timed ([&] {
      clusters = ours (scene.cloud, true, AUTO_MAX_DISTANCE, options.min_size, chosen);
    });
    automatic.add (
        pcl::tda::test::scoreObjects (scene.labels, clusters, 1), chosen, seconds);
    seconds = timed ([&] {
      clusters = ours (scene.cloud, false, FIXED_DISTANCE, options.min_size, chosen);
    });
    reference.add (
        pcl::tda::test::scoreObjects (scene.labels, clusters, 1), chosen, seconds);
    for (std::size_t k = 0; k < TOLERANCES.size(); ++k) {
      seconds = timed ([&] {
        clusters = pcl::tda::test::pclEuclideanClusters<pcl::PointXYZ> (
            scene.cloud, TOLERANCES[k], options.min_size);
      });
      sweep[k].add (pcl::tda::test::scoreObjects (scene.labels, clusters, 1),
                    TOLERANCES[k],
                    seconds);
    }
  }
  std::fprintf (stderr, "\n");
  std::size_t best = 0;
  for (std::size_t k = 1; k < TOLERANCES.size(); ++k)
    if (mean (sweep[k].f1) > mean (sweep[best].f1))
      best = k;

  std::printf ("\n### %s\n\n%s; %zu scenes; per scene: %s points, %s objects of "
               ">= %zu points (means), nearest-neighbour spacing %s mm (median)\n\n",
               generator.name.c_str(),
               generator.description.c_str(),
               options.scenes,
               fixed (mean (points), 0).c_str(),
               fixed (mean (objects), 2).c_str(),
               MIN_VISIBLE_POINTS,
               mm (median (spacing)).c_str());
  std::printf ("| method | distance mm: median (min-max) | mean F1 | pooled F1 | "
               "mean precision | mean recall | scenes F1 = 1 | mean s |\n"
               "|---|---|---|---|---|---|---|---|\n");
  json << "{\"generator\": \"" << generator.name << "\", \"scenes\": " << options.scenes
       << ", \"median_spacing\": " << median (spacing) << ", ";
  report ("ours, automatic (max 0.1 m)", "auto", automatic, json);
  json << ", ";
  report ("pcl::EuclideanClusterExtraction, best swept tolerance",
          "pcl_best",
          sweep[best],
          json);
  json << ", ";
  report ("ours, fixed 1 cm", "fixed_1cm", reference, json);
  std::printf ("\nSweep of pcl::EuclideanClusterExtraction (tolerance mm: mean F1): ");
  json << ", \"sweep\": [";
  for (std::size_t k = 0; k < TOLERANCES.size(); ++k) {
    std::printf ("%s%s: %s",
                 k ? ", " : "",
                 mm (TOLERANCES[k]).c_str(),
                 fixed (mean (sweep[k].f1), 3).c_str());
    json << (k ? ", " : "") << "[" << TOLERANCES[k] << ", " << mean (sweep[k].f1)
         << "]";
  }
  std::printf ("\n");
  json << "]}";
}

/** A real scan, its preprocessing and the automatic distance's settings. */
struct RealScan {
  std::string file;
  std::string steps;
  pcl::tda::ScenePreprocessing preprocessing;
  double max_distance;
  pcl::uindex_t min_size;
};

/** Runs the automatic distance on the real scans present in the data folder. */
void
evaluateRealScans (const Options& options, std::ostringstream& json)
{
  pcl::tda::ScenePreprocessing table;
  table.max_depth = 1.5;
  table.leaf = 0.005;
  pcl::tda::ScenePreprocessing kinect;
  kinect.leaf = 0.02;
  pcl::tda::ScenePreprocessing as_is;
  as_is.remove_plane = false;
  const std::vector<RealScan> scans = {
      {"table_scene_mug_stereo_textured.pcd",
       "z < 1.5, plane removed, voxel 5 mm",
       table,
       AUTO_MAX_DISTANCE,
       options.min_size},
      {"kinect_frame.pcd",
       "plane removed, voxel 2 cm",
       kinect,
       AUTO_MAX_DISTANCE,
       options.min_size},
      {"car6.pcd", "as is", as_is, 0.5, 10},
      {"milk.pcd", "as is", as_is, AUTO_MAX_DISTANCE, options.min_size},
  };
  std::printf ("\n### Real scans (%s)\n\n", options.data.c_str());
  json << "[";
  if (!std::filesystem::is_directory (options.data)) {
    std::printf ("skipped: %s is absent\n", options.data.c_str());
    json << "]";
    return;
  }
  std::printf (
      "| scan | preprocessing | points | NN spacing mm (median) | max distance "
      "/ min size | chosen distance mm | clusters | labelled | largest "
      "clusters |\n|---|---|---|---|---|---|---|---|---|\n");
  bool first = true;
  for (const RealScan& scan : scans) {
    const std::string path = options.data + "/" + scan.file;
    Cloud raw;
    if (!std::filesystem::is_regular_file (path) ||
        pcl::io::loadPCDFile (path, raw) < 0) {
      std::printf (
          "| %s | skipped: cannot read %s |\n", scan.file.c_str(), path.c_str());
      continue;
    }
    const Cloud::Ptr cloud = pcl::tda::preprocessScene (raw, scan.preprocessing);
    double chosen = 0.0;
    const std::vector<pcl::PointIndices> clusters =
        ours (cloud, true, scan.max_distance, scan.min_size, chosen);
    std::size_t labelled = 0;
    std::string largest;
    for (std::size_t k = 0; k < clusters.size(); ++k) {
      labelled += clusters[k].indices.size();
      if (k < 4)
        largest += (k ? ", " : "") + std::to_string (clusters[k].indices.size());
    }
    const double spacing = medianSpacing (cloud);
    const double share = static_cast<double> (labelled) / cloud->size();
    std::printf ("| %s | %s | %zu | %s | %g / %u | %s | %zu | %s%% | %s |\n",
                 scan.file.c_str(),
                 scan.steps.c_str(),
                 cloud->size(),
                 mm (spacing).c_str(),
                 scan.max_distance,
                 scan.min_size,
                 fixed (1000.0 * chosen, 2).c_str(),
                 clusters.size(),
                 fixed (100.0 * share, 1).c_str(),
                 largest.c_str());
    json << (first ? "" : ", ") << "{\"scan\": \"" << scan.file
         << "\", \"points\": " << cloud->size() << ", \"median_spacing\": " << spacing
         << ", \"chosen_distance\": " << chosen << ", \"clusters\": " << clusters.size()
         << ", \"labelled\": " << share << "}";
    first = false;
  }
  json << "]";
}

} // namespace

int
main (int argc, char** argv)
{
  Options options;
  if (const auto stop = pcl::tda::bench::parseCommandLine (
          argc, argv, options, parseOptions, printUsage))
    return *stop;

  std::vector<Generator> generators = {
      {"tabletop (ours; the rule was tuned on it)",
       "boxes, cylinders and spheres, 3-6 objects at least 5 cm apart, 1 cm "
       "sampling, depth noise 1 mm at 1 m, table removed by its label",
       [&] (std::size_t i) {
         pcl::tda::TabletopParameters parameters;
         parameters.seed = options.seed + i;
         parameters.num_objects = 3 + i % 4;
         const pcl::tda::TabletopScene scene =
             pcl::tda::generateTabletopScene (parameters);
         return prepare (*scene.cloud,
                         pcl::tda::TABLE_LABEL,
                         pcl::tda::FIRST_OBJECT_LABEL,
                         options.leaf);
       }},
      {"depth camera (independent)",
       "bowls, cones, rings, L-blocks and lying capsules, 3-6 objects 1-3 cm or "
       ">= 6 cm apart, 640 x 480 pinhole camera at 0.8-1.5 m and 30-60 degrees, "
       "noise 1.5e-3 z^2, disparity quantized to 1/8 pixel, grazing dropouts and "
       "projector shadows, table removed by its label",
       [&] (std::size_t i) {
         pcl::tda::DepthCameraParameters parameters;
         parameters.seed = options.seed + i;
         const pcl::tda::DepthCameraScene scene =
             pcl::tda::generateDepthCameraScene (parameters);
         return prepare (*scene.cloud,
                         pcl::tda::DEPTH_BACKGROUND_LABEL,
                         pcl::tda::DEPTH_FIRST_OBJECT_LABEL,
                         options.leaf);
       }},
  };
  const auto scans = pcl::tda::test::loadRealObjectScans (options.data);
  if (scans.empty())
    std::fprintf (stderr,
                  "real-object scenes skipped: cannot read the object scans from "
                  "%s\n",
                  options.data.c_str());
  else
    generators.push_back (
        {"real objects (scans; made differently)",
         "3-6 object scans of the data folder (milk.pcd, rops_cloud.pcd, car6.pcd) "
         "as random subsamples of 1,000-4,000 points, turned at random, scaled to "
         "10-25 cm, placed at least 1.5 cm apart in a 0.8 m square; no table, no "
         "added noise",
         [&] (std::size_t i) {
           return prepare (
               pcl::tda::test::makeRealObjectScene (scans, options.seed + i),
               0,
               1,
               options.leaf);
         }});

  std::ostringstream json;
  try {
    std::printf ("## Automatic cluster distance: object F1 at IoU >= 0.5\n\n"
                 "Seed %llu, minimum cluster size %u, voxel leaf %s; ground-truth "
                 "objects with fewer than %zu points are not counted.\n",
                 static_cast<unsigned long long> (options.seed),
                 options.min_size,
                 options.leaf > 0.0 ? (mm (options.leaf) + " mm").c_str() : "off",
                 MIN_VISIBLE_POINTS);
    json << "{\"scenes\": " << options.scenes << ", \"seed\": " << options.seed
         << ", \"min_size\": " << options.min_size << ", \"leaf\": " << options.leaf
         << ", \"generators\": [";
    for (std::size_t g = 0; g < generators.size(); ++g) {
      json << (g ? ", " : "");
      evaluate (generators[g], options, json);
    }
    json << "], \"real_scans\": ";
    evaluateRealScans (options, json);
    json << "}";
  }
  catch (const std::exception& error) {
    std::fprintf (stderr, "pcl_tda_bench_auto_distance: %s\n", error.what());
    return 1;
  }
  std::printf ("\n%s\n", json.str().c_str());
  return 0;
}
