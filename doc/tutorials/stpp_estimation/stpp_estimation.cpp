// Tutorial: the STPP signature of scans and the distances between them
// (doc/tutorials/stpp_estimation.md).

#include <pcl/console/time.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/tda/features/stpp_estimation.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Signatures = pcl::PointCloud<pcl::tda::STPPSignature>;

/** \brief The Euclidean distance between two signatures. */
double
signatureDistance (const pcl::tda::STPPSignature& a, const pcl::tda::STPPSignature& b)
{
  double sum = 0;
  for (int i = 0; i < pcl::tda::STPPSignature::descriptorSize(); ++i)
    sum += (a.histogram[i] - b.histogram[i]) * (a.histogram[i] - b.histogram[i]);
  return std::sqrt (sum);
}

int
main (int argc, char** argv)
{
  if (argc < 3) {
    std::cerr << "Syntax is: " << argv[0] << " a.pcd b.pcd [c.pcd ...]\n";
    return EXIT_FAILURE;
  }
  // The scans, and the first one again with every second point only.
  std::vector<Cloud::Ptr> clouds;
  std::vector<std::string> names;
  for (int i = 1; i < argc; ++i) {
    Cloud::Ptr cloud (new Cloud);
    if (pcl::io::loadPCDFile (argv[i], *cloud) < 0)
      return EXIT_FAILURE;
    clouds.push_back (cloud);
    names.push_back (argv[i]);
  }
  Cloud::Ptr half (new Cloud);
  for (std::size_t i = 0; i < clouds[0]->size(); i += 2)
    half->push_back ((*clouds[0])[i]);
  clouds.push_back (half);
  names.push_back (names[0] + ", every 2nd point");

  // One signature per cloud, as pcl::VFHEstimation or pcl::ESFEstimation give.
  Signatures signatures;
  pcl::tda::STPPEstimation<pcl::PointXYZ, pcl::tda::STPPSignature> stpp;
  for (std::size_t c = 0; c < clouds.size(); ++c) {
    pcl::console::TicToc timer;
    timer.tic();
    stpp.setInputCloud (clouds[c]);
    Signatures signature;
    stpp.compute (signature);
    if (signature.size() != 1)
      return EXIT_FAILURE; // compute() printed why
    signatures.push_back (signature[0]);
    std::printf ("%c: %s, %zu points, size %.3f m, %.1f ms\n   radii",
                 static_cast<char> ('A' + c),
                 names[c].c_str(),
                 clouds[c]->size(),
                 stpp.getCloudSize(),
                 timer.toc());
    for (const double radius : stpp.getLevelRadii())
      std::printf (" %.4f", radius);
    std::printf ("; open 1-cycles at them");
    for (const pcl::tda::PersistenceDiagram& diagram : stpp.getLevelDiagrams()) {
      std::size_t open = 0;
      for (const pcl::tda::PersistenceInterval& bar : diagram)
        open += bar.dimension == 1 && bar.isEssential();
      std::printf (" %zu", open);
    }
    std::printf ("\n");
    // The barcode of the first scan's level 2 (radius S / 4), to look at.
    if (c == 0) {
      try {
        pcl::tda::PlotOptions plot;
        plot.title = names[0] + ", level 2 (r = S / 4)";
        plot.max_bars_per_dimension = 40;
        plot.max_value = stpp.getLevelRadii()[2];
        plot.unit = "m";
        plot.cut = 2 * stpp.getLevelRadii()[2] / 3; // the curves are sampled after it
        pcl::tda::saveBarcodeSVG ("level2.svg", stpp.getLevelDiagrams()[2], plot);
      }
      catch (const pcl::PCLException& error) {
        std::cerr << error.detailedMessage() << "\n";
        return EXIT_FAILURE;
      }
    }
  }

  // The distances between the signatures: small for the same object.
  std::printf ("Distances between the signatures:\n  ");
  for (std::size_t b = 0; b < signatures.size(); ++b)
    std::printf ("%8c", static_cast<char> ('A' + b));
  std::printf ("\n");
  for (std::size_t a = 0; a < signatures.size(); ++a) {
    std::printf ("%c ", static_cast<char> ('A' + a));
    for (std::size_t b = 0; b < signatures.size(); ++b)
      std::printf ("%8.3f", signatureDistance (signatures[a], signatures[b]));
    std::printf ("\n");
  }
  if (pcl::io::savePCDFileASCII ("signatures.pcd", signatures) < 0)
    return EXIT_FAILURE;
  std::cout << "Written: signatures.pcd, level2.svg\n";
  return EXIT_SUCCESS;
}
