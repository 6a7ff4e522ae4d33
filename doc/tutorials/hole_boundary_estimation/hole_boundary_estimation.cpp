// Tutorial: the holes of a scan from its minimal 1-cycles, beside
// pcl::BoundaryEstimation, and their filling
// (doc/tutorials/hole_boundary_estimation.md).

#include <pcl/common/io.h>
#include <pcl/console/time.h>
#include <pcl/features/boundary.h>
#include <pcl/features/normal_3d.h>
#include <pcl/io/pcd_io.h>
#include <pcl/search/kdtree.h>
#include <pcl/tda/features/hole_boundary_estimation.h>
#include <pcl/tda/surface/hole_filling.h>
#include <pcl/point_types.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <vector>

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

int
main (int argc, char** argv)
{
  if (argc < 2) {
    std::cerr << "Syntax is: " << argv[0] << " input.pcd\n";
    return EXIT_FAILURE;
  }
  Cloud::Ptr cloud (new Cloud);
  if (pcl::io::loadPCDFile (argv[1], *cloud) < 0)
    return EXIT_FAILURE;
  std::cout << "Loaded " << cloud->size() << " points from " << argv[1] << "\n";

  // The holes: the 1-cycles of the Vietoris-Rips complex that no triangle fills,
  // made minimal, and kept when the surface around them spans them.
  pcl::console::TicToc timer;
  timer.tic();
  pcl::tda::HoleBoundaryEstimation<pcl::PointXYZ, pcl::Boundary> hb;
  hb.setInputCloud (cloud);
  hb.setRadius (0.0); // 0: chosen from the spacing of the points
  pcl::PointCloud<pcl::Boundary> flags;
  hb.compute (flags);
  if (flags.empty())
    return EXIT_FAILURE; // compute() printed why
  const std::vector<pcl::tda::HoleRim>& holes = hb.getHoles();
  std::size_t flagged = 0;
  for (const pcl::Boundary& flag : flags)
    flagged += flag.boundary_point;
  const auto& searched = hb.getSearchCounts();
  std::cout << "pcl::tda::HoleBoundaryEstimation: " << holes.size() << " holes, "
            << flagged << " points in their rim bands (" << timer.toc()
            << " ms); radius " << hb.getUsedRadius() << " m, " << searched.edges
            << " edges, " << searched.open_classes << " 1-cycles open at the radius, "
            << searched.persistent_classes << " of them still open at "
            << hb.getUsedPersistenceRadius() << " m\n";
  for (std::size_t k = 0; k < holes.size(); ++k)
    std::printf ("  hole %zu: rim of %zu points, %.1f cm long, area %.2f cm^2, "
                 "closed at %.2f mm\n",
                 k + 1,
                 holes[k].rim.size(),
                 holes[k].perimeter * 1e2,
                 holes[k].area * 1e4,
                 holes[k].birth * 1e3);

  // PCL's boundary points, with normals and the angle criterion at one and two
  // times the same radius.
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree (new pcl::search::KdTree<pcl::PointXYZ>);
  for (const double factor : {1.0, 2.0}) {
    const double radius = factor * hb.getUsedRadius();
    timer.tic();
    pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
    pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> ne;
    ne.setInputCloud (cloud);
    ne.setSearchMethod (tree);
    ne.setRadiusSearch (radius);
    ne.compute (*normals);
    pcl::BoundaryEstimation<pcl::PointXYZ, pcl::Normal, pcl::Boundary> be;
    be.setInputCloud (cloud);
    be.setInputNormals (normals);
    be.setSearchMethod (tree);
    be.setRadiusSearch (radius);
    pcl::PointCloud<pcl::Boundary> pcl_flags;
    be.compute (pcl_flags);
    std::size_t pcl_flagged = 0, in_bands = 0;
    for (std::size_t i = 0; i < pcl_flags.size(); ++i)
      if (pcl_flags[i].boundary_point) {
        ++pcl_flagged;
        in_bands += flags[i].boundary_point;
      }
    std::cout << "pcl::BoundaryEstimation, radius " << radius << " m: " << pcl_flagged
              << " boundary points (" << timer.toc() << " ms), " << in_bands
              << " of them in the rim bands\n";
  }

  // Fill the holes: new points on a surface fitted around each rim.
  pcl::tda::HoleFilling<pcl::PointXYZ> filler;
  filler.setInputCloud (cloud);
  filler.setHoles (holes);
  Cloud filled;
  if (!filler.reconstruct (filled))
    return EXIT_FAILURE; // reconstruct() printed why
  std::cout << "pcl::tda::HoleFilling: " << filled.size() - cloud->size()
            << " new points, per hole";
  for (const std::size_t count : filler.getNewPointCounts())
    std::cout << " " << count;
  std::cout << "\n";

  // Save the points labelled by hole (0: in no rim band) and the filled cloud.
  pcl::PointCloud<pcl::PointXYZL> labelled;
  pcl::copyPointCloud (*cloud, labelled);
  for (std::size_t i = 0; i < labelled.size(); ++i)
    labelled[i].label = hb.getRimBandLabels()[i];
  if (pcl::io::savePCDFileBinary ("holes.pcd", labelled) < 0 ||
      pcl::io::savePCDFileBinary ("filled.pcd", filled) < 0)
    return EXIT_FAILURE;
  std::cout << "Written: holes.pcd, filled.pcd\n";
  return EXIT_SUCCESS;
}
