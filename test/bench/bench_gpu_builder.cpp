// pcl_tda_bench_gpu_builder: pcl::tda::gpu::VietorisRipsBuilder (here on its OpenMP
// backend, or on CUDA when built with it and a device is present) against the CPU
// builder pcl::tda::VietorisRipsBuilder and against the bare neighbour search
// (pcl::search::KdTree::radiusSearch around every point, in parallel), on the same
// points and radius in the same run: 15k, 100k and 1M points of a real scan (random
// subsamples; past the scan's size, the scan plus jittered copies of its points,
// labelled so), medians of several runs, the ratios, whether the two complexes are
// identical, and the pass counts behind the CUDA estimate of doc/gpu_builder.md.
//
// Usage: pcl_tda_bench_gpu_builder [scan.pcd] [-runs N] [-degree D] [-seed S]
// The radius gives about D neighbours per point (default 12). The report goes to
// stdout as a markdown table; the last line is one JSON object. Exit status: 0 when
// every complex is identical, 2 when one differs, 1 on error.

#include <pcl/common/common.h>
#include <pcl/common/point_tests.h>
#include <pcl/io/pcd_io.h>
#include <pcl/search/kdtree.h>
#include <pcl/tda/gpu/vietoris_rips_builder.h>
#include <pcl/tda/search/canonical_order.h>
#include <pcl/tda/search/point_spacing.h>
#include <pcl/tda/search/uniform_grid.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#include "bench_command_line.h"
#include "bench_statistics.h"
#include "complex_difference.h"
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using pcl::tda::bench::median;
using pcl::tda::bench::seconds;

struct Options {
  std::string input =
      std::string (PCL_TDA_DATA_DIR) + "/table_scene_mug_stereo_textured.pcd";
  int runs = 5;
  double degree = 12.0;
  unsigned int seed = 1;
};

/** \a size points of \a scan (finite points only): a random subsample, or past the
 * scan's size the scan and random points of it moved by up to 1e-4 of its bounding
 * box diagonal along each axis. \a label says which. */
Cloud::Ptr
sample (const Cloud& scan, std::size_t size, unsigned int seed, std::string& label)
{
  std::mt19937 random (seed);
  Cloud::Ptr cloud (new Cloud);
  if (size <= scan.size()) {
    std::vector<std::size_t> order (scan.size());
    std::iota (order.begin(), order.end(), 0);
    std::shuffle (order.begin(), order.end(), random);
    for (std::size_t i = 0; i < size; ++i)
      cloud->push_back (scan[order[i]]);
    label = "subsample";
    return cloud;
  }
  pcl::PointXYZ low, high;
  pcl::getMinMax3D (scan, low, high);
  const float jitter = 1e-4f * (high.getVector3fMap() - low.getVector3fMap()).norm();
  std::uniform_int_distribution<std::size_t> pick (0, scan.size() - 1);
  std::uniform_real_distribution<float> move (-jitter, jitter);
  *cloud = scan;
  while (cloud->size() < size) {
    pcl::PointXYZ p = scan[pick (random)];
    p.x += move (random);
    p.y += move (random);
    p.z += move (random);
    cloud->push_back (p);
  }
  std::ostringstream text;
  text << "scan + jittered copies (x" << static_cast<double> (size) / scan.size()
       << ")";
  label = text.str();
  return cloud;
}

/** The bare neighbour search: a k-d tree over the points and a radius search around
 * every one of them, in parallel. \return the neighbours found */
std::size_t
neighbourSearch (const Cloud::Ptr& cloud, double radius)
{
  pcl::search::KdTree<pcl::PointXYZ> tree (false); // unsorted results, as needed
  tree.setInputCloud (cloud);
  std::size_t found = 0;
  const auto n = static_cast<std::int64_t> (cloud->size());
#pragma omp parallel reduction(+ : found)
  {
    pcl::Indices indices;
    std::vector<float> distances;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t i = 0; i < n; ++i)
      found +=
          tree.radiusSearch (static_cast<pcl::index_t> (i), radius, indices, distances);
  }
  return found;
}

