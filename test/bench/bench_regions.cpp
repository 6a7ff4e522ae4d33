// pcl_tda_bench_regions: pcl::tda::PersistentRegionGrowingRGB with the defaults of
// pcl_tda_regions against pcl::RegionGrowingRGB (its defaults, the PCL tutorial's
// settings, and the best of a sweep of its thresholds tuned per noise level) and
// pcl::RegionGrowing (the PCL tutorial's settings), on the same generated scenes
// (colour regions, depth camera view) at three noise levels, in the same run:
// adjusted Rand index over all points, Hoover's counts at T = 0.8, regions out, and
// time (normal estimation included where a method uses normals; medians of several
// runs); then frames of the held-out depth camera generator, and the time on the
// real coloured scans.
//
// Usage: pcl_tda_bench_regions [data_dir] [-scenes N] [-runs N] [-seed S]
// The report goes to stdout as markdown tables; the last line is one JSON object.

#include <pcl/common/point_tests.h>
#include <pcl/features/normal_3d.h>
#include <pcl/io/pcd_io.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/region_growing.h>
#include <pcl/segmentation/region_growing_rgb.h>
#include <pcl/tda/apps/region_settings.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/generators/depth_camera_scenes.h>
#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/point_types.h>

#include "bench_command_line.h"
#include "bench_statistics.h"
#include "segmentation/segmentation_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using pcl::tda::bench::median;
using pcl::tda::bench::seconds;

using Cloud = pcl::PointCloud<pcl::PointXYZRGB>;
using pcl::tda::test::adjustedRandIndex;
using pcl::tda::test::HooverCounts;
using pcl::tda::test::hooverCounts;
using pcl::tda::test::segmentLabels;

struct Options {
  std::string data = PCL_TDA_DATA_DIR;
  std::size_t scenes = 8;
  int runs = 3;
  std::uint64_t seed = 100;
  bool sweep = true;
};

/** A segmentation method: the regions of a cloud. */
using Method = std::function<std::vector<pcl::PointIndices> (const Cloud::Ptr&)>;

/** Ours, as pcl_tda_regions runs with no options but -radius \a radius (0: none;
 * radius, normals included). */
std::vector<pcl::PointIndices>
ours (const Cloud::Ptr& cloud, double radius = 0.0)
{
  pcl::tda::RegionSettings settings;
  settings.radius = radius;
  pcl::tda::ToolRegionGrowing growing;
  growing.setInputCloud (cloud);
  pcl::tda::configureRegionGrowing (
      growing, settings, pcl::tda::regionRadius (settings, *cloud), nullptr);
  std::vector<pcl::PointIndices> regions;
  growing.extract (regions);
  return regions;
}

/** Ours as pcl_tda_regions runs with no options. */
std::vector<pcl::PointIndices>
ourDefaults (const Cloud::Ptr& cloud)
{
  return ours (cloud);
}

/** pcl::RegionGrowingRGB with its defaults except those given (negative: default). */
Method
pclRGB (double distance, double point_color, double region_color, int min_size)
{
  return [=] (const Cloud::Ptr& cloud) {
    pcl::RegionGrowingRGB<pcl::PointXYZRGB> growing;
    growing.setInputCloud (cloud);
    growing.setSearchMethod (pcl::search::KdTree<pcl::PointXYZRGB>::Ptr (
        new pcl::search::KdTree<pcl::PointXYZRGB>));
    if (distance > 0.0)
      growing.setDistanceThreshold (static_cast<float> (distance));
    if (point_color > 0.0)
      growing.setPointColorThreshold (static_cast<float> (point_color));
    if (region_color > 0.0)
      growing.setRegionColorThreshold (static_cast<float> (region_color));
    if (min_size > 0)
      growing.setMinClusterSize (min_size);
    std::vector<pcl::PointIndices> regions;
    growing.extract (regions);
    return regions;
  };
}

