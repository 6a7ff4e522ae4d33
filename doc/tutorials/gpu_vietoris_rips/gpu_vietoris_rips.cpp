// Tutorial: the Vietoris-Rips complex built with Thrust (gpu/), against the CPU
// builder, and its persistence (doc/tutorials/gpu_vietoris_rips.md).

#include <pcl/console/time.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/common/persistence_engines.h>
#include <pcl/tda/common/persistence_plots.h>
#include <pcl/tda/gpu/vietoris_rips_builder.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <cstdlib>
#include <iostream>
#include <string>

/** \brief True when \a a and \a b are the same complex: the same points as
 * vertices, the same edges and triangles in the same order, with the same values. */
bool
sameComplex (const pcl::tda::FilteredComplex& a, const pcl::tda::FilteredComplex& b)
{
  if (a.pointIndices() != b.pointIndices() || a.numEdges() != b.numEdges() ||
      a.numTriangles() != b.numTriangles())
    return false;
  for (std::size_t i = 0; i < a.numEdges(); ++i) {
    const pcl::tda::FilteredEdge &x = a.edges()[i], &y = b.edges()[i];
    if (x.source != y.source || x.target != y.target || x.value != y.value)
      return false;
  }
  for (std::size_t i = 0; i < a.numTriangles(); ++i) {
    const pcl::tda::FilteredTriangle &x = a.triangles()[i], &y = b.triangles()[i];
    if (x.edges != y.edges || x.value != y.value)
      return false;
  }
  return true;
}

int
main (int argc, char** argv)
{
  if (argc < 2) {
    std::cerr << "Syntax is: " << argv[0] << " input.pcd [radius]\n";
    return EXIT_FAILURE;
  }
  const double radius = argc > 2 ? std::atof (argv[2]) : 0.006;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  if (pcl::io::loadPCDFile (argv[1], *cloud) < 0)
    return EXIT_FAILURE;
  std::cout << "Loaded " << cloud->size() << " points from " << argv[1] << "\n";

  // Where the Thrust code will run: a CUDA device, or the host's cores (OpenMP).
  std::string why;
  const pcl::tda::gpu::DeviceBackend backend = pcl::tda::gpu::selectBackend (why);
  std::cout << "Library built with CUDA: "
            << (pcl::tda::gpu::builtWithCUDA() ? "yes" : "no") << "; backend "
            << pcl::tda::gpu::backendName (backend);
  if (!why.empty())
    std::cout << " (" << why << ")";
  std::cout << "\n";

  // The CPU builder, then the gpu/ one with the same settings.
  pcl::console::TicToc timer;
  timer.tic();
  pcl::tda::VietorisRipsBuilder<pcl::PointXYZ> cpu_builder;
  cpu_builder.setInputCloud (cloud);
  cpu_builder.setRadius (radius);
  cpu_builder.setMaxDimension (2);
  pcl::tda::FilteredComplex cpu_complex;
  if (!cpu_builder.compute (cpu_complex))
    return EXIT_FAILURE; // the builder printed why
  std::cout << "pcl::tda::VietorisRipsBuilder:      " << cpu_complex.numEdges()
            << " edges, " << cpu_complex.numTriangles() << " triangles (" << timer.toc()
            << " ms)\n";

  timer.tic();
  pcl::tda::gpu::VietorisRipsBuilder<pcl::PointXYZ> gpu_builder;
  gpu_builder.setInputCloud (cloud);
  gpu_builder.setRadius (radius);
  gpu_builder.setMaxDimension (2);
  pcl::tda::FilteredComplex complex;
  if (!gpu_builder.compute (complex))
    return EXIT_FAILURE; // the builder printed why
  std::cout << "pcl::tda::gpu::VietorisRipsBuilder: " << complex.numEdges()
            << " edges, " << complex.numTriangles() << " triangles (" << timer.toc()
            << " ms, " << pcl::tda::gpu::backendName (gpu_builder.getBackend())
            << ")\n";
  if (!sameComplex (cpu_complex, complex)) {
    std::cerr << "The two complexes differ\n";
    return EXIT_FAILURE;
  }
  std::cout << "The two complexes are identical\n";

  // Persistence of the complex, as of any FilteredComplex.
  timer.tic();
  const pcl::tda::PersistenceDiagram diagram =
      pcl::tda::computePersistence (complex).diagram (complex);
  std::size_t bars[2] = {0, 0}, essential[2] = {0, 0};
  for (const pcl::tda::PersistenceInterval& bar : diagram) {
    ++bars[bar.dimension];
    essential[bar.dimension] += bar.isEssential();
  }
  std::cout << "Persistence: " << bars[0] << " H0 bars (" << essential[0]
            << " components at r), " << bars[1] << " H1 bars (" << essential[1]
            << " 1-cycles open at r) in " << timer.toc() << " ms\n";
  try {
    pcl::tda::PlotOptions plot;
    plot.title = std::string (argv[1]) + ", gpu::VietorisRipsBuilder";
    plot.max_value = radius;
    plot.unit = "m";
    pcl::tda::savePersistenceDiagramSVG ("diagram.svg", diagram, plot);
  }
  catch (const pcl::PCLException& error) {
    std::cerr << error.detailedMessage() << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "Written: diagram.svg\n";
  return EXIT_SUCCESS;
}