/** The sum over the vertices of their squared degree: the merge steps of the gpu
 * builder's two triangle passes, each edge merging the lists of its two ends. */
double
mergeSteps (const pcl::tda::FilteredComplex& complex)
{
  std::vector<double> degree (complex.numVertices(), 0.0);
  for (const auto& edge : complex.edges()) {
    degree[edge.source] += 1.0;
    degree[edge.target] += 1.0;
  }
  double steps = 0.0;
  for (const double d : degree)
    steps += d * d;
  return steps;
}

/** Medians of the phase timings of a builder. */
struct PhaseMedians {
  std::vector<double> total, neighbours, edges, triangles;

  void
  add (double seconds, const pcl::tda::VietorisRipsTimings& timings)
  {
    total.push_back (seconds);
    neighbours.push_back (timings.neighbor_search);
    edges.push_back (timings.edges);
    triangles.push_back (timings.triangles);
  }
};

void
printUsage (std::FILE* stream)
{
  std::fprintf (
      stream,
      "Usage: pcl_tda_bench_gpu_builder [scan.pcd] [-runs N] [-degree D] "
      "[-seed S]\n"
      "  scan.pcd  the scan (default %s/table_scene_mug_stereo_textured.pcd)\n"
      "  -runs N   runs per measurement, medians reported (default 5)\n"
      "  -degree D neighbours per point the radius gives (default 12)\n"
      "  -seed S   seed of the subsamples and the jitter (default 1)\n",
      PCL_TDA_DATA_DIR);
}

void
parseOptions (int argc, char** argv, Options& options)
{
  long runs = options.runs, seed = options.seed;
  pcl::tda::ToolCommandLine command_line;
  command_line.addInteger ("-runs", runs, 1, 1000);
  command_line.addNumber (
      "-degree", options.degree, pcl::tda::NumberRange::above (0.0));
  command_line.addInteger ("-seed", seed, 0, 0xffffffffL);
  pcl::tda::bench::takeOptionalArgument (
      command_line.parse (argc, argv), "scan", options.input);
  options.runs = static_cast<int> (runs);
  options.seed = static_cast<unsigned int> (seed);
}

} // namespace