/** pcl::RegionGrowing (normals and curvature), as in the PCL tutorial. */
std::vector<pcl::PointIndices>
pclNormalGrowing (const Cloud::Ptr& cloud)
{
  pcl::search::KdTree<pcl::PointXYZRGB>::Ptr tree (
      new pcl::search::KdTree<pcl::PointXYZRGB>);
  pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
  pcl::NormalEstimation<pcl::PointXYZRGB, pcl::Normal> estimation;
  estimation.setSearchMethod (tree);
  estimation.setInputCloud (cloud);
  estimation.setKSearch (50);
  estimation.compute (*normals);
  pcl::RegionGrowing<pcl::PointXYZRGB, pcl::Normal> growing;
  growing.setMinClusterSize (50);
  growing.setMaxClusterSize (1000000);
  growing.setSearchMethod (tree);
  growing.setNumberOfNeighbours (30);
  growing.setInputCloud (cloud);
  growing.setInputNormals (normals);
  growing.setSmoothnessThreshold (3.0 / 180.0 * M_PI);
  growing.setCurvatureThreshold (1.0);
  std::vector<pcl::PointIndices> regions;
  growing.extract (regions);
  return regions;
}

/** Quality and time of one method on one scene. */
struct Score {
  double ari = 0.0, seconds = 0.0;
  HooverCounts hoover;
  std::size_t regions = 0;
};

/** Runs \a method on \a cloud \a runs times and scores its regions against
 * \a truth (a label per point) on the points \a scored (all when empty). */
Score
score (const Method& method,
       const Cloud::Ptr& cloud,
       std::vector<std::int64_t> truth,
       int runs,
       const std::vector<std::size_t>& scored = {})
{
  Score result;
  std::vector<pcl::PointIndices> regions;
  std::vector<double> times;
  for (int run = 0; run < runs; ++run)
    times.push_back (seconds ([&] { regions = method (cloud); }));
  auto found = segmentLabels (regions, cloud->size());
  if (!scored.empty()) {
    std::vector<std::int64_t> scored_truth, scored_found;
    for (const std::size_t i : scored) {
      scored_truth.push_back (truth[i]);
      scored_found.push_back (found[i]);
    }
    truth = std::move (scored_truth);
    found = std::move (scored_found);
  }
  result.ari = adjustedRandIndex (truth, found);
  result.hoover = hooverCounts (truth, found, 0.8);
  result.regions = regions.size();
  result.seconds = median (times);
  return result;
}

/** Mean quality and median time of a method over the scenes of a noise level. */
struct Summary {
  std::string method;
  double ari = 0.0, correct = 0.0, over = 0.0, under = 0.0, regions = 0.0;
  double seconds = 0.0;
};

Summary
summarize (const std::string& name, const std::vector<Score>& scores)
{
  Summary summary{name};
  std::vector<double> times;
  for (const Score& s : scores) {
    summary.ari += s.ari / scores.size();
    summary.correct += static_cast<double> (s.hoover.correct) / scores.size();
    summary.over += static_cast<double> (s.hoover.over) / scores.size();
    summary.under += static_cast<double> (s.hoover.under) / scores.size();
    summary.regions += static_cast<double> (s.regions) / scores.size();
    times.push_back (s.seconds);
  }
  summary.seconds = median (times);
  return summary;
}

struct Scene {
  Cloud::Ptr cloud;
  std::vector<std::int64_t> truth;
  std::size_t num_regions = 0;
};

Scene
makeScene (const pcl::tda::TabletopNoise& noise, std::uint64_t seed)
{
  pcl::tda::TabletopParameters parameters;
  parameters.colour_regions = true;
  parameters.point_spacing = 0.005f;
  parameters.setNoise (noise);
  parameters.seed = seed;
  const pcl::tda::TabletopScene generated =
      pcl::tda::generateTabletopScene (parameters);
  Scene scene;
  scene.cloud.reset (new Cloud);
  pcl::copyPointCloud (*generated.cloud, *scene.cloud);
  scene.truth.assign (generated.region_labels.begin(), generated.region_labels.end());
  scene.num_regions = generated.regions.size();
  return scene;
}

