// Builds the complex of a unit square's corners through the installed package, with
// the CPU builder and with the gpu/ one, and prints its H0 diagram size: 4
// components born, 3 die at 1, 1 is essential.
#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/gpu/vietoris_rips_builder.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#include <cstdio>

int
main ()
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  cloud->push_back ({0, 0, 0});
  cloud->push_back ({1, 0, 0});
  cloud->push_back ({0, 1, 0});
  cloud->push_back ({1, 1, 0});
  pcl::tda::VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (1.0);
  pcl::tda::FilteredComplex complex;
  if (!builder.compute (complex))
    return 1;
  pcl::tda::gpu::VietorisRipsBuilder<pcl::PointXYZ> gpu_builder;
  gpu_builder.setInputCloud (cloud);
  gpu_builder.setRadius (1.0);
  pcl::tda::FilteredComplex gpu_complex;
  if (!gpu_builder.compute (gpu_complex))
    return 1;
  const auto diagram = pcl::tda::computeH0Persistence (complex).diagram (complex);
  std::printf ("edges %zu (gpu %zu) intervals %zu\n",
               complex.numEdges(),
               gpu_complex.numEdges(),
               diagram.size());
  return complex.numEdges() == 4 && gpu_complex.numEdges() == 4 && diagram.size() == 4
             ? 0
             : 1;
}
