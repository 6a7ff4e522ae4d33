// pcl_tda_bench_persistence: H0 + H1 persistence of a point cloud's Vietoris-Rips
// filtration by our pipeline against Ripser (point-cloud and sparse modes), GUDHI and
// PHAT's five reductions, and our H1 engines against each other, all on the same
// points, radius and complex in the same run: medians of several runs, min and max,
// ratios, whether the diagrams (and PHAT's pairs) agree, peak memory.
//
// Usage: pcl_tda_bench_persistence input.pcd radius [options]
//        pcl_tda_bench_persistence input.pcd -find-radius DEGREE [options]
// The readable report goes to stdout as markdown tables; the last stdout line is one
// JSON object. Exit status: 0 when all diagrams agree, 2 when some differ, 1 on error.

#include <pcl/common/common.h>
#include <pcl/filters/filter.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/apps/voxel_grid_filter.h>
#include <pcl/tda/common/diagram_comparison.h>
#include <pcl/tda/common/diagram_io.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/persistence_engines.h>
#include <pcl/tda/search/clique_persistence.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#include <fcntl.h>
#include <gudhi/distance_functions.h>
#include <gudhi/Flag_complex_edge_collapser.h>
#include <gudhi/Persistent_cohomology.h>
#include <gudhi/Rips_complex.h>
#include <gudhi/Simplex_tree.h>
#include <omp.h>
#include <phat/algorithms/chunk_reduction.h>
#include <phat/algorithms/row_reduction.h>
#include <phat/algorithms/spectral_sequence_reduction.h>
#include <phat/algorithms/standard_reduction.h>
#include <phat/algorithms/twist_reduction.h>
#include <phat/compute_persistence_pairs.h>
#include <phat/representations/default_representations.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Clock = std::chrono::steady_clock;

#include "bench_command_line.h"
#include "common/test_utils.h"

namespace {

const std::vector<std::string> PHAT_REDUCTIONS = {
    "standard", "twist", "chunk", "row", "spectral_sequence"};
// Our engines on the complex with its triangles listed; "cohomology" is the default
// engine's reduction there, the default pipeline enumerating the triangles instead.
const std::vector<std::string> OUR_ENGINES = {
    "cohomology", "standard", "incremental", "fip"};

struct Options {
  std::string input;
  double radius = 0.0;
  double find_degree = 0.0;
  int points = 0;
  unsigned int seed = 1;
  int runs = 3;
  double leaf = 0.0;
  std::set<std::string> tools;
};

void
printUsage (std::FILE* stream)
{
  std::fprintf (
      stream,
      "Usage: pcl_tda_bench_persistence input.pcd radius [options]\n"
      "       pcl_tda_bench_persistence input.pcd -find-radius DEGREE [options]\n"
      "Times H0 + H1 persistence of the Vietoris-Rips filtration up to radius by our\n"
      "pipeline, Ripser, GUDHI and PHAT on the same points and compares the diagrams.\n"
      "  -n N          random subsample of N points (larger than the cloud: jittered\n"
      "                copies are added first)\n"
      "  -seed S       seed of the subsample and of the jitter (default 1)\n"
      "  -leaf L       voxel grid of leaf L first (default: off)\n"
      "  -runs R       runs per measurement, at least 5 for those under a second;\n"
      "                medians reported (default 3)\n"
      "  -tools LIST   comma-separated reference tools (default all; ours always "
      "runs):\n"
      "                ripser (point-cloud mode), ripser-sparse (on our edges), "
      "gudhi,\n"
      "                gudhi-collapse (GUDHI's edge collapse of our edges, then our\n"
      "                H0 + H1 on the edges it keeps),\n"
      "                phat-standard, phat-twist, phat-chunk, phat-row,\n"
      "                phat-spectral_sequence (PHAT's reductions of our complex; "
      "phat:\n"
      "                all five), our H1 engines on the listed triangles cohomology,\n"
      "                standard, incremental, fip (engines: all four), all\n"
      "  -find-radius DEGREE  instead of benchmarking, print the radius at which the\n"
      "                complex has average vertex degree DEGREE (2 edges / points)\n");
}

/** Adds the tools of a -tools list: tool names and the groups phat, engines, all.
 * \throws pcl::BadArgumentException on an unknown name */
void
parseTools (const std::string& list, std::set<std::string>& tools)
{
  std::set<std::string> phat,
      known = {"ripser", "ripser-sparse", "gudhi", "gudhi-collapse"};
  for (const std::string& reduction : PHAT_REDUCTIONS)
    phat.insert ("phat-" + reduction);
  known.insert (phat.begin(), phat.end());
  known.insert (OUR_ENGINES.begin(), OUR_ENGINES.end());
  std::istringstream items (list);
  std::string item;
  while (std::getline (items, item, ',')) {
    if (item == "all")
      tools.insert (known.begin(), known.end());
    else if (item == "phat")
      tools.insert (phat.begin(), phat.end());
    else if (item == "engines")
      tools.insert (OUR_ENGINES.begin(), OUR_ENGINES.end());
    else if (known.count (item))
      tools.insert (item);
    else if (!item.empty())
      PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                           "Unknown tool '" << item << "' in -tools.");
  }
}

/** \throws pcl::BadArgumentException on a bad command line */
void
parseOptions (int argc, char** argv, Options& options)
{
  long points = options.points, seed = options.seed, runs = options.runs;
  std::string tools = "all";
  pcl::tda::ToolCommandLine command_line;
  command_line.addNumber (
      "-find-radius", options.find_degree, pcl::tda::NumberRange::above (0.0));
  command_line.addInteger ("-n", points, 0, 1000000000L);
  command_line.addInteger ("-seed", seed, 0, 0xffffffffL);
  command_line.addInteger ("-runs", runs, 1, 1000);
  command_line.addNumber ("-leaf", options.leaf, pcl::tda::NumberRange::atLeast (0.0));
  command_line.addText ("-tools", tools);
  const std::vector<std::string> arguments = command_line.parse (argc, argv);
  const bool find_radius = command_line.given ("-find-radius");
  if (arguments.size() != (find_radius ? 1u : 2u))
    PCL_THROW_EXCEPTION (
        pcl::BadArgumentException,
        "Give the input file and "
            << (find_radius ? "no radius (-find-radius chooses it)." : "the radius."));
  options.input = arguments[0];
  if (!find_radius)
    options.radius = pcl::tda::bench::positiveNumber (arguments[1], "radius", false);
  options.points = static_cast<int> (points);
  options.seed = static_cast<unsigned int> (seed);
  options.runs = static_cast<int> (runs);
  parseTools (tools, options.tools);
}

// ---------------------------------------------------------------------------------
// Measurements

/** Median, smallest and largest of the times of several runs, in seconds. */
struct Stats {
  double median = 0.0, min = 0.0, max = 0.0;
  std::size_t runs = 0;
};

