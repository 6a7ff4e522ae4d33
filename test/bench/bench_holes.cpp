// pcl_tda_bench_holes: pcl::tda::HoleBoundaryEstimation at its defaults against
// pcl::NormalEstimationOMP + pcl::BoundaryEstimation (the usual tutorial settings,
// and the best of a sweep of its radii and angle threshold tuned per surface kind
// and noise level) on the same generated hole surfaces (plane, height field,
// cylinder, sphere, torus; three noise levels), in the same run: per-point precision,
// recall and F1 of the rim band against the generator's labels (outer border
// excluded), hole-level recall and precision of our rims, and time (medians of
// several runs). Then the thesis setting of Sec 5.6 (Tables 5.1-5.3) on real scans
// with 10, 20 and 30 % of the points removed at random: complex size, essential
// beta_1, holes, times and flagged points of both.
//
// Usage: pcl_tda_bench_holes [data_dir] [-scenes N] [-runs N] [-seed S] [-quick]
// The report goes to stdout as markdown tables; the last line is one JSON object.

#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/features/boundary.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/filters/filter.h>
#include <pcl/io/pcd_io.h>
#include <pcl/search/kdtree.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/features/hole_boundary_estimation.h>
#include <pcl/tda/generators/hole_surfaces.h>
#include <pcl/tda/generators/random_sampling.h>
#include <pcl/point_types.h>

#include "bench_command_line.h"
#include "bench_hole_filling.h"
#include "bench_statistics.h"
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using pcl::tda::bench::fillHoles;
using pcl::tda::bench::mean;
using pcl::tda::bench::median;
using pcl::tda::bench::nearestDistances;
using pcl::tda::bench::seconds;

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Flags = std::vector<std::uint8_t>;
using Ours = pcl::tda::HoleBoundaryEstimation<pcl::PointXYZ, pcl::Boundary>;
using PclBoundary = pcl::BoundaryEstimation<pcl::PointXYZ, pcl::Normal, pcl::Boundary>;

struct Options {
  std::string data = PCL_TDA_DATA_DIR;
  std::size_t scenes = 4;
  int runs = 3;
  std::uint64_t seed = 1;
  bool quick = false;
};

/** Noise levels of the generated surfaces, in units of the spacing h. */
const double NOISE_LEVELS[] = {0.0, 0.1, 0.25};

/** PCL's sweep: normal radius, boundary radius (both in units of h), angle. */
const double SWEEP_NORMAL_RADII[] = {2.0, 3.0, 5.0};
const double SWEEP_BOUNDARY_RADII[] = {1.5, 2.0, 3.0, 4.0, 5.0};
const double SWEEP_ANGLES[] = {
    M_PI / 4, M_PI / 3, M_PI / 2, 2 * M_PI / 3, 3 * M_PI / 4};
const char* const SWEEP_ANGLE_NAMES[] = {"pi/4", "pi/3", "pi/2", "2pi/3", "3pi/4"};
constexpr std::size_t NUM_NORMAL_RADII = std::size (SWEEP_NORMAL_RADII);
constexpr std::size_t NUM_BOUNDARY_RADII = std::size (SWEEP_BOUNDARY_RADII);
constexpr std::size_t NUM_ANGLES = std::size (SWEEP_ANGLES);
constexpr std::size_t NUM_SETTINGS = NUM_NORMAL_RADII * NUM_BOUNDARY_RADII * NUM_ANGLES;

/** The PCL tutorial's way: normals from the k = 20 nearest points, boundary radius
 * 2.5 h, PCL's default angle threshold pi/2. */
constexpr int TUTORIAL_NORMAL_K = 20;
constexpr double TUTORIAL_BOUNDARY_RADIUS = 2.5;

/** A setting of PCL's pipeline: normals from the \a normal_k nearest points (when
 * positive) or within \a normal_radius, boundary within \a boundary_radius (radii
 * in units of h, or in metres where h is 1), angle threshold \a angle. */
struct PclSetting {
  int normal_k = 0;
  double normal_radius = 0.0;
  double boundary_radius = 0.0;
  double angle = M_PI / 2;
  std::string name;
};

PclSetting
sweepSetting (std::size_t index)
{
  const std::size_t a = index % NUM_ANGLES;
  const std::size_t b = (index / NUM_ANGLES) % NUM_BOUNDARY_RADII;
  const std::size_t n = index / (NUM_ANGLES * NUM_BOUNDARY_RADII);
  PclSetting setting;
  setting.normal_radius = SWEEP_NORMAL_RADII[n];
  setting.boundary_radius = SWEEP_BOUNDARY_RADII[b];
  setting.angle = SWEEP_ANGLES[a];
  std::ostringstream name;
  name << "normals r " << setting.normal_radius << " h, boundary r "
       << setting.boundary_radius << " h, " << SWEEP_ANGLE_NAMES[a];
  setting.name = name.str();
  return setting;
}

/** Per point flags (0 or 1) of a boundary cloud of \a size points; all 0 when the
 * computation failed (empty output). */