void
printUsage (std::FILE* stream)
{
  std::fprintf (stream,
                "Usage: pcl_tda_bench_regions [data_dir] [options]\n"
                "  data_dir   folder of the real scans (default %s)\n"
                "  -scenes N  generated scenes per noise level (default 8)\n"
                "  -runs N    timed runs per method and cloud (default 3)\n"
                "  -seed S    seed of the first scene (default 100)\n"
                "  -sweep 0|1 sweep pcl::RegionGrowingRGB's thresholds (default 1)\n"
                "  -h         this help\n",
                PCL_TDA_DATA_DIR);
}

void
parseOptions (int argc, char** argv, Options& options)
{
  long scenes = static_cast<long> (options.scenes), runs = options.runs, seed = 100;
  pcl::tda::ToolCommandLine command_line;
  command_line.addInteger ("-scenes", scenes, 1, 10000);
  command_line.addInteger ("-runs", runs, 1, 1000);
  command_line.addInteger ("-seed", seed, 0, std::numeric_limits<long>::max());
  long sweep = 1;
  command_line.addInteger ("-sweep", sweep, 0, 1);
  pcl::tda::bench::takeOptionalArgument (
      command_line.parse (argc, argv), "data folder", options.data);
  options.scenes = static_cast<std::size_t> (scenes);
  options.runs = static_cast<int> (runs);
  options.seed = static_cast<std::uint64_t> (seed);
  options.sweep = sweep != 0;
}

} // namespace