Stats
summarize (std::vector<double> values)
{
  std::sort (values.begin(), values.end());
  const std::size_t n = values.size();
  return {n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]),
          values.front(),
          values.back(),
          n};
}

/** Whether a measurement needs another run: it gets at least \a runs, and at least 5
 * while its median is under a second (see BENCHMARKS.md). */
bool
needsRun (const std::vector<double>& times, int runs)
{
  const auto done = static_cast<int> (times.size());
  return done < runs || (done < 5 && summarize (times).median < 1.0);
}

double
secondsSince (Clock::time_point start)
{
  return std::chrono::duration<double> (Clock::now() - start).count();
}

/** Peak resident memory of this process so far, in bytes. */
std::size_t
peakMemory ()
{
  rusage usage{};
  getrusage (RUSAGE_SELF, &usage);
  return static_cast<std::size_t> (usage.ru_maxrss) * 1024;
}

/** Times of the runs of one subprocess and the largest peak memory among them. */
struct ProcessMeasurement {
  bool ran = false;
  Stats seconds;
  /** 0 when unknown (no /usr/bin/time). */
  std::size_t peak_memory = 0;
};

/** Where a subprocess writes its stdout, its stderr and its peak memory. */
struct ProcessFiles {
  std::string out, err, memory;
};

/** GNU time: it measures a child it forks itself, while a child forked from this
 * large process would count this process's pages in its peak memory. */
const char* const GNU_TIME = "/usr/bin/time";

/** Runs \a args (no shell), stdout and stderr into \a files; wall-clock seconds and
 * peak memory in bytes (0 when unknown). Throws when the command fails. */