Flags
toFlags (const pcl::PointCloud<pcl::Boundary>& boundary, std::size_t size)
{
  Flags flags (size, 0);
  if (boundary.size() == size)
    for (std::size_t i = 0; i < size; ++i)
      flags[i] = boundary[i].boundary_point != 0;
  return flags;
}

std::size_t
countFlags (const Flags& flags)
{
  return static_cast<std::size_t> (std::count (flags.begin(), flags.end(), 1));
}

/** Ours at its defaults on \a cloud (everything of compute() timed by callers);
 * \a failed: compute() gave no output (it prints why). */
Flags
runOurs (const Cloud::Ptr& cloud, Ours& ours, bool& failed)
{
  ours.setInputCloud (cloud);
  pcl::PointCloud<pcl::Boundary> boundary;
  ours.compute (boundary);
  failed = boundary.size() != cloud->size();
  return toFlags (boundary, cloud->size());
}

/** PCL's pipeline: a k-d tree, pcl::NormalEstimationOMP (default threads) and
 * pcl::BoundaryEstimation (serial), radii scaled by \a unit. */
Flags
runPcl (const Cloud::Ptr& cloud, const PclSetting& setting, double unit)
{
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree (new pcl::search::KdTree<pcl::PointXYZ>);
  pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud (cloud);
  estimation.setSearchMethod (tree);
  if (setting.normal_k > 0)
    estimation.setKSearch (setting.normal_k);
  else
    estimation.setRadiusSearch (setting.normal_radius * unit);
  estimation.compute (*normals);
  PclBoundary boundary_estimation;
  boundary_estimation.setInputCloud (cloud);
  boundary_estimation.setInputNormals (normals);
  boundary_estimation.setSearchMethod (tree);
  boundary_estimation.setRadiusSearch (setting.boundary_radius * unit);
  boundary_estimation.setAngleThreshold (static_cast<float> (setting.angle));
  pcl::PointCloud<pcl::Boundary> boundary;
  boundary_estimation.compute (boundary);
  return toFlags (boundary, cloud->size());
}

/** The largest angle between consecutive neighbours of \a q around it in the (u, v)
 * plane, exactly as pcl::BoundaryEstimation::isBoundaryPoint() computes it (which
 * returns whether it exceeds the angle threshold); -1 where that returns false for
 * every threshold. */
float
largestAngularGap (const Cloud& cloud,
                   const pcl::PointXYZ& q,
                   const pcl::Indices& indices,
                   const Eigen::Vector4f& u,
                   const Eigen::Vector4f& v)
{
  if (indices.size() < 3 || !pcl::isXYZFinite (q))
    return -1.0f;
  std::vector<float> angles;
  angles.reserve (indices.size());
  for (const pcl::index_t index : indices) {
    if (!pcl::isXYZFinite (cloud[index]))
      continue;
    const Eigen::Vector4f delta = cloud[index].getVector4fMap() - q.getVector4fMap();
    if (delta == Eigen::Vector4f::Zero())
      continue;
    angles.push_back (std::atan2 (v.dot (delta), u.dot (delta)));
  }
  if (angles.empty())
    return -1.0f;
  std::sort (angles.begin(), angles.end());
  float largest = 0.0f;
  for (std::size_t i = 0; i + 1 < angles.size(); ++i)
    largest = std::max (largest, angles[i + 1] - angles[i]);
  return std::max (largest,
                   2 * static_cast<float> (M_PI) - angles.back() + angles.front());
}

/** The flags of every setting of the sweep (index of sweepSetting()), as
 * pcl::BoundaryEstimation::compute() gives them (the same k-d tree radius search,
 * PCL's u-v frame and its angle criterion, largestAngularGap()), but with the
 * neighbours searched once per boundary radius and the angles sorted once per
 * normal radius for all thresholds. benchGroup() checks the flags of the chosen
 * setting against compute()'s. */
std::vector<Flags>
sweepFlags (const Cloud::Ptr& cloud, double h)
{
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree (new pcl::search::KdTree<pcl::PointXYZ>);
  tree->setInputCloud (cloud);
  std::vector<pcl::PointCloud<pcl::Normal>> normals (NUM_NORMAL_RADII);
  for (std::size_t n = 0; n < NUM_NORMAL_RADII; ++n) {
    pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation;
    estimation.setInputCloud (cloud);
    estimation.setSearchMethod (tree);
    estimation.setRadiusSearch (SWEEP_NORMAL_RADII[n] * h);
    estimation.compute (normals[n]);
  }
  std::vector<Flags> flags (NUM_SETTINGS, Flags (cloud->size(), 0));
  PclBoundary boundary;
  pcl::Indices neighbours;
  std::vector<float> distances;
  for (std::size_t b = 0; b < NUM_BOUNDARY_RADII; ++b)
    for (std::size_t i = 0; i < cloud->size(); ++i) {
      if (!pcl::isFinite ((*cloud)[i]) ||
          tree->radiusSearch (static_cast<pcl::index_t> (i),
                              SWEEP_BOUNDARY_RADII[b] * h,
                              neighbours,
                              distances) == 0)
        continue;
      for (std::size_t n = 0; n < NUM_NORMAL_RADII; ++n) {
        Eigen::Vector4f u, v;
        boundary.getCoordinateSystemOnPlane (normals[n][i], u, v);
        const float gap = largestAngularGap (*cloud, (*cloud)[i], neighbours, u, v);
        for (std::size_t a = 0; a < NUM_ANGLES; ++a)
          flags[(n * NUM_BOUNDARY_RADII + b) * NUM_ANGLES + a][i] =
              gap > static_cast<float> (SWEEP_ANGLES[a]);
      }
    }
  return flags;
}