int
main (int argc, char** argv)
{
  Options options;
  if (const auto stop = pcl::tda::bench::parseCommandLine (
          argc, argv, options, parseOptions, printUsage))
    return *stop;

  // The sweep of pcl::RegionGrowingRGB: distance (its neighbour radius, in
  // metres), point and region colour thresholds (RGB distances); min size 20.
  struct Setting {
    double distance, point_color, region_color;
  };
  std::vector<Setting> sweep;
  for (const double distance : {0.01, 0.02})
    for (const double point_color : {3.0, 6.0, 10.0, 15.0, 25.0})
      for (const double region_color : {3.0, 5.0, 10.0, 20.0})
        sweep.push_back ({distance, point_color, region_color});

  std::ostringstream json;
  json << "{\"levels\":[";
  const pcl::tda::TabletopNoise levels[] = {pcl::tda::TABLETOP_NO_NOISE,
                                            pcl::tda::TABLETOP_MODERATE_NOISE,
                                            pcl::tda::TABLETOP_HEAVY_NOISE};
  for (std::size_t l = 0; l < 3; ++l) {
    const pcl::tda::TabletopNoise& noise = levels[l];
    std::vector<Scene> scenes;
    double points = 0.0, truth_regions = 0.0;
    for (std::size_t s = 0; s < options.scenes; ++s) {
      scenes.push_back (makeScene (noise, options.seed + s));
      points += static_cast<double> (scenes.back().cloud->size()) / options.scenes;
      truth_regions += static_cast<double> (scenes.back().num_regions) / options.scenes;
    }
    std::fprintf (stderr, "noise %s: %zu scenes\n", noise.name, scenes.size());
    const auto run_all = [&] (const Method& method, int runs) {
      std::vector<Score> scores;
      for (const Scene& scene : scenes)
        scores.push_back (score (method, scene.cloud, scene.truth, runs));
      return scores;
    };
    std::vector<Summary> rows;
    rows.push_back (summarize ("ours (pcl_tda_regions defaults)",
                               run_all (ourDefaults, options.runs)));
    rows.push_back (summarize ("pcl::RegionGrowingRGB defaults",
                               run_all (pclRGB (-1, -1, -1, -1), options.runs)));
    rows.push_back (summarize ("pcl::RegionGrowingRGB tutorial (10, 6, 5, 600)",
                               run_all (pclRGB (10, 6, 5, 600), options.runs)));
    Summary best{"", -2.0};
    for (const Setting& setting : options.sweep ? sweep : std::vector<Setting>{}) {
      std::ostringstream name;
      name << "pcl::RegionGrowingRGB best sweep (" << setting.distance << ", "
           << setting.point_color << ", " << setting.region_color << ", 20)";
      const Summary candidate = summarize (
          name.str(),
          run_all (
              pclRGB (setting.distance, setting.point_color, setting.region_color, 20),
              1));
      if (candidate.ari > best.ari)
        best = candidate;
    }
    if (options.sweep)
      rows.push_back (best);
    rows.push_back (summarize ("pcl::RegionGrowing tutorial (normals)",
                               run_all (pclNormalGrowing, options.runs)));

    std::printf ("\n### Noise %s (depth sigma %.1f mm at 1 m, RGB sigma %.0f): %zu "
                 "scenes, %.0f points, %.1f true regions on average\n\n",
                 noise.name,
                 1000.0 * noise.depth_sigma,
                 noise.colour_sigma,
                 scenes.size(),
                 points,
                 truth_regions);
    std::printf (
        "| method | ARI | correct | over | under | regions | time (s) | time / "
        "ours |\n|---|---|---|---|---|---|---|---|\n");
    for (const Summary& row : rows)
      std::printf ("| %s | %.3f | %.1f | %.1f | %.1f | %.1f | %.3f | %.1f |\n",
                   row.method.c_str(),
                   row.ari,
                   row.correct,
                   row.over,
                   row.under,
                   row.regions,
                   row.seconds,
                   row.seconds / rows[0].seconds);
    json << (l ? "," : "") << "{\"noise\":\"" << noise.name
         << "\",\"ours_ari\":" << rows[0].ari << ",\"pcl_best_ari\":" << best.ari
         << ",\"ours_under\":" << rows[0].under << ",\"pcl_best_under\":" << best.under
         << ",\"ours_s\":" << rows[0].seconds
         << ",\"pcl_default_s\":" << rows[1].seconds << "}";
  }
  json << "],\"held_out\":";

  // The held-out generator: organized depth frames of two-tone objects, table kept.
  {
    // Each frame twice: its finite points only, and organized (640 x 480, the lost
    // pixels scored nowhere), as pcl_tda_regions gets it from a PCD file.
    std::vector<Scene> frames, organized_frames;
    std::vector<std::vector<std::size_t>> finite_pixels;
    for (std::size_t s = 0; s < std::min<std::size_t> (options.scenes, 4); ++s) {
      pcl::tda::DepthCameraParameters parameters;
      parameters.colour_regions = true;
      parameters.remove_table = false;
      parameters.colour_noise = 4.0f;
      parameters.seed = options.seed + s;
      const auto generated = pcl::tda::generateDepthCameraScene (parameters);
      Scene organized;
      organized.cloud.reset (new Cloud);
      pcl::copyPointCloud (*generated.cloud, *organized.cloud);
      organized.truth.assign (generated.region_labels.begin(),
                              generated.region_labels.end());
      organized.num_regions = generated.regions.size();
      // The lost pixels have no truth: only the finite points are scored.
      Scene frame;
      frame.cloud.reset (new Cloud);
      finite_pixels.emplace_back();
      for (std::size_t i = 0; i < organized.cloud->size(); ++i)
        if (pcl::isXYZFinite ((*organized.cloud)[i])) {
          frame.cloud->push_back ((*organized.cloud)[i]);
          frame.truth.push_back (organized.truth[i]);
          finite_pixels.back().push_back (i);
        }
      frame.num_regions = organized.num_regions;
      frames.push_back (frame);
      organized_frames.push_back (organized);
    }
    const auto run_frames = [&] (const Method& method) {
      std::vector<Score> scores;
      for (const Scene& frame : frames)
        scores.push_back (score (method, frame.cloud, frame.truth, 1));
      return scores;
    };
    const auto run_organized_frames = [&] (const Method& method) {
      std::vector<Score> scores;
      for (std::size_t f = 0; f < organized_frames.size(); ++f)
        scores.push_back (score (method,
                                 organized_frames[f].cloud,
                                 organized_frames[f].truth,
                                 1,
                                 finite_pixels[f]));
      return scores;
    };
    std::vector<Summary> rows;
    rows.push_back (summarize ("ours, defaults, organized frame (as pcl_tda_regions)",
                               run_organized_frames (ourDefaults)));
    rows.push_back (summarize (
        "ours, -radius 0.01, organized frame",
        run_organized_frames ([] (const Cloud::Ptr& c) { return ours (c, 0.01); })));
    rows.push_back (summarize ("ours, defaults, finite points only (no image)",
                               run_frames (ourDefaults)));
    rows.push_back (summarize ("pcl::RegionGrowingRGB defaults",
                               run_frames (pclRGB (-1, -1, -1, -1))));
    rows.push_back (summarize ("pcl::RegionGrowingRGB (0.01, 6, 10, 20)",
                               run_frames (pclRGB (0.01, 6, 10, 20))));
    std::printf (
        "\n### Held out: depth camera frames of two-tone objects (table kept, RGB "
        "noise 4), %zu frames, scored on their finite points\n\n",
        frames.size());
    std::printf ("| method | ARI | correct | over | under | regions | time (s) |\n"
                 "|---|---|---|---|---|---|---|\n");
    for (const Summary& row : rows)
      std::printf ("| %s | %.3f | %.1f | %.1f | %.1f | %.1f | %.3f |\n",
                   row.method.c_str(),
                   row.ari,
                   row.correct,
                   row.over,
                   row.under,
                   row.regions,
                   row.seconds);
    json << "{\"ours_default_ari\":" << rows[0].ari << ",\"ours_ari\":" << rows[1].ari
         << ",\"ours_unorganized_ari\":" << rows[2].ari
         << ",\"pcl_default_ari\":" << rows[3].ari << "}";
  }
  json << ",\"scans\":[";

  std::printf ("\n### Real scans: time (s), medians of %d runs\n\n", options.runs);
  std::printf (
      "| cloud | points | ours | pcl::RegionGrowingRGB defaults | ratio | ours "
      "regions | PCL regions |\n|---|---|---|---|---|---|---|\n");
  bool first = true;
  for (const std::string name : {"milk_color.pcd", "colored_cloud.pcd"}) {
    Cloud::Ptr cloud (new Cloud);
    if (pcl::io::loadPCDFile (options.data + "/" + name, *cloud) < 0) {
      std::printf ("| %s | (not found in %s) |\n", name.c_str(), options.data.c_str());
      continue;
    }
    std::vector<std::int64_t> none (cloud->size(), 0);
    const Score our = score (ourDefaults, cloud, none, options.runs);
    const Score theirs = score (pclRGB (-1, -1, -1, -1), cloud, none, options.runs);
    std::printf ("| %s | %zu | %.3f | %.3f | %.1f | %zu | %zu |\n",
                 name.c_str(),
                 static_cast<std::size_t> (cloud->size()),
                 our.seconds,
                 theirs.seconds,
                 theirs.seconds / our.seconds,
                 our.regions,
                 theirs.regions);
    json << (first ? "" : ",") << "{\"cloud\":\"" << name
         << "\",\"ours_s\":" << our.seconds << ",\"pcl_default_s\":" << theirs.seconds
         << "}";
    first = false;
  }
  json << "]}";
  std::printf ("\n%s\n", json.str().c_str());
  return 0;
}
