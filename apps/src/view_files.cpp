#include <pcl/console/print.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/view_files.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/common/progress_bar.h>
#include <pcl/tda/search/parallel_progress.h>
#include <pcl/point_types.h>

#include <omp.h>

#include <exception>

namespace pcl {
namespace tda {

std::uint64_t
viewSeed (const std::string& name)
{
  std::uint64_t hash = 14695981039346656037ULL;
  for (const char c : name)
    hash = (hash ^ static_cast<unsigned char> (c)) * 1099511628211ULL;
  return hash;
}

std::vector<DescribedFile>
describeViewFiles (const std::vector<std::string>& files,
                   const std::vector<std::string>& names_for_seeds,
                   const std::vector<std::string>& names,
                   const TopologicalSettings& topological,
                   const std::string& label)
{
  for (const std::string& name : names)
    if (!isViewDescriptor (name))
      PCL_THROW_EXCEPTION (pcl::BadArgumentException, "Unknown descriptor " << name);
  TopologicalSettings per_view = topological;
  per_view.memory_limit /= static_cast<std::size_t> (omp_get_max_threads());
  std::vector<DescribedFile> described (files.size());
  const pcl::console::VERBOSITY_LEVEL verbosity = pcl::console::getVerbosityLevel();
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  {
    ProgressBar bar (label);
    const ProgressCallback report = [&bar] (std::size_t done, std::size_t total) {
      bar.update (done, total);
    };
    ParallelProgress progress (report, files.size());
#pragma omp parallel for schedule(dynamic)
    for (std::size_t i = 0; i < files.size(); ++i) {
      try {
        pcl::PointCloud<pcl::PointXYZRGB> cloud;
        loadPointCloudFile (files[i], cloud);
        described[i].descriptors = computeViewDescriptors (
            cloud, names, viewSeed (names_for_seeds[i]), per_view);
      }
      catch (const std::exception& error) {
        described[i].error = errorMessage (error);
      }
      progress.advance (1);
    }
  }
  pcl::console::setVerbosityLevel (verbosity);
  return described;
}

} // namespace tda
} // namespace pcl