/** Per-point quality of flags against the rim band labels. */
struct PointScore {
  double precision = 0.0, recall = 0.0, f1 = 0.0;
};

/** Positive: a label of a hole (1..k); points of the outer border band are left
 * out. A method that flags nothing has precision 0. */
PointScore
scorePoints (const Flags& flags, const std::vector<std::uint32_t>& labels)
{
  std::size_t tp = 0, fp = 0, fn = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] == pcl::tda::OUTER_BORDER_LABEL)
      continue;
    const bool truth = labels[i] != pcl::tda::SURFACE_LABEL;
    if (flags[i] && truth)
      ++tp;
    else if (flags[i])
      ++fp;
    else if (truth)
      ++fn;
  }
  PointScore score;
  score.precision = tp + fp ? static_cast<double> (tp) / (tp + fp) : 0.0;
  score.recall = tp + fn ? static_cast<double> (tp) / (tp + fn) : 0.0;
  score.f1 =
      score.precision + score.recall > 0.0
          ? 2.0 * score.precision * score.recall / (score.precision + score.recall)
          : 0.0;
  return score;
}

/** Hole-level counts of one cloud: true holes, found rims, and true holes matched by
 * a found rim (its centroid within half the hole's radius of the hole's centre). */
struct HoleCounts {
  std::size_t truth = 0, found = 0, matched = 0, findable = 0;
};

/** Per true hole of \a surface, whether a rim of \a found matches it (its centroid
 * within half the hole's radius of the hole's centre; each rim matches one hole). */
std::vector<bool>
matchedTrueHoles (const std::vector<pcl::tda::HoleRim>& found,
                  const pcl::tda::HoleSurface& surface)
{
  std::vector<bool> taken (surface.holes.size(), false);
  for (const pcl::tda::HoleRim& rim : found) {
    for (std::size_t j = 0; j < surface.holes.size(); ++j) {
      const auto& hole = surface.holes[j];
      if (!taken[j] && (rim.centroid - hole.center).norm() <= 0.5f * hole.radius) {
        taken[j] = true;
        break;
      }
    }
  }
  return taken;
}

HoleCounts
matchHoles (const std::vector<pcl::tda::HoleRim>& found,
            const pcl::tda::HoleSurface& surface)
{
  HoleCounts counts;
  counts.truth = surface.holes.size();
  // Homology has k - 1 hole classes on a closed surface.
  counts.findable = surface.closed && counts.truth ? counts.truth - 1 : counts.truth;
  counts.found = found.size();
  const std::vector<bool> matched = matchedTrueHoles (found, surface);
  counts.matched =
      static_cast<std::size_t> (std::count (matched.begin(), matched.end(), true));
  return counts;
}

/** The filling of the holes ours found, against the samples the holes cut out
 * (HoleSurface::cut) and against HoleBoundaryEstimation run again on the filled
 * cloud. */
struct FillingScore {
  std::size_t new_points = 0;
  /** Of each new point to the nearest cut sample, in units of h. */
  std::vector<double> distances;
  /** Cut samples of the found holes, and those with a new point within 1.5 h. */
  std::size_t cut_samples = 0, covered = 0;
  /** Found holes, and those found again on the filled cloud. */
  std::size_t filled = 0, found_again = 0;

  void
  add (const pcl::tda::HoleSurface& surface, const Cloud::Ptr& cloud, const Ours& ours)
  {
    const Cloud::Ptr added = fillHoles (cloud, ours.getHoles());
    new_points += added->size();
    const std::vector<bool> found = matchedTrueHoles (ours.getHoles(), surface);
    Cloud::Ptr cut (new Cloud), cut_of_found (new Cloud);
    for (const auto& p : *surface.cut) {
      cut->push_back ({p.x, p.y, p.z});
      if (found[p.label - 1])
        cut_of_found->push_back ({p.x, p.y, p.z});
    }
    cut_samples += cut_of_found->size();
    const double h = surface.spacing;
    if (!added->empty() && !cut->empty()) {
      for (const double d : nearestDistances (*added, cut))
        distances.push_back (d / h);
      for (const double d : nearestDistances (*cut_of_found, added))
        covered += d <= 1.5 * h;
    }
    // Every found hole is counted, also one the filling added no point to.
    Cloud::Ptr filled_cloud (new Cloud (*cloud));
    *filled_cloud += *added;
    Ours again;
    bool failed = false;
    runOurs (filled_cloud, again, failed);
    const std::vector<bool> found_after = matchedTrueHoles (again.getHoles(), surface);
    for (std::size_t j = 0; j < found.size(); ++j) {
      filled += found[j];
      found_again += found[j] && found_after[j];
    }
  }
};

