// Tutorial: colour regions by persistence, beside pcl::RegionGrowingRGB
// (doc/tutorials/persistent_region_growing_rgb.md).

#include <pcl/common/io.h>
#include <pcl/console/time.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/tda/segmentation/persistent_region_growing_rgb.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <vector>

using Cloud = pcl::PointCloud<pcl::PointXYZRGB>;

/** \brief Number of regions the program describes one by one. */
constexpr std::size_t NUM_REGIONS_SHOWN = 8;

/** \brief The number of bars of \a barcode alive at \a threshold: the number of
 * regions that region colour threshold gives. */
std::size_t
regionsAt (const pcl::tda::PersistenceDiagram& barcode, double threshold)
{
  return std::count_if (barcode.begin(),
                        barcode.end(),
                        [threshold] (const pcl::tda::PersistenceInterval& bar) {
                          return bar.birth <= threshold && threshold < bar.death;
                        });
}

int
main (int argc, char** argv)
{
  if (argc < 2) {
    std::cerr << "Syntax is: " << argv[0] << " coloured_cloud.pcd\n";
    return EXIT_FAILURE;
  }
  Cloud::Ptr cloud (new Cloud);
  if (pcl::io::loadPCDFile (argv[1], *cloud) < 0)
    return EXIT_FAILURE;
  std::cout << "Loaded " << cloud->size() << " points from " << argv[1] << "\n";

  pcl::console::TicToc timer;
  timer.tic();
  pcl::tda::PersistentRegionGrowingRGB<pcl::PointXYZRGB> rg;
  rg.setInputCloud (cloud);
  rg.setMaxDistance (0.004);         // neighbours: points at most 4 mm apart
  rg.setMinNeighbors (5);            // points with fewer also join their 15 nearest
  rg.setEstimateNormals (true);      // PCA normals from the same neighbours
  rg.setNormalAngleThreshold (30.0); // degrees between the normals of neighbours
  rg.setColorThreshold (3.0);        // Delta E76 between neighbours: the patches
  rg.setRegionColorThreshold (10.0); // Delta E76 between the patches' mean colours
  rg.setMinClusterSize (20);         // smaller patches join their most similar one
  std::vector<pcl::PointIndices> regions;
  rg.extract (regions);
  if (regions.empty())
    return EXIT_FAILURE; // extract() printed why
  std::cout << regions.size() << " regions in " << timer.toc() << " ms, "
            << rg.getNumEdges() << " edges in the neighbour graph\n";

  // Each region with its mean colour and the range of region colour thresholds
  // over which it stays as it is.
  const std::vector<pcl::tda::RegionLifetime>& lifetimes = rg.getRegionLifetimes();
  for (std::size_t k = 0; k < std::min (regions.size(), NUM_REGIONS_SHOWN); ++k) {
    double r = 0, g = 0, b = 0;
    for (const pcl::index_t index : regions[k].indices) {
      r += (*cloud)[index].r;
      g += (*cloud)[index].g;
      b += (*cloud)[index].b;
    }
    const double n = static_cast<double> (regions[k].indices.size());
    std::printf ("  region %zu: %zu points, mean colour (%.0f, %.0f, %.0f), "
                 "Delta E %.2f to %.2f\n",
                 k + 1,
                 regions[k].indices.size(),
                 r / n,
                 g / n,
                 b / n,
                 lifetimes[k].birth,
                 lifetimes[k].death);
  }

  // The region barcode: the number of bars alive at a threshold is the number of
  // regions that threshold gives.
  const pcl::tda::PersistenceDiagram& barcode = rg.getRegionBarcode();
  std::cout << "Regions by region colour threshold (Delta E):";
  const char* separator = " ";
  for (const double threshold : {5.0, 10.0, 15.0, 20.0, 30.0}) {
    std::cout << separator << threshold << " -> " << regionsAt (barcode, threshold);
    separator = ", ";
  }
  std::cout << "\n";

  // Save every point with its own colour and its region (0: none), and the barcode.
  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  pcl::copyPointCloud (*cloud, labelled);
  for (pcl::PointXYZRGBL& point : labelled)
    point.label = 0;
  for (std::size_t k = 0; k < regions.size(); ++k)
    for (const pcl::index_t index : regions[k].indices)
      labelled[index].label = static_cast<std::uint32_t> (k + 1);
  try {
    pcl::io::savePCDFileBinary ("regions.pcd", labelled);
    pcl::tda::PlotOptions plot;
    plot.title = "Region barcode (Delta E76)";
    plot.max_value = 40.0;
    plot.cut = rg.getChosenRegionColorThreshold();
    pcl::tda::saveBarcodeSVG ("barcode.svg", barcode, plot);
  }
  catch (const pcl::PCLException& error) {
    std::cerr << error.detailedMessage() << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "Written: regions.pcd, barcode.svg\n";
  return EXIT_SUCCESS;
}
