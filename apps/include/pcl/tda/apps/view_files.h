#pragma once

#include <pcl/tda/apps/view_descriptors.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The descriptors of one PCD file, or why it could not be read. */
struct DescribedFile {
  /** \brief One per descriptor asked for (each with its own failure, if any). */
  std::vector<ViewDescriptor> descriptors;
  /** \brief Why the file could not be read; empty when it was. */
  std::string error;
};

/** \brief The seed of ESF's sampling for the view named \a name (FNV-1a of the
 * name): equal names give equal histograms, on any thread. */
std::uint64_t
viewSeed (const std::string& name);

/** \brief Reads every file of \a files (as pcl::PointXYZRGB: colour where the file
 * has one) and computes its descriptors \a names (computeViewDescriptors(), seeded
 * with viewSeed() of \a names_for_seeds[i]), in parallel over the files (OpenMP,
 * each file on one thread), with a progress bar labelled \a label. The files
 * described at once share \a topological's memory limit: each thread's view may
 * build complexes of the limit divided by the number of threads. PCL's own
 * messages are silenced meanwhile (they come from all threads at once): every
 * failure is in the result.
 * \throws pcl::BadArgumentException on an unknown descriptor name */
std::vector<DescribedFile>
describeViewFiles (const std::vector<std::string>& files,
                   const std::vector<std::string>& names_for_seeds,
                   const std::vector<std::string>& names,
                   const TopologicalSettings& topological,
                   const std::string& label);

} // namespace tda
} // namespace pcl