/** One generated cloud and its truth. */
struct Scene {
  Cloud::Ptr cloud;
  std::vector<std::uint32_t> labels;
  pcl::tda::HoleSurface surface;
};

Scene
makeScene (pcl::tda::HoleSurfaceKind kind, double noise, std::uint64_t seed)
{
  pcl::tda::HoleSurfaceParameters parameters;
  parameters.kind = kind;
  parameters.noise_sigma = static_cast<float> (noise);
  parameters.seed = seed;
  Scene scene;
  scene.surface = pcl::tda::generateHoleSurface (parameters);
  scene.cloud.reset (new Cloud);
  pcl::copyPointCloud (*scene.surface.cloud, *scene.cloud);
  for (const auto& p : *scene.surface.cloud)
    scene.labels.push_back (p.label);
  return scene;
}

/** The row of one method on the scenes of one kind and noise level. */
struct Row {
  std::string method;
  std::vector<double> precision, recall, f1, times;
  double flagged = 0.0;

  void
  add (const PointScore& score, double time, std::size_t flagged_points, double n)
  {
    precision.push_back (score.precision);
    recall.push_back (score.recall);
    f1.push_back (score.f1);
    times.push_back (time);
    flagged += static_cast<double> (flagged_points) / n;
  }
};

struct GroupResult {
  std::string kind;
  double noise = 0.0;
  Row ours, tutorial, best;
  std::string best_setting;
  HoleCounts holes;
  FillingScore filling;
  /** True holes matched on each surface, e.g. "3 3 2 3". */
  std::string matched_per_surface;
  std::size_t mismatches = 0, failures = 0;
};

/** "b / a" with two decimals. */
std::string
ratio (double b, double a)
{
  char text[32];
  std::snprintf (text, sizeof text, "%.2f", b / a);
  return text;
}

void
printUsage (std::FILE* stream)
{
  std::fprintf (stream,
                "Usage: pcl_tda_bench_holes [data_dir] [options]\n"
                "  data_dir   folder of the real scans (default %s)\n"
                "  -scenes N  generated surfaces per kind and noise level (default 4)\n"
                "  -runs N    timed runs per method and cloud (default 3)\n"
                "  -seed S    seed of the first surface (default 1)\n"
                "  -quick     smoke test: 1 scene, 1 run, plane and cylinder only\n"
                "  -h         this help\n",
                PCL_TDA_DATA_DIR);
}

void
parseOptions (int argc, char** argv, Options& options)
{
  long scenes = static_cast<long> (options.scenes), runs = options.runs, seed = 1;
  bool quick = false;
  pcl::tda::ToolCommandLine command_line;
  command_line.addInteger ("-scenes", scenes, 1, 10000);
  command_line.addInteger ("-runs", runs, 1, 1000);
  command_line.addInteger ("-seed", seed, 0, std::numeric_limits<long>::max());
  command_line.addSwitch ("-quick", quick);
  pcl::tda::bench::takeOptionalArgument (
      command_line.parse (argc, argv), "data folder", options.data);
  options.scenes = static_cast<std::size_t> (scenes);
  options.runs = static_cast<int> (runs);
  options.seed = static_cast<std::uint64_t> (seed);
  options.quick = quick;
  if (quick) {
    if (command_line.given ("-scenes") || command_line.given ("-runs"))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "-quick sets -scenes and -runs to 1: give neither.");
    options.scenes = 1;
    options.runs = 1;
  }
}

