// pcl_tda_bench_holes_cut: hole recall of pcl::tda::HoleBoundaryEstimation, at its
// defaults, on real scans into which round holes were cut: data made differently
// from the hole generator the class was tuned on. For each scan and seed, holes of
// radius R (in units of the scan's surface spacing h) are cut around random points
// well inside the surface (their 2R-neighbourhood holds at least 90 % of the
// median number of points) and at least 4R apart: every point within R of a centre
// is removed. A cut hole is found when a rim's centroid lies within R / 2 of its
// centre. The scans' own holes and borders give further rims, which are counted
// but not scored.
//
// Usage: pcl_tda_bench_holes_cut [data_dir] [-seeds N] [-holes K]
// The report goes to stdout as a markdown table.

#include <pcl/filters/filter.h>
#include <pcl/io/pcd_io.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/tda/apps/tool_options.h>
#include <pcl/tda/features/hole_boundary_estimation.h>
#include <pcl/tda/search/point_spacing.h>
#include <pcl/point_types.h>

#include "bench_command_line.h"
#include "bench_statistics.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Ours = pcl::tda::HoleBoundaryEstimation<pcl::PointXYZ, pcl::Boundary>;

/** The radii of the cut holes, in units of the surface spacing. */
constexpr double HOLE_RADII[] = {4.0, 8.0};

struct Options {
  std::string data = PCL_TDA_DATA_DIR;
  int seeds = 3;
  int holes = 3;
};

/** A cloud with round holes cut into it. */
struct CutScan {
  Cloud::Ptr cloud;
  std::vector<Eigen::Vector3f> centres;
};

/** Up to \a count holes of radius \a hole_radius cut into \a scan around points well
 * inside it, at least 4 radii apart, chosen in the order of a shuffle by \a seed. */
CutScan
cutHoles (const Cloud::Ptr& scan, double hole_radius, int count, unsigned seed)
{
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud (scan);
  const auto neighbours = [&] (const pcl::PointXYZ& p, double r) {
    pcl::Indices found;
    std::vector<float> distances;
    return tree.radiusSearch (p, r, found, distances);
  };
  std::vector<int> sample_counts;
  for (std::size_t i = 0; i < scan->size();
       i += std::max<std::size_t> (1, scan->size() / 500))
    sample_counts.push_back (neighbours ((*scan)[i], 2.0 * hole_radius));
  std::nth_element (sample_counts.begin(),
                    sample_counts.begin() + sample_counts.size() / 2,
                    sample_counts.end());
  const double inside_count = 0.9 * sample_counts[sample_counts.size() / 2];

  std::vector<std::size_t> order (scan->size());
  std::iota (order.begin(), order.end(), 0);
  std::mt19937 random (seed);
  std::shuffle (order.begin(), order.end(), random);
  CutScan cut;
  for (const std::size_t i : order) {
    if (static_cast<int> (cut.centres.size()) == count)
      break;
    const Eigen::Vector3f p = (*scan)[i].getVector3fMap();
    const bool apart = std::all_of (
        cut.centres.begin(), cut.centres.end(), [&] (const Eigen::Vector3f& c) {
          return (c - p).norm() >= 4.0 * hole_radius;
        });
    if (apart && neighbours ((*scan)[i], 2.0 * hole_radius) >= inside_count)
      cut.centres.push_back (p);
  }
  cut.cloud.reset (new Cloud);
  for (const pcl::PointXYZ& q : *scan) {
    const bool removed = std::any_of (
        cut.centres.begin(), cut.centres.end(), [&] (const Eigen::Vector3f& c) {
          return (q.getVector3fMap() - c).norm() <= hole_radius;
        });
    if (!removed)
      cut.cloud->push_back (q);
  }
  return cut;
}

struct Found {
  std::size_t matched = 0;
  std::size_t rims = 0;
};