std::pair<double, std::size_t>
runProcess (std::vector<std::string> args, const ProcessFiles& files)
{
  const bool gnu_time = access (GNU_TIME, X_OK) == 0;
  if (gnu_time)
    args.insert (args.begin(), {GNU_TIME, "-f", "%M", "-o", files.memory});
  std::vector<char*> argv;
  for (const std::string& arg : args)
    argv.push_back (const_cast<char*> (arg.c_str()));
  argv.push_back (nullptr);
  // posix_spawn, not fork(): a fork copies the page tables of this large process
  // (milliseconds at a few hundred MiB), which would count in the child's time.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init (&actions);
  posix_spawn_file_actions_addopen (
      &actions, 1, files.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen (
      &actions, 2, files.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  const auto start = Clock::now();
  pid_t pid = 0;
  const int spawned =
      posix_spawnp (&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy (&actions);
  int status = 0;
  if (spawned != 0 || waitpid (pid, &status, 0) != pid)
    throw std::runtime_error ("cannot start " + args[0]);
  const double seconds = secondsSince (start);
  if (!WIFEXITED (status) || WEXITSTATUS (status) != 0) {
    std::ifstream err (files.err);
    const std::string message ((std::istreambuf_iterator<char> (err)),
                               std::istreambuf_iterator<char>());
    std::string command;
    for (const std::string& arg : args)
      command += " " + arg;
    throw std::runtime_error ("failed:" + command + "\n" + message.substr (0, 2000));
  }
  std::size_t kibibytes = 0;
  if (gnu_time && !(std::ifstream (files.memory) >> kibibytes))
    throw std::runtime_error ("no peak memory from " + std::string (GNU_TIME));
  return {seconds, kibibytes * 1024};
}

ProcessMeasurement
measureProcess (const std::vector<std::string>& args,
                const ProcessFiles& files,
                int runs)
{
  ProcessMeasurement measurement;
  std::vector<double> times;
  while (needsRun (times, runs)) {
    const auto [seconds, memory] = runProcess (args, files);
    times.push_back (seconds);
    measurement.peak_memory = std::max (measurement.peak_memory, memory);
  }
  measurement.ran = true;
  measurement.seconds = summarize (times);
  return measurement;
}

/** The shortest text that reads back as exactly \a value. */
std::string
formatDouble (double value)
{
  return pcl::tda::formatFiltrationValue (value);
}

/** \a text as a JSON string. */
std::string
jsonString (const std::string& text)
{
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\')
      quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

// ---------------------------------------------------------------------------------
// Input

/** Loads the finite points of the PCD file, applies the voxel grid and the
 * subsample (enlarged by jittered copies when more points are asked for, which sets
 * \a jittered). */
Cloud::Ptr
loadPoints (const Options& options, std::size_t& loaded, bool& jittered)
{
  Cloud::Ptr cloud (new Cloud);
  if (pcl::io::loadPCDFile (options.input, *cloud) < 0)
    throw std::runtime_error ("cannot read " + options.input);
  loaded = cloud->size();
  cloud->is_dense = false;
  pcl::Indices finite;
  pcl::removeNaNFromPointCloud (*cloud, *cloud, finite);
  if (options.leaf > 0.0) {
    cloud = pcl::tda::voxelGridFilter<pcl::PointXYZ> (cloud, options.leaf);
  }
  if (cloud->empty())
    throw std::runtime_error ("no finite point in " + options.input);
  if (options.points == 0)
    return cloud;

  std::mt19937_64 random (options.seed);
  const std::size_t original = cloud->size();
  const auto wanted = static_cast<std::size_t> (options.points);
  jittered = wanted > original;
  if (jittered) {
    pcl::PointXYZ low, high;
    pcl::getMinMax3D (*cloud, low, high);
    const double sigma = 1e-4 * (high.getVector3fMap() - low.getVector3fMap()).norm();
    std::normal_distribution<double> noise (0.0, sigma);
    cloud->reserve (wanted + original);
    while (cloud->size() < wanted)
      for (std::size_t i = 0; i < original; ++i) {
        const pcl::PointXYZ& p = (*cloud)[i];
        cloud->push_back (pcl::PointXYZ (static_cast<float> (p.x + noise (random)),
                                         static_cast<float> (p.y + noise (random)),
                                         static_cast<float> (p.z + noise (random))));
      }
  }
  // Partial Fisher-Yates shuffle; the chosen points keep their order.
  std::vector<std::size_t> order (cloud->size());
  std::iota (order.begin(), order.end(), 0);
  for (std::size_t i = 0; i < wanted; ++i)
    std::swap (order[i],
               order[std::uniform_int_distribution<std::size_t> (i, order.size() - 1) (
                   random)]);
  order.resize (wanted);
  std::sort (order.begin(), order.end());
  Cloud::Ptr sample (new Cloud);
  sample->reserve (wanted);
  for (const std::size_t i : order)
    sample->push_back ((*cloud)[i]);
  return sample;
}

void
writePointsText (const std::string& path, const Cloud& cloud)
{
  FILE* out = std::fopen (path.c_str(), "w");
  if (!out)
    throw std::runtime_error ("cannot write " + path);
  for (const auto& p : cloud)
    std::fprintf (out, "%.9g %.9g %.9g\n", p.x, p.y, p.z);
  if (std::fclose (out) != 0)
    throw std::runtime_error ("cannot write " + path);
}

/** Ripser's sparse format: `i j d` per edge, 0-based vertex ids. \return the number
 * of vertices Ripser will see (1 + the largest id). */
std::size_t
writeEdgesText (const std::string& path, const pcl::tda::FilteredComplex& complex)
{
  FILE* out = std::fopen (path.c_str(), "w");
  if (!out)
    throw std::runtime_error ("cannot write " + path);
  std::size_t vertices = 0;
  for (const auto& edge : complex.edges()) {
    std::fprintf (out, "%u %u %.17g\n", edge.source, edge.target, edge.value);
    vertices = std::max<std::size_t> (vertices, edge.target + 1);
  }
  if (std::fclose (out) != 0)
    throw std::runtime_error ("cannot write " + path);
  return vertices;
}

// ---------------------------------------------------------------------------------
// Our pipeline

struct OursMeasurement {
  Stats total, build, h0, h1;
  pcl::tda::VietorisRipsTimings build_phases;
  /** The complex with its triangles listed (built once, untimed), which our other
   * engines and PHAT reduce, and its persistence by the cohomology engine. */
  pcl::tda::FilteredComplex complex;
  pcl::tda::PersistenceResult result;
  pcl::tda::PersistenceDiagram diagram;
};

/** Point cloud in memory to H0 + H1 diagram as pcl_tda_barcode computes it by
 * default: the edges, H0, and H1 of their clique complex with the triangles
 * enumerated, not listed (computeCliqueH1Persistence()). */
OursMeasurement
measureOurs (const Cloud::ConstPtr& cloud, double radius, int runs)
{
  OursMeasurement ours;
  std::vector<double> total, build, h0, h1;
  pcl::tda::VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (radius);
  while (needsRun (total, runs)) {
    // Free the last run's diagram first: the peak memory is that of one run.
    ours = OursMeasurement();
    const auto start = Clock::now();
    builder.setMaxDimension (1);
    pcl::tda::FilteredComplex skeleton;
    if (!builder.compute (skeleton))
      throw std::runtime_error ("the Vietoris-Rips builder failed");
    build.push_back (secondsSince (start));
    const auto h0_start = Clock::now();
    const pcl::tda::PersistenceResult result =
        pcl::tda::computeH0Persistence (skeleton);
    h0.push_back (secondsSince (h0_start));
    const auto h1_start = Clock::now();
    const pcl::tda::CliqueH1Persistence clique =
        pcl::tda::computeCliqueH1Persistence (skeleton, result);
    pcl::tda::PersistenceDiagram diagram = result.diagram (skeleton, 0);
    diagram.insert (diagram.end(), clique.diagram.begin(), clique.diagram.end());
    h1.push_back (secondsSince (h1_start));
    total.push_back (build.back() + h0.back() + h1.back());
    ours.build_phases = builder.getTimings();
    ours.diagram = std::move (diagram);
  }
  ours.total = summarize (total);
  ours.build = summarize (build);
  ours.h0 = summarize (h0);
  ours.h1 = summarize (h1);
  return ours;
}

/** Adds to \a ours the complex with its triangles listed and its persistence. */
void
listTriangles (const Cloud::ConstPtr& cloud, double radius, OursMeasurement& ours)
{
  pcl::tda::VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (radius);
  if (!builder.compute (ours.complex))
    throw std::runtime_error ("the Vietoris-Rips builder failed");
  ours.result = pcl::tda::computePersistence (ours.complex);
}

// ---------------------------------------------------------------------------------
// In-process references

struct EngineMeasurement {
  std::string name;
  Stats h1;
  bool agree = false;
};

/** H1 by \a engine given H0, compared with the default engine's diagram. */
EngineMeasurement
measureEngine (const OursMeasurement& ours,
               pcl::tda::PersistenceEngine engine,
               int runs)
{
  std::vector<double> times;
  pcl::tda::PersistenceResult result;
  while (needsRun (times, runs)) {
    result = pcl::tda::computeH0Persistence (ours.complex);
    const auto start = Clock::now();
    pcl::tda::addH1Persistence (ours.complex, engine, result);
    times.push_back (secondsSince (start));
  }
  return {
      pcl::tda::engineName (engine),
      summarize (times),
      pcl::tda::compareDiagrams (result.diagram (ours.complex, 1), ours.diagram, 1e-5)
          .equal};
}

struct PHATMeasurement {
  std::string name;
  Stats matrix, reduction;
  bool agree = false;
};

/** PHAT's boundary matrix of \a complex in our global filtration order. */
void
buildPHATMatrix (const pcl::tda::FilteredComplex& complex,
                 phat::boundary_matrix<phat::bit_tree_pivot_column>& matrix)
{
  const auto order = complex.filtrationOrder();
  std::vector<phat::index> edge_position (complex.numEdges());
  matrix.set_num_cols (static_cast<phat::index> (order.size()));
  phat::column column;
  for (std::size_t g = 0; g < order.size(); ++g) {
    const auto index = static_cast<phat::index> (g);
    const pcl::tda::SimplexRef simplex = order[g];
    matrix.set_dim (index, static_cast<phat::dimension> (simplex.dimension));
    if (simplex.dimension == 0)
      continue;
    if (simplex.dimension == 1) {
      edge_position[simplex.index] = index;
      const auto& edge = complex.edges()[simplex.index];
      column = {edge.source, edge.target};
    }
    else {
      const auto& edges = complex.triangles()[simplex.index].edges;
      column = {
          edge_position[edges[0]], edge_position[edges[1]], edge_position[edges[2]]};
      std::sort (column.begin(), column.end());
    }
    matrix.set_col (index, column);
  }
}

/** Matrix construction and reduction by \a Algorithm with \a threads OpenMP threads
 * (0: the default); the pairs compared with ours exactly. */
template <typename Algorithm>
PHATMeasurement
measurePHAT (const std::string& name,
             const OursMeasurement& ours,
             const std::vector<std::pair<std::int64_t, std::int64_t>>& our_pairs,
             int runs,
             int threads = 0)
{
  std::vector<double> matrix_times, reduction_times;
  phat::persistence_pairs pairs;
  while (needsRun (reduction_times, runs)) {
    const auto start = Clock::now();
    phat::boundary_matrix<phat::bit_tree_pivot_column> matrix;
    buildPHATMatrix (ours.complex, matrix);
    matrix_times.push_back (secondsSince (start));
    const int previous_threads = omp_get_max_threads();
    if (threads > 0)
      omp_set_num_threads (threads);
    const auto reduction_start = Clock::now();
    phat::compute_persistence_pairs<Algorithm> (pairs, matrix);
    reduction_times.push_back (secondsSince (reduction_start));
    omp_set_num_threads (previous_threads);
  }
  pairs.sort();
  bool agree = static_cast<std::size_t> (pairs.get_num_pairs()) == our_pairs.size();
  for (std::size_t p = 0; agree && p < our_pairs.size(); ++p)
    agree = pairs.get_pair (static_cast<phat::index> (p)) == our_pairs[p];
  return {name, summarize (matrix_times), summarize (reduction_times), agree};
}

struct GUDHIMeasurement {
  bool ran = false;
  Stats construction, persistence, total;
  std::size_t simplices = 0;
  pcl::tda::PersistenceDiagram diagram;
};

/** GUDHI's Rips_complex and Simplex_tree of dimension 2, persistent cohomology over
 * Z2; distances in double precision like ours. */
GUDHIMeasurement
measureGUDHI (const Cloud& cloud, double radius, int runs)
{
  using SimplexTree = Gudhi::Simplex_tree<>;
  using Cohomology = Gudhi::persistent_cohomology::
      Persistent_cohomology<SimplexTree, Gudhi::persistent_cohomology::Field_Zp>;
  std::vector<std::array<double, 3>> points;
  points.reserve (cloud.size());
  for (const auto& p : cloud)
    points.push_back ({p.x, p.y, p.z});

  GUDHIMeasurement gudhi;
  std::vector<double> construction, persistence, total;
  while (needsRun (total, runs)) {
    const auto start = Clock::now();
    SimplexTree tree;
    {
      Gudhi::rips_complex::Rips_complex<double> rips (
          points, radius, Gudhi::Euclidean_distance());
      rips.create_complex (tree, 2);
    }
    construction.push_back (secondsSince (start));
    const auto persistence_start = Clock::now();
    // GUDHI leaves the complex's top dimension out: H1 needs it where there is no
    // triangle (a lattice at its step); elsewhere H2 would be computed for nothing.
    Cohomology cohomology (tree, tree.dimension() < 2);
    cohomology.init_coefficients (2);
    // Minimum interval length 0: GUDHI drops the zero-length intervals, which the
    // diagram comparison ignores anyway.
    cohomology.compute_persistent_cohomology();
    persistence.push_back (secondsSince (persistence_start));
    total.push_back (construction.back() + persistence.back());
    gudhi.simplices = tree.num_simplices();
    gudhi.diagram.clear();
    for (int dimension = 0; dimension <= 1; ++dimension)
      for (const auto& [birth, death] : cohomology.intervals_in_dimension (dimension))
        gudhi.diagram.push_back ({dimension, birth, death});
  }
  gudhi.ran = true;
  gudhi.construction = summarize (construction);
  gudhi.persistence = summarize (persistence);
  gudhi.total = summarize (total);
  return gudhi;
}

struct EdgeCollapseMeasurement {
  bool ran = false;
  Stats collapse, persistence; // GUDHI's collapse; our H0 + H1 on the edges it keeps
  std::size_t kept_edges = 0;
  pcl::tda::PersistenceDiagram diagram;
};

/** Edge collapse as a step before our H0 + H1 (thesis-independent; Boissonnat and
 * Pritam, SoCG 2020, as GUDHI 3.7 implements it after Glisse and Pritam, SoCG 2022):
 * GUDHI's collapse of our edges, which keeps the diagram of the flag filtration, then
 * our H0 and H1 (triangles enumerated, as by default) on the edges it keeps. */
EdgeCollapseMeasurement
measureEdgeCollapse (const pcl::tda::FilteredComplex& complex, int runs)
{
  using GUDHIEdge = std::tuple<pcl::tda::SimplexIndex, pcl::tda::SimplexIndex, double>;
  std::vector<GUDHIEdge> edges;
  edges.reserve (complex.numEdges());
  for (const auto& edge : complex.edges())
    edges.emplace_back (edge.source, edge.target, edge.value);

  EdgeCollapseMeasurement measurement;
  std::vector<double> collapse, persistence;
  while (needsRun (collapse, runs)) {
    const auto start = Clock::now();
    const auto kept = Gudhi::collapse::flag_complex_collapse_edges (edges);
    collapse.push_back (secondsSince (start));
    std::vector<pcl::tda::FilteredEdge> kept_edges;
    kept_edges.reserve (kept.size());
    for (const auto& [u, v, value] : kept)
      kept_edges.push_back ({std::min (u, v), std::max (u, v), value});
    std::sort (kept_edges.begin(), kept_edges.end(), pcl::tda::EdgeFiltrationLess());
    measurement.kept_edges = kept_edges.size();
    const pcl::tda::FilteredComplex collapsed = pcl::tda::FilteredComplex (
        complex.numVertices(), std::move (kept_edges), {}, complex.pointIndices());

    const auto persistence_start = Clock::now();
    const pcl::tda::PersistenceResult h0 = pcl::tda::computeH0Persistence (collapsed);
    const pcl::tda::CliqueH1Persistence h1 =
        pcl::tda::computeCliqueH1Persistence (collapsed, h0);
    persistence.push_back (secondsSince (persistence_start));
    measurement.diagram = h0.diagram (collapsed, 0);
    measurement.diagram.insert (
        measurement.diagram.end(), h1.diagram.begin(), h1.diagram.end());
  }
  measurement.ran = true;
  measurement.collapse = summarize (collapse);
  measurement.persistence = summarize (persistence);
  return measurement;
}

// ---------------------------------------------------------------------------------
// Radius search

/** Edges of the complex of radius \a radius (dimension 1 only). */
std::size_t
countEdges (const Cloud::ConstPtr& cloud, double radius)
{
  pcl::tda::VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (radius);
  builder.setMaxDimension (1);
  pcl::tda::FilteredComplex complex;
  if (!builder.compute (complex))
    throw std::runtime_error ("the Vietoris-Rips builder failed");
  return complex.numEdges();
}

/** Bisects on the radius until 2 * edges / points is within 0.5% of the degree
 * asked for, and prints that radius. */
int
findRadius (const Options& options, const Cloud::ConstPtr& cloud)
{
  const double target = options.find_degree;
  const double points = static_cast<double> (cloud->size());
  if (target >= points - 1.0)
    throw std::runtime_error ("the average degree must be below points - 1");
  const auto degree = [&] (double radius) {
    return 2.0 * static_cast<double> (countEdges (cloud, radius)) / points;
  };
  pcl::PointXYZ low, high;
  pcl::getMinMax3D (*cloud, low, high);
  const double diagonal = (high.getVector3fMap() - low.getVector3fMap()).norm();
  if (!(diagonal > 0.0))
    throw std::runtime_error ("all points are equal");
  // Bracket the degree between radii below and above, then bisect.
  double below = 1e-3 * diagonal, above = below;
  while (degree (above) < target)
    above *= 2.0;
  for (int halvings = 0; degree (below) >= target; ++halvings) {
    if (halvings == 60)
      throw std::runtime_error ("the degree stays that high at tiny radii: many "
                                "duplicate points?");
    below *= 0.5;
  }
  double radius = above, found = degree (above);
  for (int step = 0; step < 60 && std::abs (found - target) > 0.005 * target; ++step) {
    radius = 0.5 * (below + above);
    found = degree (radius);
    (found < target ? below : above) = radius;
  }
  std::printf ("| input | points | leaf | target degree | radius | degree |\n"
               "|---|---|---|---|---|---|\n"
               "| %s | %zu | %g | %g | %.6g | %.3f |\n",
               options.input.c_str(),
               cloud->size(),
               options.leaf,
               options.find_degree,
               radius,
               found);
  std::printf ("{\"input\": %s, \"points\": %zu, \"leaf\": %g, \"target_degree\": "
               "%g, \"radius\": %.6g, \"degree\": %.6f}\n",
               jsonString (options.input).c_str(),
               cloud->size(),
               options.leaf,
               options.find_degree,
               radius,
               found);
  return 0;
}

// ---------------------------------------------------------------------------------
// Report

/** Everything one benchmark run measured. */
struct Results {
  std::string name;
  std::size_t points_read = 0, points = 0;
  std::size_t beta1 = 0, complex_bytes = 0;
  std::size_t memory_loaded = 0, memory_ours = 0, memory_end = 0;
  ProcessMeasurement ours_process, ripser, ripser_sparse;
  bool process_agrees = false, ripser_agrees = false, sparse_agrees = false;
  bool gudhi_agrees = false, collapse_agrees = false;
  std::size_t sparse_missing = 0;
  GUDHIMeasurement gudhi;
  EdgeCollapseMeasurement collapse;
  std::vector<PHATMeasurement> phat;
  std::vector<EngineMeasurement> engines;

  bool
  allAgree () const
  {
    bool agree = process_agrees && (!ripser.ran || ripser_agrees) &&
                 (!ripser_sparse.ran || sparse_agrees) &&
                 (!gudhi.ran || gudhi_agrees) && (!collapse.ran || collapse_agrees);
    for (const auto& measurement : phat)
      agree &= measurement.agree;
    for (const auto& engine : engines)
      agree &= engine.agree;
    return agree;
  }

  const EngineMeasurement*
  engine (const std::string& engine_name) const
  {
    for (const auto& measurement : engines)
      if (measurement.name == engine_name)
        return &measurement;
    return nullptr;
  }
};

/** Seconds with three decimals, or three significant digits below 0.1 s. */
std::string
seconds (double value)
{
  char text[32];
  std::snprintf (text, sizeof (text), value < 0.1 ? "%.3g" : "%.3f", value);
  return text;
}

std::string
spread (const Stats& stats)
{
  return seconds (stats.median) + " (" + seconds (stats.min) + "-" +
         seconds (stats.max) + ")";
}

/** How many times longer the reference took than ours. */
std::string
times (double reference, double ours)
{
  char text[32];
  std::snprintf (
      text, sizeof (text), "%.*fx", reference < ours ? 2 : 1, reference / ours);
  return text;
}

std::string
json (const Stats& stats)
{
  char text[128];
  std::snprintf (text,
                 sizeof (text),
                 "{\"median\": %.6f, \"min\": %.6f, \"max\": %.6f, \"runs\": %zu}",
                 stats.median,
                 stats.min,
                 stats.max,
                 stats.runs);
  return text;
}

std::string
json (bool value)
{
  return value ? "true" : "false";
}

/** Bytes of a peak memory, null when unknown (0). */
std::string
jsonBytes (std::size_t bytes)
{
  return bytes ? std::to_string (bytes) : "null";
}

double
mebibytes (std::size_t bytes)
{
  return static_cast<double> (bytes) / 1048576.0;
}

void
printRow (const std::vector<std::string>& cells)
{
  std::string row = "|";
  for (const std::string& text : cells)
    row += " " + text + " |";
  std::printf ("%s\n", row.c_str());
}

void
printHeader (const std::vector<std::string>& cells)
{
  printRow (cells);
  printRow (std::vector<std::string> (cells.size(), "---"));
}

const char*
agreement (bool agree)
{
  return agree ? "equal" : "DIFFER";
}

/** Every measurement with its spread, then the three summary tables. */
void
printReport (const Options& options,
             const OursMeasurement& ours,
             const Results& results)
{
  const auto& complex = ours.complex;
  std::printf (
      "\n%s: %zu points read, %zu used, radius %s, %d OpenMP threads, %d runs\n",
      options.input.c_str(),
      results.points_read,
      results.points,
      formatDouble (options.radius).c_str(),
      omp_get_max_threads(),
      options.runs);
  std::printf (
      "complex: %zu vertices, %zu edges, %zu triangles (%.1f MiB); beta1 = %zu\n",
      complex.numVertices(),
      complex.numEdges(),
      complex.numTriangles(),
      mebibytes (results.complex_bytes),
      results.beta1);
  std::printf ("peak memory of this process: %.1f MiB after loading, %.1f MiB after "
               "our pipeline, %.1f MiB at the end\n",
               mebibytes (results.memory_loaded),
               mebibytes (results.memory_ours),
               mebibytes (results.memory_end));
  if (results.sparse_missing > 0)
    std::printf ("Ripser sparse: %zu isolated vertices after its largest vertex id, "
                 "their essential H0 bars added back\n",
                 results.sparse_missing);

  std::printf ("\n### All measurements (seconds; x = reference / ours)\n\n");
  printHeader ({"measurement",
                "runs",
                "median",
                "min",
                "max",
                "x",
                "compared with",
                "agrees",
                "peak MiB"});
  const auto line = [] (const std::string& what,
                        const Stats& stats,
                        const std::string& ratio,
                        const std::string& against,
                        const std::string& agrees,
                        const std::string& memory) {
    printRow ({what,
               std::to_string (stats.runs),
               seconds (stats.median),
               seconds (stats.min),
               seconds (stats.max),
               ratio,
               against,
               agrees,
               memory});
  };
  const auto memory = [] (std::size_t bytes) {
    if (bytes == 0)
      return std::string ("-");
    char text[32];
    std::snprintf (text, sizeof (text), "%.1f", mebibytes (bytes));
    return std::string (text);
  };
  line ("ours, in process: build + H0 + H1",
        ours.total,
        "",
        "",
        "",
        memory (results.memory_ours));
  line ("ours: Vietoris-Rips build", ours.build, "", "", "", "");
  line ("ours: H0 (union-find)", ours.h0, "", "", "", "");
  line ("ours: H1 (default)", ours.h1, "", "", "", "");
  line ("ours, process: pcl_tda_barcode",
        results.ours_process.seconds,
        "",
        "ours in process",
        agreement (results.process_agrees),
        memory (results.ours_process.peak_memory));
  if (results.ripser.ran)
    line ("Ripser point-cloud",
          results.ripser.seconds,
          times (results.ripser.seconds.median, results.ours_process.seconds.median),
          "ours, process",
          agreement (results.ripser_agrees),
          memory (results.ripser.peak_memory));
  if (results.ripser_sparse.ran)
    line ("Ripser sparse, our edges",
          results.ripser_sparse.seconds,
          times (results.ripser_sparse.seconds.median, ours.total.median),
          "ours, in process",
          agreement (results.sparse_agrees),
          memory (results.ripser_sparse.peak_memory));
  if (results.gudhi.ran) {
    line ("GUDHI Rips_complex + Simplex_tree",
          results.gudhi.construction,
          times (results.gudhi.construction.median, ours.build.median),
          "ours: build",
          "",
          "");
    line ("GUDHI Persistent_cohomology",
          results.gudhi.persistence,
          times (results.gudhi.persistence.median, ours.h0.median + ours.h1.median),
          "ours: H0 + H1",
          "",
          "");
    line ("GUDHI total",
          results.gudhi.total,
          times (results.gudhi.total.median, ours.total.median),
          "ours, in process",
          agreement (results.gudhi_agrees),
          "");
  }
  if (results.collapse.ran) {
    line ("GUDHI edge collapse of our edges",
          results.collapse.collapse,
          times (results.collapse.collapse.median, ours.h0.median + ours.h1.median),
          "ours: H0 + H1",
          "",
          "");
    line ("ours: H0 + H1 on the collapsed edges",
          results.collapse.persistence,
          times (results.collapse.persistence.median, ours.h0.median + ours.h1.median),
          "ours: H0 + H1",
          agreement (results.collapse_agrees),
          "");
  }
  for (const auto& measurement : results.phat) {
    line ("PHAT boundary matrix for " + measurement.name,
          measurement.matrix,
          "",
          "",
          "",
          "");
    line ("PHAT " + measurement.name + "_reduction",
          measurement.reduction,
          times (measurement.reduction.median, ours.h1.median),
          "ours: H1 (default)",
          measurement.agree ? "same pairs" : "PAIRS DIFFER",
          "");
  }
  for (const auto& engine : results.engines)
    line ("ours: H1 (" + engine.name + ")",
          engine.h1,
          times (engine.h1.median, ours.h1.median),
          "ours: H1 (default)",
          agreement (engine.agree),
          "");

  const auto median_or_dash = [] (bool ran, const Stats& stats) {
    return ran ? spread (stats) : std::string ("-");
  };
  const auto ratio_or_dash = [] (bool ran, double reference, double ours_median) {
    return ran ? times (reference, ours_median) : std::string ("-");
  };
  std::string differ;
  for (const auto& [ran, agrees, tool] :
       {std::make_tuple (true, results.process_agrees, "pcl_tda_barcode"),
        std::make_tuple (results.ripser.ran, results.ripser_agrees, "ripser"),
        std::make_tuple (results.ripser_sparse.ran, results.sparse_agrees, "sparse"),
        std::make_tuple (results.gudhi.ran, results.gudhi_agrees, "gudhi"),
        std::make_tuple (results.collapse.ran, results.collapse_agrees, "collapse")})
    if (ran && !agrees)
      differ += std::string (differ.empty() ? "" : ", ") + tool;

  std::printf ("\n### End to end, H0 + H1: ours vs Ripser and GUDHI\n\n");
  printHeader ({"input",
                "points",
                "radius",
                "edges",
                "triangles",
                "beta1",
                "ours s",
                "ours process s",
                "Ripser point-cloud s",
                "x",
                "Ripser sparse s",
                "x",
                "GUDHI construct + persistence s",
                "x",
                "diagrams"});
  printRow (
      {results.name,
       std::to_string (results.points),
       formatDouble (options.radius),
       std::to_string (complex.numEdges()),
       std::to_string (complex.numTriangles()),
       std::to_string (results.beta1),
       spread (ours.total),
       spread (results.ours_process.seconds),
       median_or_dash (results.ripser.ran, results.ripser.seconds),
       ratio_or_dash (results.ripser.ran,
                      results.ripser.seconds.median,
                      results.ours_process.seconds.median),
       median_or_dash (results.ripser_sparse.ran, results.ripser_sparse.seconds),
       ratio_or_dash (results.ripser_sparse.ran,
                      results.ripser_sparse.seconds.median,
                      ours.total.median),
       results.gudhi.ran ? seconds (results.gudhi.construction.median) + " + " +
                               seconds (results.gudhi.persistence.median)
                         : "-",
       ratio_or_dash (results.gudhi.ran, results.gudhi.total.median, ours.total.median),
       differ.empty() ? "equal" : "DIFFER: " + differ});

  if (results.collapse.ran) {
    const EdgeCollapseMeasurement& collapse = results.collapse;
    const double ours_persistence = ours.h0.median + ours.h1.median;
    const double with_collapse = collapse.collapse.median + collapse.persistence.median;
    std::printf ("\n### Edge collapse before H0 + H1 (GUDHI's collapse, then ours; "
                 "x = ours without it / with it)\n\n");
    printHeader ({"input",
                  "points",
                  "radius",
                  "edges",
                  "kept edges",
                  "ours H0 + H1 s",
                  "GUDHI collapse s",
                  "ours H0 + H1 after it s",
                  "together s",
                  "x",
                  "diagrams"});
    printRow ({results.name,
               std::to_string (results.points),
               formatDouble (options.radius),
               std::to_string (complex.numEdges()),
               std::to_string (collapse.kept_edges) + " (" +
                   std::to_string (static_cast<int> (
                       std::lround (100.0 * static_cast<double> (collapse.kept_edges) /
                                    static_cast<double> (std::max<std::size_t> (
                                        complex.numEdges(), 1))))) +
                   " %)",
               seconds (ours_persistence),
               spread (collapse.collapse),
               spread (collapse.persistence),
               seconds (with_collapse),
               times (ours_persistence, with_collapse),
               agreement (results.collapse_agrees)});
  }

  if (!results.phat.empty() || !results.engines.empty()) {
    std::printf ("\n### H1 on the same complex: our engines vs PHAT's reductions "
                 "(seconds, x = time / our default H1, which enumerates the "
                 "triangles)\n\n");
    std::vector<std::string> header = {
        "input", "points", "radius", "edges", "triangles", "default H1 s"};
    std::vector<std::string> row = {results.name,
                                    std::to_string (results.points),
                                    formatDouble (options.radius),
                                    std::to_string (complex.numEdges()),
                                    std::to_string (complex.numTriangles()),
                                    seconds (ours.h1.median)};
    bool agree = true;
    for (const std::string& engine_name : OUR_ENGINES) {
      header.push_back (engine_name + " s");
      const EngineMeasurement* engine = results.engine (engine_name);
      row.push_back (engine ? seconds (engine->h1.median) + " (" +
                                  times (engine->h1.median, ours.h1.median) + ")"
                            : "-");
      agree &= !engine || engine->agree;
    }
    header.push_back ("PHAT matrix s");
    row.push_back (results.phat.empty() ? "-"
                                        : seconds (results.phat.front().matrix.median));
    for (const std::string& reduction : PHAT_REDUCTIONS) {
      header.push_back ("PHAT " + reduction + " s");
      const auto found =
          std::find_if (results.phat.begin(),
                        results.phat.end(),
                        [&] (const PHATMeasurement& m) { return m.name == reduction; });
      row.push_back (found == results.phat.end()
                         ? "-"
                         : seconds (found->reduction.median) + " (" +
                               times (found->reduction.median, ours.h1.median) + ")");
      agree &= found == results.phat.end() || found->agree;
    }
    header.push_back ("pairs");
    row.push_back (agree ? "equal" : "DIFFER");
    printHeader (header);
    printRow (row);
  }

  const EngineMeasurement* incremental = results.engine ("incremental");
  const EngineMeasurement* fip = results.engine ("fip");
  if (incremental || fip) {
    std::printf ("\n### Incremental (Alg 5.11) vs fast incremental (Alg 5.12-5.14) "
                 "persistence, H1 given H0\n\n");
    printHeader ({"input",
                  "points",
                  "radius",
                  "edges",
                  "triangles",
                  "beta1",
                  "incremental s",
                  "fip s",
                  "speed-up",
                  "diagrams"});
    printRow (
        {results.name,
         std::to_string (results.points),
         formatDouble (options.radius),
         std::to_string (complex.numEdges()),
         std::to_string (complex.numTriangles()),
         std::to_string (results.beta1),
         incremental ? spread (incremental->h1) : "-",
         fip ? spread (fip->h1) : "-",
         incremental && fip ? times (incremental->h1.median, fip->h1.median) : "-",
         (!incremental || incremental->agree) && (!fip || fip->agree) ? "equal"
                                                                      : "DIFFER"});
  }
}

/** The last stdout line: one JSON object of sizes, medians, ratios, agreement and
 * memory; tools that did not run are null. */
void
printJSON (const Options& options, const OursMeasurement& ours, const Results& results)
{
  const auto& complex = ours.complex;
  std::ostringstream out;
  out << "{\"input\": " << jsonString (options.input)
      << ", \"leaf\": " << formatDouble (options.leaf)
      << ", \"points_read\": " << results.points_read
      << ", \"points\": " << results.points
      << ", \"radius\": " << formatDouble (options.radius)
      << ", \"runs\": " << options.runs << ", \"threads\": " << omp_get_max_threads()
      << ", \"vertices\": " << complex.numVertices()
      << ", \"edges\": " << complex.numEdges()
      << ", \"triangles\": " << complex.numTriangles()
      << ", \"beta1\": " << results.beta1;
  out << ", \"ours\": {\"total\": " << json (ours.total)
      << ", \"build\": " << json (ours.build) << ", \"h0\": " << json (ours.h0)
      << ", \"h1\": " << json (ours.h1)
      << ", \"process\": " << json (results.ours_process.seconds)
      << ", \"process_agree\": " << json (results.process_agrees) << "}";
  const auto process = [&] (const char* key,
                            const ProcessMeasurement& measurement,
                            double ours_median,
                            bool agrees,
                            const std::string& extra) {
    out << ", \"" << key << "\": ";
    if (!measurement.ran) {
      out << "null";
      return;
    }
    out << "{\"seconds\": " << json (measurement.seconds)
        << ", \"ratio\": " << measurement.seconds.median / ours_median
        << ", \"agree\": " << json (agrees)
        << ", \"peak_memory_bytes\": " << jsonBytes (measurement.peak_memory) << extra
        << "}";
  };
  process ("ripser",
           results.ripser,
           results.ours_process.seconds.median,
           results.ripser_agrees,
           "");
  process ("ripser_sparse",
           results.ripser_sparse,
           ours.total.median,
           results.sparse_agrees,
           ", \"missing_vertices\": " + std::to_string (results.sparse_missing));
  out << ", \"gudhi\": ";
  if (results.gudhi.ran)
    out << "{\"construction\": " << json (results.gudhi.construction)
        << ", \"persistence\": " << json (results.gudhi.persistence)
        << ", \"total\": " << json (results.gudhi.total)
        << ", \"ratio\": " << results.gudhi.total.median / ours.total.median
        << ", \"agree\": " << json (results.gudhi_agrees)
        << ", \"simplices\": " << results.gudhi.simplices << "}";
  else
    out << "null";
  out << ", \"gudhi_collapse\": ";
  if (results.collapse.ran)
    out << "{\"collapse\": " << json (results.collapse.collapse)
        << ", \"persistence_after\": " << json (results.collapse.persistence)
        << ", \"kept_edges\": " << results.collapse.kept_edges
        << ", \"agree\": " << json (results.collapse_agrees) << "}";
  else
    out << "null";
  out << ", \"phat\": ";
  if (results.phat.empty())
    out << "null";
  else {
    out << "{";
    for (std::size_t i = 0; i < results.phat.size(); ++i) {
      const PHATMeasurement& measurement = results.phat[i];
      out << (i ? ", " : "") << "\"" << measurement.name
          << "\": {\"matrix\": " << json (measurement.matrix)
          << ", \"reduction\": " << json (measurement.reduction)
          << ", \"ratio\": " << measurement.reduction.median / ours.h1.median
          << ", \"agree\": " << json (measurement.agree) << "}";
    }
    out << "}";
  }
  out << ", \"engines\": {\"default\": {\"h1\": " << json (ours.h1) << "}";
  for (const auto& engine : results.engines)
    out << ", \"" << engine.name << "\": {\"h1\": " << json (engine.h1)
        << ", \"ratio\": " << engine.h1.median / ours.h1.median
        << ", \"agree\": " << json (engine.agree) << "}";
  out << "}, \"memory\": {\"complex_bytes\": " << results.complex_bytes
      << ", \"peak_after_loading_bytes\": " << results.memory_loaded
      << ", \"peak_after_ours_bytes\": " << results.memory_ours
      << ", \"peak_at_end_bytes\": " << results.memory_end
      << ", \"ours_process_peak_bytes\": "
      << jsonBytes (results.ours_process.peak_memory)
      << "}, \"all_agree\": " << json (results.allAgree()) << "}";
  std::printf ("%s\n", out.str().c_str());
}

/** Agreement of two diagrams; prints the differences when they disagree. */
bool
agree (const std::string& what,
       const pcl::tda::PersistenceDiagram& first,
       const pcl::tda::PersistenceDiagram& second)
{
  const auto comparison = pcl::tda::compareDiagrams (first, second, 1e-5);
  if (!comparison.equal)
    std::printf (
        "Diagrams differ, %s:\n%s\n", what.c_str(), comparison.summary().c_str());
  return comparison.equal;
}

/** Removes the scratch files when the benchmark ends, also on error. */
struct ScratchFiles {
  std::string prefix = "/tmp/pcl_tda_bench_persistence_" + std::to_string (::getpid());
  std::string pcd = prefix + "_cloud.pcd", points = prefix + "_points.txt",
              edges = prefix + "_edges.txt", ours = prefix + "_ours.csv";
  ProcessFiles process{
      prefix + "_out.txt", prefix + "_err.txt", prefix + "_memory.txt"};

  ~ScratchFiles()
  {
    for (const std::string* file :
         {&pcd, &points, &edges, &ours, &process.out, &process.err, &process.memory})
      std::remove (file->c_str());
  }
};

int
benchmark (const Options& options, const std::string& self)
{
  Results results;
  bool jittered = false;
  const Cloud::Ptr cloud = loadPoints (options, results.points_read, jittered);
  results.points = cloud->size();
  results.name = options.input.substr (options.input.rfind ('/') + 1) +
                 (options.leaf > 0.0 ? ", leaf " + formatDouble (options.leaf) : "") +
                 (jittered ? ", jittered copies" : "");
  results.memory_loaded = peakMemory();
  const auto wants = [&] (const std::string& tool) {
    return options.tools.count (tool) > 0;
  };
  const int runs = options.runs;

  // Ours first, so that its peak memory is not that of a reference tool.
  OursMeasurement ours = measureOurs (cloud, options.radius, runs);
  results.memory_ours = peakMemory();
  listTriangles (cloud, options.radius, ours);
  const auto& complex = ours.complex;
  results.complex_bytes = complex.numEdges() * sizeof (pcl::tda::FilteredEdge) +
                          complex.numTriangles() * sizeof (pcl::tda::FilteredTriangle);
  results.beta1 =
      std::count_if (ours.diagram.begin(), ours.diagram.end(), [] (const auto& i) {
        return i.dimension == 1 && i.isEssential();
      });

  // Ours as a process, PCD file to CSV file, to compare with Ripser's process.
  const ScratchFiles files;
  if (pcl::io::savePCDFileBinary (files.pcd, *cloud) < 0)
    throw std::runtime_error ("cannot write " + files.pcd);
  const std::string radius = formatDouble (options.radius);
  results.ours_process =
      measureProcess ({self.substr (0, self.rfind ('/') + 1) + "pcl_tda_barcode",
                       files.pcd,
                       files.ours,
                       "-radius",
                       radius},
                      files.process,
                      runs);
  results.process_agrees = agree ("ours in process vs pcl_tda_barcode",
                                  ours.diagram,
                                  pcl::tda::loadDiagram (files.ours));

  if (wants ("ripser")) {
    writePointsText (files.points, *cloud);
    results.ripser = measureProcess ({"ripser",
                                      "--format",
                                      "point-cloud",
                                      "--dim",
                                      "1",
                                      "--threshold",
                                      radius,
                                      files.points},
                                     files.process,
                                     runs);
    results.ripser_agrees = agree ("ours vs Ripser point-cloud",
                                   ours.diagram,
                                   pcl::tda::loadDiagram (files.process.out));
  }
  if (wants ("ripser-sparse")) {
    results.sparse_missing =
        complex.numVertices() - writeEdgesText (files.edges, complex);
    results.ripser_sparse = measureProcess ({"ripser",
                                             "--format",
                                             "sparse",
                                             "--dim",
                                             "1",
                                             "--threshold",
                                             radius,
                                             files.edges},
                                            files.process,
                                            runs);
    // Ripser's vertex count is 1 + the largest id in the file: it drops the isolated
    // vertices after it, each an essential H0 class.
    pcl::tda::PersistenceDiagram diagram = pcl::tda::loadDiagram (files.process.out);
    diagram.insert (diagram.end(),
                    results.sparse_missing,
                    {0, 0.0, std::numeric_limits<double>::infinity()});
    results.sparse_agrees = agree ("ours vs Ripser sparse", ours.diagram, diagram);
  }
  if (wants ("gudhi")) {
    results.gudhi = measureGUDHI (*cloud, options.radius, runs);
    results.gudhi_agrees = agree ("ours vs GUDHI", ours.diagram, results.gudhi.diagram);
    if (results.gudhi.simplices != complex.numSimplices())
      std::printf ("GUDHI's complex has %zu simplices, ours %zu.\n",
                   results.gudhi.simplices,
                   complex.numSimplices());
  }
  if (wants ("gudhi-collapse")) {
    results.collapse = measureEdgeCollapse (complex, runs);
    results.collapse_agrees = agree ("ours vs ours after GUDHI's edge collapse",
                                     ours.diagram,
                                     results.collapse.diagram);
  }
  if (std::any_of (PHAT_REDUCTIONS.begin(),
                   PHAT_REDUCTIONS.end(),
                   [&] (const std::string& name) { return wants ("phat-" + name); })) {
    const auto pairs = pcl::tda::test::globalPairs (complex, ours.result);
    if (wants ("phat-standard"))
      results.phat.push_back (
          measurePHAT<phat::standard_reduction> ("standard", ours, pairs, runs));
    if (wants ("phat-twist"))
      results.phat.push_back (
          measurePHAT<phat::twist_reduction> ("twist", ours, pairs, runs));
    if (wants ("phat-chunk"))
      results.phat.push_back (
          measurePHAT<phat::chunk_reduction> ("chunk", ours, pairs, runs));
    if (wants ("phat-row"))
      results.phat.push_back (
          measurePHAT<phat::row_reduction> ("row", ours, pairs, runs));
    // One thread: with more, this PHAT version reads unsynchronised pivot columns.
    if (wants ("phat-spectral_sequence"))
      results.phat.push_back (measurePHAT<phat::spectral_sequence_reduction> (
          "spectral_sequence", ours, pairs, runs, 1));
  }
  for (const auto& entry : pcl::tda::persistenceEngines())
    if (wants (entry.name))
      results.engines.push_back (measureEngine (ours, entry.engine, runs));
  results.memory_end = peakMemory();

  printReport (options, ours, results);
  printJSON (options, ours, results);
  return results.allAgree() ? 0 : 2;
}

} // namespace

int
main (int argc, char** argv)
{
  Options options;
  if (const auto stop = pcl::tda::bench::parseCommandLine (
          argc, argv, options, parseOptions, printUsage))
    return *stop;
  try {
    std::size_t loaded = 0;
    bool jittered = false;
    if (options.find_degree > 0.0)
      return findRadius (options, loadPoints (options, loaded, jittered));
    return benchmark (options, argv[0]);
  }
  catch (const std::exception& error) {
    std::fprintf (stderr, "Error: %s\n", pcl::tda::errorMessage (error).c_str());
    return 1;
  }
}