/** Section 1: one kind and noise level. */
GroupResult
benchGroup (pcl::tda::HoleSurfaceKind kind, double noise, const Options& options)
{
  GroupResult group;
  group.kind = pcl::tda::holeSurfaceKindName (kind);
  group.noise = noise;
  group.ours.method = "ours (defaults)";
  PclSetting tutorial;
  tutorial.normal_k = TUTORIAL_NORMAL_K;
  tutorial.boundary_radius = TUTORIAL_BOUNDARY_RADIUS;
  tutorial.angle = M_PI / 2;
  tutorial.name = "normals k 20, boundary r 2.5 h, pi/2";
  group.tutorial.method = "PCL tutorial (" + tutorial.name + ")";

  std::vector<Scene> scenes;
  for (std::size_t s = 0; s < options.scenes; ++s)
    scenes.push_back (makeScene (kind, noise, options.seed + s));
  const double n = static_cast<double> (scenes.size());

  // Ours and the tutorial's settings, timed; then the sweep, whose candidates are
  // its settings and the tutorial's (index NUM_SETTINGS); then its best, timed.
  std::vector<std::vector<Flags>> candidates;
  std::vector<double> candidate_f1 (NUM_SETTINGS + 1, 0.0);
  double sweep_s = 0.0;
  for (const Scene& scene : scenes) {
    const double h = scene.surface.spacing;
    Flags flags;
    std::vector<double> times;
    Ours ours;
    bool failed = false;
    for (int run = 0; run < options.runs; ++run)
      times.push_back (seconds ([&] { flags = runOurs (scene.cloud, ours, failed); }));
    group.failures += failed;
    group.ours.add (
        scorePoints (flags, scene.labels), median (times), countFlags (flags), n);
    const HoleCounts counts = matchHoles (ours.getHoles(), scene.surface);
    group.holes.truth += counts.truth;
    group.holes.found += counts.found;
    group.holes.matched += counts.matched;
    group.holes.findable += counts.findable;
    group.matched_per_surface += (group.matched_per_surface.empty() ? "" : " ") +
                                 std::to_string (counts.matched);
    group.filling.add (scene.surface, scene.cloud, ours);

    times.clear();
    for (int run = 0; run < options.runs; ++run)
      times.push_back (seconds ([&] { flags = runPcl (scene.cloud, tutorial, h); }));
    group.tutorial.add (
        scorePoints (flags, scene.labels), median (times), countFlags (flags), n);

    sweep_s += seconds ([&] { candidates.push_back (sweepFlags (scene.cloud, h)); });
    candidates.back().push_back (flags);
    for (std::size_t k = 0; k <= NUM_SETTINGS; ++k)
      candidate_f1[k] += scorePoints (candidates.back()[k], scene.labels).f1 / n;
  }
  const std::size_t best = static_cast<std::size_t> (
      std::max_element (candidate_f1.begin(), candidate_f1.end()) -
      candidate_f1.begin());
  const PclSetting best_setting = best < NUM_SETTINGS ? sweepSetting (best) : tutorial;
  std::fprintf (stderr, "  sweep %.1f s\n", sweep_s);
  group.best_setting = best_setting.name;
  group.best.method = "PCL best of sweep (" + best_setting.name + ")";

  for (std::size_t s = 0; s < scenes.size(); ++s) {
    const Scene& scene = scenes[s];
    Flags flags;
    std::vector<double> times;
    for (int run = 0; run < options.runs; ++run)
      times.push_back (seconds (
          [&] { flags = runPcl (scene.cloud, best_setting, scene.surface.spacing); }));
    group.best.add (
        scorePoints (flags, scene.labels), median (times), countFlags (flags), n);
    for (std::size_t i = 0; i < flags.size(); ++i)
      group.mismatches += flags[i] != candidates[s][best][i];
  }
  return group;
}

/** Section 2: one real scan with a fraction of its points removed at random. */
struct ScanResult {
  std::string name;
  double removed = 0.0;
  std::size_t points = 0, persistent = 0, beta1 = 0, holes = 0;
  std::size_t ours_flagged = 0, pcl_flagged = 0;
  std::size_t edges = 0, new_points = 0;
  std::uint64_t triangles = 0;
  /** Median distance of the new points of HoleFilling to the nearest removed point,
   * in spacings (radius / AUTO_RADIUS_PER_SPACING). */
  double fill_distance = 0.0;
  double radius = 0.0, ours_s = 0.0, pcl_s = 0.0;
  bool failed = false;
};

/** A cloud split at random into the points kept and those removed. */
struct Removal {
  Cloud::Ptr kept{new Cloud}, removed{new Cloud};
};

Removal
removeAtRandom (const Cloud& cloud, double fraction, std::uint64_t seed)
{
  std::vector<std::size_t> order (cloud.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  pcl::tda::PortableRandom random (seed);
  for (std::size_t i = order.size(); i > 1; --i)
    std::swap (order[i - 1], order[random.index (i)]);
  const std::size_t keep =
      order.size() - static_cast<std::size_t> (
                         std::llround (fraction * static_cast<double> (order.size())));
  std::vector<bool> kept (cloud.size(), false);
  for (std::size_t k = 0; k < keep; ++k)
    kept[order[k]] = true;
  Removal removal;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    (kept[i] ? removal.kept : removal.removed)->push_back (cloud[i]);
  return removal;
}

ScanResult
benchScan (const std::string& name,
           const Removal& removal,
           double fraction,
           const Options& options)
{
  const Cloud::Ptr& cloud = removal.kept;
  ScanResult result;
  result.name = name;
  result.removed = fraction;
  result.points = cloud->size();
  Ours ours;
  Flags flags;
  std::vector<double> times;
  bool failed = false;
  for (int run = 0; run < options.runs; ++run)
    times.push_back (seconds ([&] { flags = runOurs (cloud, ours, failed); }));
  result.failed = failed;
  result.ours_s = median (times);
  result.ours_flagged = countFlags (flags);
  result.persistent = ours.getSearchCounts().persistent_classes;
  result.beta1 = ours.getSearchCounts().open_classes;
  result.holes = ours.getHoles().size();
  result.radius = ours.getUsedRadius();
  result.edges = ours.getComplex().numEdges();
  result.triangles = ours.getSearchCounts().triangles;
  const Cloud::Ptr added = fillHoles (cloud, ours.getHoles());
  result.new_points = added->size();
  std::vector<double> distances;
  if (!added->empty() && !removal.removed->empty())
    distances = nearestDistances (*added, removal.removed);
  result.fill_distance =
      distances.empty()
          ? std::nan ("")
          : median (distances) / (result.radius / Ours::AUTO_RADIUS_PER_SPACING);
  if (failed) {
    result.pcl_s = std::nan ("");
    return result;
  }
  PclSetting setting;
  setting.normal_radius = result.radius;
  setting.boundary_radius = result.radius;
  times.clear();
  for (int run = 0; run < options.runs; ++run)
    times.push_back (seconds ([&] { flags = runPcl (cloud, setting, 1.0); }));
  result.pcl_s = median (times);
  result.pcl_flagged = countFlags (flags);
  return result;
}

} // namespace