/** How many cut holes a rim's centroid lies within half a radius of. */
Found
findCutHoles (const CutScan& cut, double hole_radius)
{
  Ours ours;
  ours.setInputCloud (cut.cloud);
  pcl::PointCloud<pcl::Boundary> flags;
  ours.compute (flags);
  Found found;
  found.rims = ours.getHoles().size();
  for (const Eigen::Vector3f& centre : cut.centres)
    found.matched +=
        std::any_of (ours.getHoles().begin(),
                     ours.getHoles().end(),
                     [&] (const pcl::tda::HoleRim& rim) {
                       return (rim.centroid - centre).norm() <= 0.5 * hole_radius;
                     });
  return found;
}

void
printUsage (std::FILE* stream)
{
  std::fprintf (stream,
                "Usage: pcl_tda_bench_holes_cut [data_dir] [-seeds N] [-holes K]\n"
                "  data_dir  folder of the real scans (default %s)\n"
                "  -seeds N  cut scans per scan and hole radius (default 3)\n"
                "  -holes K  holes cut into each (default 3)\n",
                PCL_TDA_DATA_DIR);
}

void
parseOptions (int argc, char** argv, Options& options)
{
  long seeds = options.seeds, holes = options.holes;
  pcl::tda::ToolCommandLine command_line;
  command_line.addInteger ("-seeds", seeds, 1, 1000);
  command_line.addInteger ("-holes", holes, 1, 100);
  const std::vector<std::string> folders = command_line.parse (argc, argv);
  if (folders.size() > 1)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException, "Give at most one data folder.");
  if (!folders.empty())
    options.data = folders[0];
  options.seeds = static_cast<int> (seeds);
  options.holes = static_cast<int> (holes);
}

} // namespace

int
main (int argc, char** argv)
{
  Options options;
  if (const auto stop = pcl::tda::bench::parseCommandLine (
          argc, argv, options, parseOptions, printUsage))
    return *stop;
  std::printf ("| cloud | points | h | hole radius | holes cut | found | recall | rims "
               "reported | time (s) |\n|---|---|---|---|---|---|---|---|---|\n");
  std::size_t all_cut = 0, all_found = 0;
  for (const std::string name :
       {"milk.pcd", "rops_cloud.pcd", "car6.pcd", "kinect_frame.pcd"}) {
    Cloud::Ptr raw (new Cloud), scan (new Cloud);
    if (pcl::io::loadPCDFile (options.data + "/" + name, *raw) < 0) {
      std::printf ("| %s | (not found in %s) |\n", name.c_str(), options.data.c_str());
      continue;
    }
    pcl::Indices unused;
    pcl::removeNaNFromPointCloud (*raw, *scan, unused);
    const double h = pcl::tda::surfaceSpacing (*scan);
    for (const double radius_in_h : HOLE_RADII) {
      const double hole_radius = radius_in_h * h;
      std::size_t cut_count = 0, found_count = 0, rims = 0;
      std::vector<double> times;
      for (int seed = 1; seed <= options.seeds; ++seed) {
        std::fprintf (
            stderr, "%s, holes of %g h, seed %d\n", name.c_str(), radius_in_h, seed);
        const CutScan cut = cutHoles (scan, hole_radius, options.holes, seed);
        Found found;
        times.push_back (pcl::tda::bench::seconds (
            [&] { found = findCutHoles (cut, hole_radius); }));
        cut_count += cut.centres.size();
        found_count += found.matched;
        rims += found.rims;
      }
      all_cut += cut_count;
      all_found += found_count;
      std::printf ("| %s | %zu | %.3g | %g h | %zu | %zu | %.3f | %zu | %.3f |\n",
                   name.c_str(),
                   scan->size(),
                   h,
                   radius_in_h,
                   cut_count,
                   found_count,
                   cut_count ? static_cast<double> (found_count) / cut_count : 0.0,
                   rims,
                   pcl::tda::bench::median (times));
    }
  }
  std::printf ("\nAll scans: %zu of %zu cut holes found (recall %.3f).\n",
               all_found,
               all_cut,
               all_cut ? static_cast<double> (all_found) / all_cut : 0.0);
  return 0;
}
