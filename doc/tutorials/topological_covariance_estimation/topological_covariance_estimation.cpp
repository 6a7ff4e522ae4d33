// Tutorial: the topological covariance descriptor of scans and the log-Euclidean
// distances between them (doc/tutorials/topological_covariance_estimation.md).

#include <pcl/common/io.h>
#include <pcl/features/normal_3d.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/features/topological_covariance_estimation.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using Descriptor = pcl::tda::CovarianceSignature;
using Descriptors = pcl::PointCloud<Descriptor>;
constexpr std::size_t FEATURES = pcl::tda::COVARIANCE_FEATURES; // 12

/** \brief The entry (i, j) of the matrix log(C) that \a descriptor holds. */
double
logCovariance (const Descriptor& descriptor, std::size_t i, std::size_t j)
{
  const std::size_t a = std::min (i, j), b = std::max (i, j);
  return descriptor.histogram[a * (2 * FEATURES - a + 1) / 2 + b - a] /
         (a == b ? 1.0 : std::sqrt (2.0));
}

/** \brief Appends the descriptor of every \a step th point of \a blob read as PointT
 * to \a descriptors, with normals by pcl::NormalEstimation; false on failure. */
template <typename PointT>
bool
describe (const pcl::PCLPointCloud2& blob, std::size_t step, Descriptors& descriptors)
{
  pcl::PointCloud<PointT> all;
  pcl::fromPCLPointCloud2 (blob, all);
  typename pcl::PointCloud<PointT>::Ptr cloud (new pcl::PointCloud<PointT>);
  for (std::size_t i = 0; i < all.size(); i += step)
    cloud->push_back (all[i]);

  pcl::NormalEstimation<PointT, pcl::Normal> normal_estimation;
  normal_estimation.setInputCloud (cloud);
  normal_estimation.setKSearch (10);
  pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
  normal_estimation.compute (*normals);

  pcl::tda::TopologicalCovarianceEstimation<PointT, pcl::Normal, Descriptor> tc;
  tc.setInputCloud (cloud);
  tc.setInputNormals (normals);
  Descriptors descriptor;
  tc.compute (descriptor);
  if (descriptor.size() != 1)
    return false; // compute() printed why
  descriptors.push_back (descriptor[0]);
  std::printf ("   %zu points, r = %.4f m; diagonal of log(C):\n  ",
               cloud->size(),
               tc.getUsedRadius());
  for (std::size_t i = 0; i < FEATURES; ++i)
    std::printf (
        "%s %.1f", i % 3 == 0 ? " |" : "", logCovariance (descriptor[0], i, i));
  std::printf ("\n");
  return true;
}

/** \brief Draws the matrix log(C) of \a descriptor: blue below 0, red above, the
 * fullest at |value| >= 10. */
bool
saveLogCovarianceSVG (const std::string& path, const Descriptor& descriptor)
{
  const char* labels[FEATURES] = {
      "x", "y", "z", "L", "a", "b", "nx", "ny", "nz", "β 0.6r", "β 0.8r", "β r"};
  std::ofstream svg (path);
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='560' height='540' "
         "font-family='sans-serif' font-size='12' text-anchor='middle'>\n"
      << "<rect width='100%' height='100%' fill='white'/>\n";
  for (std::size_t i = 0; i < FEATURES; ++i) {
    svg << "<text x='27' y='" << 84 + 40 * i << "'>" << labels[i] << "</text><text x='"
        << 80 + 40 * i << "' y='50'>" << labels[i] << "</text>\n";
    for (std::size_t j = 0; j < FEATURES; ++j) {
      const double value = logCovariance (descriptor, i, j);
      const int fade =
          255 - static_cast<int> (std::min (175.0, 17.5 * std::abs (value)));
      svg << "<rect x='" << 60 + 40 * j << "' y='" << 60 + 40 * i
          << "' width='40' height='40' fill='rgb(" << (value < 0 ? fade : 255) << ","
          << fade << "," << (value < 0 ? 255 : fade) << ")'/><text x='" << 80 + 40 * j
          << "' y='" << 84 + 40 * i << "'>"
          << std::round (value * 10) / 10 + 0.0 // + 0.0: 0, not -0
          << "</text>\n";
    }
  }
  svg << "</svg>\n";
  return static_cast<bool> (svg);
}

int
main (int argc, char** argv)
{
  if (argc < 3) {
    std::cerr << "Syntax is: " << argv[0] << " a.pcd b.pcd [c.pcd ...]\n";
    return EXIT_FAILURE;
  }
  // One descriptor per scan, with colour when the file has it; then the first scan
  // again with every second point only.
  std::vector<std::string> files (argv + 1, argv + argc);
  files.push_back (argv[1]);
  Descriptors descriptors;
  for (std::size_t f = 0; f < files.size(); ++f) {
    pcl::PCLPointCloud2 blob;
    if (pcl::io::loadPCDFile (files[f], blob) < 0)
      return EXIT_FAILURE;
    const bool color =
        pcl::getFieldIndex (blob, "rgb") >= 0 || pcl::getFieldIndex (blob, "rgba") >= 0;
    const std::size_t step = f + 1 < files.size() ? 1 : 2;
    std::printf ("%c: %s%s%s\n",
                 static_cast<char> ('A' + f),
                 files[f].c_str(),
                 color ? ", with colour" : "",
                 step == 1 ? "" : ", every 2nd point");
    if (!(color ? describe<pcl::PointXYZRGB> (blob, step, descriptors)
                : describe<pcl::PointXYZ> (blob, step, descriptors)))
      return EXIT_FAILURE;
  }

  // The Euclidean distances between the vectors are the log-Euclidean distances
  // between the covariance matrices.
  std::printf ("%d values per descriptor; log-Euclidean distances:\n  ",
               Descriptor::descriptorSize());
  for (std::size_t b = 0; b < descriptors.size(); ++b)
    std::printf ("%7c", static_cast<char> ('A' + b));
  for (std::size_t a = 0; a < descriptors.size(); ++a) {
    std::printf ("\n%c ", static_cast<char> ('A' + a));
    for (std::size_t b = 0; b < descriptors.size(); ++b) {
      double sum = 0;
      for (int k = 0; k < Descriptor::descriptorSize(); ++k)
        sum += std::pow (descriptors[a].histogram[k] - descriptors[b].histogram[k], 2);
      std::printf ("%7.2f", std::sqrt (sum));
    }
  }
  std::printf ("\n");
  if (pcl::io::savePCDFileASCII ("descriptors.pcd", descriptors) < 0 ||
      !saveLogCovarianceSVG ("log_covariance.svg", descriptors[0]))
    return EXIT_FAILURE;
  std::cout << "Written: descriptors.pcd, log_covariance.svg (log(C) of A)\n";
  return EXIT_SUCCESS;
}