int
main (int argc, char** argv)
{
  Options options;
  if (const auto stop = pcl::tda::bench::parseCommandLine (
          argc, argv, options, parseOptions, printUsage))
    return *stop;
  Cloud loaded, scan;
  if (pcl::io::loadPCDFile (options.input, loaded) != 0) {
    std::fprintf (stderr,
                  "Cannot read %s (the real scans live in ../shared/data)\n",
                  options.input.c_str());
    return 1;
  }
  for (const auto& point : loaded)
    if (pcl::isXYZFinite (point))
      scan.push_back (point);
  std::string why;
  const pcl::tda::gpu::DeviceBackend backend = pcl::tda::gpu::selectBackend (why);
  const std::string ours =
      "gpu::VietorisRipsBuilder (" + pcl::tda::gpu::backendName (backend) + ")";

  std::printf ("## gpu::VietorisRipsBuilder vs the CPU builder vs the bare neighbour "
               "search\n\n");
  std::printf ("Scan %s (%zu finite points), %d OpenMP threads, radius for about %.0f "
               "neighbours per point; seconds, medians of %d runs.\n\n",
               options.input.c_str(),
               scan.size(),
               omp_get_max_threads(),
               options.degree,
               options.runs);
  std::printf (
      "| points | cloud | radius | edges | triangles | CPU builder | %s | ratio "
      "| bare search | ours / search | identical |\n",
      ours.c_str());
  std::printf ("|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::ostringstream json, phases, passes;
  json << "{\"backend\": \"" << pcl::tda::gpu::backendName (backend)
       << "\", \"sizes\": [";
  bool all_identical = true;
  const std::size_t sizes[] = {15000, 100000, 1000000};
  for (const std::size_t size : sizes) {
    std::string label;
    const Cloud::Ptr cloud = sample (scan, size, options.seed, label);
    // A disk of radius r on a surface holds pi r^2 / a points, a the area per point.
    const double radius =
        std::sqrt (options.degree / M_PI) * pcl::tda::surfaceSpacing (*cloud);

    pcl::tda::VietorisRipsBuilder<pcl::PointXYZ> cpu;
    pcl::tda::gpu::VietorisRipsBuilder<pcl::PointXYZ> device;
    cpu.setInputCloud (cloud);
    device.setInputCloud (cloud);
    cpu.setRadius (radius);
    device.setRadius (radius);
    PhaseMedians cpu_times, device_times;
    std::vector<double> search_times;
    bool identical = true;
    pcl::tda::FilteredComplex expected, actual;
    for (int run = 0; run < options.runs; ++run) {
      bool built = true;
      cpu_times.add (seconds ([&] { built = cpu.compute (expected) && built; }),
                     cpu.getTimings());
      device_times.add (seconds ([&] { built = device.compute (actual) && built; }),
                        device.getTimings());
      search_times.push_back (seconds ([&] { neighbourSearch (cloud, radius); }));
      identical = identical && built &&
                  pcl::tda::test::complexDifference (expected, actual).empty();
    }
    all_identical = all_identical && identical;
    const double cpu_s = median (cpu_times.total), ours_s = median (device_times.total),
                 search_s = median (search_times);
    std::printf ("| %zu | %s | %.5f | %zu | %zu | %.3f | %.3f | %.2f | %.3f | %.2f | "
                 "%s |\n",
                 cloud->size(),
                 label.c_str(),
                 radius,
                 expected.numEdges(),
                 expected.numTriangles(),
                 cpu_s,
                 ours_s,
                 ours_s / cpu_s,
                 search_s,
                 ours_s / search_s,
                 identical ? "yes" : "NO");
    std::fflush (stdout);
    phases << "| " << cloud->size() << " | " << median (cpu_times.neighbours) << " / "
           << median (device_times.neighbours) << " | " << median (cpu_times.edges)
           << " / " << median (device_times.edges) << " | "
           << median (cpu_times.triangles) << " / " << median (device_times.triangles)
           << " |\n";
    std::vector<pcl::tda::Point3d> points (cloud->size());
    for (std::size_t i = 0; i < cloud->size(); ++i)
      points[i] = {(*cloud)[i].x, (*cloud)[i].y, (*cloud)[i].z};
    const pcl::tda::UniformGrid grid (points, radius);
    pcl::Indices all (cloud->size());
    std::iota (all.begin(), all.end(), 0);
    std::vector<double> order_times;
    for (int run = 0; run < options.runs; ++run)
      order_times.push_back (seconds ([&] {
        std::size_t skipped;
        pcl::tda::canonicalOrder (*cloud, all, skipped);
      }));
    passes << "| " << cloud->size() << " | " << grid.numCandidatePairs() << " | "
           << expected.numEdges() << " | " << mergeSteps (expected) << " | "
           << expected.numTriangles() << " | " << median (order_times) << " |\n";
    json << (size == sizes[0] ? "" : ", ") << "{\"points\": " << cloud->size()
         << ", \"radius\": " << radius << ", \"edges\": " << expected.numEdges()
         << ", \"triangles\": " << expected.numTriangles() << ", \"cpu\": " << cpu_s
         << ", \"ours\": " << ours_s << ", \"search\": " << search_s
         << ", \"identical\": " << (identical ? "true" : "false") << "}";
  }
  std::printf (
      "\nPhases, CPU builder / ours (seconds, medians): neighbour search "
      "(canonical order, grid, edge count and fill), edges (sort), "
      "triangles (adjacency, count, fill).\n\n"
      "| points | neighbour search | edges | triangles |\n|---|---|---|---|\n%s",
      phases.str().c_str());
  std::printf (
      "\nPass counts of the gpu builder: distance tests of each edge pass "
      "(candidate pairs), edges, merge steps of each triangle pass (sum of "
      "squared degrees), triangles; and the seconds of its host step, the "
      "canonical order (sequential).\n\n"
      "| points | distance tests | edges | merge steps | triangles | canonical "
      "order |\n|---|---|---|---|---|---|\n%s",
      passes.str().c_str());
  json << "]}";
  std::printf ("\n%s\n", json.str().c_str());
  return all_identical ? 0 : 2;
}
