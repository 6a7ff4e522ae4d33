// Tutorial: the Vietoris-Rips complex of a point cloud and its persistence
// (doc/tutorials/vietoris_rips_persistence.md).

#include <pcl/console/time.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/common/betti_numbers.h>
#include <pcl/tda/common/diagram_io.h>
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/persistence_engines.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>

/** \brief Number of the longest bars of each dimension the program prints. */
constexpr std::size_t NUM_BARS_SHOWN = 5;

/** \brief Prints the \a count longest finite bars of dimension \a dimension of
 * \a diagram, longest first. */
void
printLongestBars (const pcl::tda::PersistenceDiagram& diagram,
                  int dimension,
                  std::size_t count)
{
  pcl::tda::PersistenceDiagram bars;
  for (const pcl::tda::PersistenceInterval& bar : diagram)
    if (bar.dimension == dimension && !bar.isEssential())
      bars.push_back (bar);
  std::sort (bars.begin(),
             bars.end(),
             [] (const pcl::tda::PersistenceInterval& a,
                 const pcl::tda::PersistenceInterval& b) {
               return a.death - a.birth > b.death - b.birth;
             });
  bars.resize (std::min (count, bars.size()));
  for (const pcl::tda::PersistenceInterval& bar : bars)
    std::printf ("  H%d [%.4f, %.4f)  length %.4f\n",
                 dimension,
                 bar.birth,
                 bar.death,
                 bar.death - bar.birth);
}

int
main (int argc, char** argv)
{
  if (argc < 2) {
    std::cerr << "Syntax is: " << argv[0] << " input.pcd [radius]\n";
    return EXIT_FAILURE;
  }
  const double radius = argc > 2 ? std::atof (argv[2]) : 0.02;

  // Read the points.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  if (pcl::io::loadPCDFile (argv[1], *cloud) < 0)
    return EXIT_FAILURE;
  std::cout << "Loaded " << cloud->size() << " points from " << argv[1] << "\n";

  // Build the Vietoris-Rips complex VR_r: every edge and triangle whose points are
  // pairwise at most r apart, each entering the filtration at its longest edge.
  pcl::console::TicToc timer;
  timer.tic();
  pcl::tda::VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (radius);
  builder.setMaxDimension (2); // triangles too: they kill the 1-cycles
  pcl::tda::FilteredComplex complex;
  if (!builder.compute (complex))
    return EXIT_FAILURE; // the builder printed why
  std::cout << "Vietoris-Rips complex of radius " << radius << ": "
            << complex.numVertices() << " vertices, " << complex.numEdges()
            << " edges, " << complex.numTriangles() << " triangles (" << timer.toc()
            << " ms)\n";

  // H0 alone: union-find over the edges (the connected components).
  timer.tic();
  const pcl::tda::PersistenceResult h0 = pcl::tda::computeH0Persistence (complex);
  const pcl::tda::PersistenceDiagram h0_diagram = h0.diagram (complex, 0);
  std::cout << "H0: " << h0_diagram.size() << " intervals (" << timer.toc() << " ms)\n";

  // H0 and H1 together: the 1-cycles (loops, holes) and when triangles fill them.
  timer.tic();
  const pcl::tda::PersistenceResult result = pcl::tda::computePersistence (complex);
  const pcl::tda::PersistenceDiagram diagram = result.diagram (complex);
  std::cout << "H0 + H1: " << diagram.size() << " intervals (" << timer.toc()
            << " ms)\n";

  // The Betti numbers at a few radii, read from the same result.
  for (const double at : {radius / 4, radius / 2, radius}) {
    const pcl::tda::BettiNumbers betti =
        pcl::tda::computeBettiNumbersAt (complex, result, at);
    std::cout << "  at r = " << at << ": beta_0 = " << betti[0]
              << ", beta_1 = " << betti[1] << "\n";
  }
  std::cout << "Longest bars:\n";
  printLongestBars (diagram, 0, NUM_BARS_SHOWN);
  printLongestBars (diagram, 1, NUM_BARS_SHOWN);

  // Save the diagram as CSV and draw its barcode.
  try {
    pcl::tda::saveDiagramCSV ("diagram.csv", diagram);
    pcl::tda::PlotOptions plot;
    std::ostringstream title;
    title << argv[1] << ", up to radius " << radius << " m";
    plot.title = title.str();
    plot.max_value = radius;
    plot.unit = "m";
    pcl::tda::saveBarcodeSVG ("barcode.svg", diagram, plot);
  }
  catch (const pcl::PCLException& error) {
    std::cerr << error.detailedMessage() << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "Written: diagram.csv, barcode.svg\n";
  return EXIT_SUCCESS;
}
