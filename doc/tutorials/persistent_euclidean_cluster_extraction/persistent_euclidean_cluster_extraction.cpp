// Tutorial: Euclidean cluster extraction by persistence, beside
// pcl::EuclideanClusterExtraction
// (doc/tutorials/persistent_euclidean_cluster_extraction.md).

#include <pcl/common/io.h>
#include <pcl/console/time.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/filters/passthrough.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/io/pcd_io.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/segmentation/sac_segmentation.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/tda/segmentation/persistent_euclidean_cluster_extraction.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <vector>

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/** \brief Prints the number of clusters and the size of each. */
void
printClusters (const char* name,
               const std::vector<pcl::PointIndices>& clusters,
               double milliseconds)
{
  std::cout << name << ": " << clusters.size() << " clusters in " << milliseconds
            << " ms, sizes";
  for (const pcl::PointIndices& cluster : clusters)
    std::cout << " " << cluster.indices.size();
  std::cout << "\n";
}

int
main (int argc, char** argv)
{
  if (argc < 2) {
    std::cerr << "Syntax is: " << argv[0] << " table_scene.pcd\n";
    return EXIT_FAILURE;
  }
  Cloud::Ptr cloud (new Cloud);
  if (pcl::io::loadPCDFile (argv[1], *cloud) < 0)
    return EXIT_FAILURE;
  std::cout << "Loaded " << cloud->size() << " points from " << argv[1] << "\n";

  // Keep the points nearer than 1.5 m (this also drops the NaNs of the organized
  // scan) and thin them with a 5 mm voxel grid.
  Cloud::Ptr near (new Cloud), filtered (new Cloud);
  pcl::PassThrough<pcl::PointXYZ> pass;
  pass.setInputCloud (cloud);
  pass.setFilterFieldName ("z");
  pass.setFilterLimits (0.0, 1.5);
  pass.filter (*near);
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud (near);
  grid.setLeafSize (0.005f, 0.005f, 0.005f);
  grid.filter (*filtered);

  // Remove the table: the dominant plane, found by RANSAC.
  pcl::SACSegmentation<pcl::PointXYZ> seg;
  seg.setOptimizeCoefficients (true);
  seg.setModelType (pcl::SACMODEL_PLANE);
  seg.setMethodType (pcl::SAC_RANSAC);
  seg.setMaxIterations (100);
  seg.setDistanceThreshold (0.01);
  seg.setInputCloud (filtered);
  pcl::PointIndices::Ptr plane (new pcl::PointIndices);
  pcl::ModelCoefficients coefficients;
  seg.segment (*plane, coefficients);
  Cloud::Ptr objects (new Cloud);
  pcl::ExtractIndices<pcl::PointXYZ> extract;
  extract.setInputCloud (filtered);
  extract.setIndices (plane);
  extract.setNegative (true);
  extract.filter (*objects);
  std::cout << filtered->size() << " points after the voxel grid, "
            << plane->indices.size() << " on the plane, " << objects->size()
            << " left\n";

  // PCL's Euclidean clustering, as in PCL's cluster_extraction tutorial.
  pcl::console::TicToc timer;
  timer.tic();
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree (new pcl::search::KdTree<pcl::PointXYZ>);
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> ec;
  ec.setClusterTolerance (0.02);
  ec.setMinClusterSize (20);
  ec.setSearchMethod (tree);
  ec.setInputCloud (objects);
  std::vector<pcl::PointIndices> pcl_clusters;
  ec.extract (pcl_clusters);
  printClusters ("pcl::EuclideanClusterExtraction, 0.02 m", pcl_clusters, timer.toc());

  // The same clusters by persistence: the H0 barcode of the radius graph up to
  // 0.02 m, whose essential bars are the clusters.
  timer.tic();
  pcl::tda::PersistentEuclideanClusterExtraction<pcl::PointXYZ> pec;
  pec.setClusterTolerance (0.02);
  pec.setMinClusterSize (20);
  pec.setInputCloud (objects);
  std::vector<pcl::PointIndices> clusters;
  pec.extract (clusters);
  printClusters (
      "pcl::tda::PersistentEuclideanClusterExtraction, 0.02 m", clusters, timer.toc());

  // Let the barcode choose the distance: the longest stable split up to 0.1 m.
  timer.tic();
  pec.setMaxDistance (0.1);
  pec.setAutoMaxDistance (true);
  pec.extract (clusters);
  const double chosen = pec.getChosenDistance();
  printClusters ("pcl::tda::PersistentEuclideanClusterExtraction, automatic",
                 clusters,
                 timer.toc());
  std::cout << "  chosen distance " << chosen << " m ("
            << (pec.getAutoDistanceIsClear() ? "a clear gap" : "no clear gap") << "), "
            << pec.getPersistenceDiagram().size() << " H0 bars\n";

  // Save the objects labelled by cluster (0: none) and the barcode with its cut.
  pcl::PointCloud<pcl::PointXYZL> labelled;
  pcl::copyPointCloud (*objects, labelled);
  for (std::size_t i = 0; i < clusters.size(); ++i)
    for (const pcl::index_t index : clusters[i].indices)
      labelled[index].label = static_cast<std::uint32_t> (i + 1);
  try {
    pcl::io::savePCDFileBinary ("clusters.pcd", labelled);
    pcl::tda::PlotOptions plot;
    plot.title = "H0 barcode of the objects";
    plot.max_value = pec.getMaxDistance();
    plot.unit = "m";
    plot.cut = chosen;
    pcl::tda::saveBarcodeSVG ("barcode.svg", pec.getPersistenceDiagram(), plot);
  }
  catch (const pcl::PCLException& error) {
    std::cerr << error.detailedMessage() << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "Written: clusters.pcd, barcode.svg\n";
  return EXIT_SUCCESS;
}