int
main (int argc, char** argv)
{
  Options options;
  if (const auto stop = pcl::tda::bench::parseCommandLine (
          argc, argv, options, parseOptions, printUsage))
    return *stop;

  std::vector<pcl::tda::HoleSurfaceKind> kinds = {
      pcl::tda::HoleSurfaceKind::PLANE,
      pcl::tda::HoleSurfaceKind::HEIGHT_FIELD,
      pcl::tda::HoleSurfaceKind::CYLINDER,
      pcl::tda::HoleSurfaceKind::SPHERE,
      pcl::tda::HoleSurfaceKind::TORUS};
  if (options.quick)
    kinds = {pcl::tda::HoleSurfaceKind::PLANE, pcl::tda::HoleSurfaceKind::CYLINDER};

  const pcl::tda::HoleSurfaceParameters defaults;
  std::printf ("## Hole boundary points: HoleBoundaryEstimation vs "
               "pcl::BoundaryEstimation\n\n");
  std::printf (
      "Generated hole surfaces (`generateHoleSurface` at its defaults: %zu points "
      "before the holes are cut, holes of radius 3, 5 and 8 h, rim band %.1f h), %zu "
      "per kind and noise level (seeds %llu-%llu); noise sigma in units of the "
      "spacing h. The same clouds for every method, in the same run.\n\n"
      "- Scores: positive = a point labelled with a hole (its rim band). Points of "
      "the outer border band are left out of the scores for both methods: PCL flags "
      "the outer border too (correctly for its purpose), ours flags hole rims only. "
      "P, R, F1: means over the surfaces; flagged: mean points flagged per surface, "
      "outer border included. Ours' default rim band width (%.1f h) equals the "
      "generator's, which favours ours here; PCL's band width follows its radius and "
      "angle, which the sweep tunes.\n"
      "- Ours: `HoleBoundaryEstimation::compute()` with no option set (radius "
      "%.1f x the surface spacing it measures, rim band %.1f x).\n"
      "- PCL: a k-d tree, `pcl::NormalEstimationOMP` (default threads) and "
      "`pcl::BoundaryEstimation` (PCL has no parallel version: serial); radii in "
      "units of the generator's h. Tutorial: normals from the %d nearest points, "
      "boundary radius %.1f h, angle pi/2 (PCL's default). Best: the best by mean F1, "
      "chosen per kind and noise level on these very surfaces, of the tutorial "
      "setting and %zu settings (normal radius 2, 3, 5 h x boundary radius 1.5, 2, "
      "3, 4, 5 h x angle pi/4, pi/3, pi/2, 2pi/3, 3pi/4); this tuning favours PCL.\n"
      "- Time: `compute()` for ours, normals + boundary (tree included) for PCL; "
      "median of %d runs per surface, then median over the surfaces; OpenMP threads: "
      "%d; PCL / ours > 1: ours faster.\n",
      static_cast<std::size_t> (defaults.num_points),
      static_cast<double> (defaults.band_width),
      options.scenes,
      static_cast<unsigned long long> (options.seed),
      static_cast<unsigned long long> (options.seed + options.scenes - 1),
      Ours::AUTO_BAND_PER_SPACING,
      Ours::AUTO_RADIUS_PER_SPACING,
      Ours::AUTO_BAND_PER_SPACING,
      TUTORIAL_NORMAL_K,
      TUTORIAL_BOUNDARY_RADIUS,
      NUM_SETTINGS,
      options.runs,
      omp_get_max_threads());

  std::vector<GroupResult> groups;
  std::size_t mismatches = 0, failures = 0;
  try {
    for (const pcl::tda::HoleSurfaceKind kind : kinds) {
      std::vector<GroupResult> rows;
      for (const double noise : NOISE_LEVELS) {
        std::fprintf (stderr,
                      "%s, noise %.2f h: %zu surfaces\n",
                      pcl::tda::holeSurfaceKindName (kind),
                      noise,
                      options.scenes);
        rows.push_back (benchGroup (kind, noise, options));
      }
      std::printf ("\n### %s\n\n", pcl::tda::holeSurfaceKindName (kind));
      std::printf (
          "| noise (h) | method | P | R | F1 | flagged | time (s) | PCL / ours "
          "|\n|---|---|---|---|---|---|---|---|\n");
      for (const GroupResult& group : rows) {
        const double ours_s = median (group.ours.times);
        for (const Row* row : {&group.ours, &group.tutorial, &group.best}) {
          const double s = median (row->times);
          std::printf ("| %.2f | %s | %.3f | %.3f | %.3f | %.0f | %.3f | %s |\n",
                       group.noise,
                       row->method.c_str(),
                       mean (row->precision),
                       mean (row->recall),
                       mean (row->f1),
                       row->flagged,
                       s,
                       row == &group.ours ? "-" : ratio (s, ours_s).c_str());
        }
        mismatches += group.mismatches;
        failures += group.failures;
        groups.push_back (group);
      }
    }
  }
  catch (const pcl::PCLException& error) {
    std::fprintf (stderr, "%s\n", pcl::tda::errorMessage (error).c_str());
    return 1;
  }
  if (mismatches)
    std::printf ("\nWarning: the sweep's flags differ from "
                 "pcl::BoundaryEstimation::compute() at %zu points.\n",
                 mismatches);
  if (failures)
    std::printf ("\nWarning: ours failed (no output; see stderr) on %zu surfaces.\n",
                 failures);

  std::printf (
      "\n### Holes found by ours\n\nA true hole is found when a rim's centroid lies "
      "within half the hole's radius of its centre. Recall = found true holes / true "
      "holes; precision = rims matching a distinct true hole / rims. On a closed "
      "surface (sphere, torus) the rims of k holes span only k - 1 homology classes, "
      "so homology guarantees no more than k - 1 of them (column k - 1 bound; k "
      "elsewhere); matched per surface shows where more were found.\n\n");
  std::printf (
      "| kind | noise (h) | true holes | k - 1 bound | rims | matched | matched "
      "per surface | recall | precision |\n|---|---|---|---|---|---|---|---|---|"
      "\n");
  for (const GroupResult& group : groups) {
    const HoleCounts& c = group.holes;
    std::printf ("| %s | %.2f | %zu | %zu | %zu | %zu | %s | %.3f | %.3f |\n",
                 group.kind.c_str(),
                 group.noise,
                 c.truth,
                 c.findable,
                 c.found,
                 c.matched,
                 group.matched_per_surface.c_str(),
                 c.truth ? static_cast<double> (c.matched) / c.truth : 0.0,
                 c.found ? static_cast<double> (c.matched) / c.found : 0.0);
  }

  std::printf (
      "\n### Filling the holes ours found\n\n`HoleFilling` (surface mode, its "
      "defaults) on the rims of ours, scored against the samples the holes cut out "
      "(`HoleSurface::cut`, on the noise-free surface): the distance from each new "
      "point to the nearest cut sample (median and 90th percentile over the new "
      "points, in h), the cut samples of the found holes with a new point within "
      "1.5 h, and the found holes that `HoleBoundaryEstimation` at its defaults finds "
      "again on the filled cloud (0: the filling removed them from H1).\n\n");
  std::printf ("| kind | noise (h) | new points per surface | to cut samples, median "
               "(h) | 90th percentile (h) | cut samples covered | holes found again "
               "|\n|---|---|---|---|---|---|---|\n");
  for (const GroupResult& group : groups) {
    const FillingScore& f = group.filling;
    std::vector<double> distances = f.distances;
    std::sort (distances.begin(), distances.end());
    const auto percentile = [&distances] (double q) {
      return distances.empty() ? std::nan ("")
                               : distances[static_cast<std::size_t> (
                                     q * static_cast<double> (distances.size() - 1))];
    };
    std::printf ("| %s | %.2f | %.0f | %s | %s | %zu / %zu | %zu / %zu |\n",
                 group.kind.c_str(),
                 group.noise,
                 static_cast<double> (f.new_points) / options.scenes,
                 pcl::tda::bench::tableCell (percentile (0.5)).c_str(),
                 pcl::tda::bench::tableCell (percentile (0.9)).c_str(),
                 f.covered,
                 f.cut_samples,
                 f.found_again,
                 f.filled);
  }

  std::printf ("\n### Summary: mean per-point F1 and time ratio\n\n");
  std::printf (
      "| kind | noise (h) | ours F1 | PCL tutorial F1 | PCL best F1 | PCL best "
      "setting | PCL best / ours time |\n|---|---|---|---|---|---|---|\n");
  std::ostringstream json;
  json << "{\"surfaces\":[";
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const GroupResult& group = groups[g];
    const double ours_s = median (group.ours.times);
    const double best_s = median (group.best.times);
    const std::string& setting = group.best_setting;
    std::printf ("| %s | %.2f | %.3f | %.3f | %.3f | %s | %s |\n",
                 group.kind.c_str(),
                 group.noise,
                 mean (group.ours.f1),
                 mean (group.tutorial.f1),
                 mean (group.best.f1),
                 setting.c_str(),
                 ratio (best_s, ours_s).c_str());
    const HoleCounts& c = group.holes;
    json << (g ? "," : "") << "{\"kind\":\"" << group.kind
         << "\",\"noise\":" << group.noise << ",\"ours_f1\":" << mean (group.ours.f1)
         << ",\"pcl_tutorial_f1\":" << mean (group.tutorial.f1)
         << ",\"pcl_best_f1\":" << mean (group.best.f1) << ",\"pcl_best\":\"" << setting
         << "\",\"hole_recall\":"
         << (c.truth ? static_cast<double> (c.matched) / c.truth : 0.0)
         << ",\"hole_precision\":"
         << (c.found ? static_cast<double> (c.matched) / c.found : 0.0)
         << ",\"ours_s\":" << ours_s
         << ",\"pcl_tutorial_s\":" << median (group.tutorial.times)
         << ",\"pcl_best_s\":" << best_s << ",\"filled_holes\":" << group.filling.filled
         << ",\"found_again\":" << group.filling.found_again << "}";
  }
  json << "],\"scans\":[";

  // Section 2: the thesis setting on real scans.
  std::printf ("\n### Real scans with points removed at random (thesis Sec 5.6, "
               "Tables 5.1-5.3 analogue)\n\n");
  std::printf (
      "Non-finite points dropped, then 10, 20 or 30 %% of the points removed at "
      "random (seed %llu). Ours at its defaults; edges, triangles: its complex, up "
      "to the persistence radius (the triangles counted, not listed); beta1: the "
      "1-classes open at the radius; persistent: those still open at the persistence "
      "radius, searched for holes with the polygons around borders; holes: rims "
      "reported; new points: `HoleFilling` (surface mode) in those holes; new to "
      "removed: the median distance from a new point to the nearest removed point, "
      "in spacings h = radius / %.1f (the holes found are mostly the scan's own, "
      "which no removed point lies in: there it measures how far the hole reaches, "
      "not an error). PCL: "
      "`pcl::NormalEstimationOMP` and `pcl::BoundaryEstimation` both at our used "
      "radius, angle pi/2 (so about 8 neighbours per point: PCL's normals are rough at "
      "this radius and it flags many points). No ground truth: flagged points only. "
      "Times: median of %d runs.\n\n",
      static_cast<unsigned long long> (options.seed),
      Ours::AUTO_RADIUS_PER_SPACING,
      options.runs);
  std::printf (
      "| cloud | removed | points | radius | edges | triangles | beta1 | persistent | "
      "holes | ours (s) | PCL (s) | PCL / ours | ours flagged | PCL flagged | new "
      "points | new to removed (h) |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  bool first = true;
  for (const std::string name : {"milk.pcd",
                                 "rops_cloud.pcd",
                                 "bunny.pcd",
                                 "car6.pcd",
                                 "kinect_frame.pcd",
                                 "table_scene_mug_stereo_textured.pcd"}) {
    Cloud::Ptr raw (new Cloud);
    if (pcl::io::loadPCDFile (options.data + "/" + name, *raw) < 0) {
      std::printf ("| %s | (not found in %s) |\n", name.c_str(), options.data.c_str());
      continue;
    }
    Cloud::Ptr finite (new Cloud);
    pcl::Indices unused;
    pcl::removeNaNFromPointCloud (*raw, *finite, unused);
    for (const double fraction : {0.1, 0.2, 0.3}) {
      const Removal removal = removeAtRandom (*finite, fraction, options.seed);
      std::fprintf (stderr, "%s, %.0f %% removed\n", name.c_str(), 100.0 * fraction);
      const ScanResult r = benchScan (name, removal, fraction, options);
      std::printf (
          "| %s | %.0f %% | %zu | %.5g | %zu | %llu | %zu | %zu | %zu | %.3f | %.3f | "
          "%.2f | %s | %zu | %zu | %s |\n",
          name.c_str(),
          100.0 * fraction,
          r.points,
          r.radius,
          r.edges,
          static_cast<unsigned long long> (r.triangles),
          r.beta1,
          r.persistent,
          r.holes,
          r.ours_s,
          r.pcl_s,
          r.pcl_s / r.ours_s,
          r.failed ? "failed" : std::to_string (r.ours_flagged).c_str(),
          r.pcl_flagged,
          r.new_points,
          pcl::tda::bench::tableCell (r.fill_distance).c_str());
      json << (first ? "" : ",") << "{\"cloud\":\"" << name
           << "\",\"removed\":" << fraction << ",\"points\":" << r.points
           << ",\"beta1\":" << r.beta1 << ",\"persistent\":" << r.persistent
           << ",\"holes\":" << r.holes << ",\"edges\":" << r.edges
           << ",\"triangles\":" << r.triangles << ",\"new_points\":" << r.new_points
           << ",\"ours_s\":" << r.ours_s << ",\"pcl_s\":" << r.pcl_s << "}";
      first = false;
    }
  }
  json << "]}";
  std::printf ("\n%s\n", json.str().c_str());
  return 0;
}
