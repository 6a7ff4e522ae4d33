#pragma once

#include <pcl/tda/apps/view_descriptors.h>

#include <cstddef>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The descriptors pcl_tda_classify compares by default: thesis Table 6.1
 * (STPP against PCL's VFH, ESF, GRSD, CVFH and OUR-CVFH), Experiment 2 (the Betti-0
 * and Betti-1 parts of STPP), Experiment 4 (the topological covariance descriptor),
 * and STPP combined with VFH and with ESF. */
constexpr const char* DEFAULT_DESCRIPTORS =
    "stpp,stpp0,stpp1,covariance,vfh,esf,grsd,cvfh,ourcvfh,stpp+vfh,stpp+esf";

/** \brief A descriptor to classify with: one of viewDescriptorNames(), or several
 * joined by '+', whose vectors are concatenated. */
struct DescriptorSpec {
  /** \brief As given, e.g. "stpp+esf". */
  std::string name;
  /** \brief Its descriptors of viewDescriptorNames(), e.g. {"stpp", "esf"}. */
  std::vector<std::string> parts;
};

/** \brief Parses a comma-separated list of descriptors (DescriptorSpec), e.g.
 * "stpp,esf,stpp+esf".
 * \throws pcl::BadArgumentException naming an unknown or repeated descriptor, or a
 * descriptor repeated within a combination */
std::vector<DescriptorSpec>
parseDescriptorList (const std::string& list);

/** \brief The descriptors of viewDescriptorNames() that \a specs need, each once, in
 * order of appearance. */
std::vector<std::string>
neededViewDescriptors (const std::vector<DescriptorSpec>& specs);

/** \brief The vectors of one descriptor for every view, and what it took. */
struct DescriptorTable {
  /** \brief The vector of each view; empty where the descriptor failed. */
  std::vector<std::vector<float>> rows;
  /** \brief Why it failed on each view ("" where it did not). */
  std::vector<std::string> failures;
  /** \brief Milliseconds to compute it on each view, normals included (once). */
  std::vector<double> milliseconds;
  /** \brief The sizes of its parts (fitFeatureScaling()). */
  std::vector<std::size_t> parts;
  /** \brief The size of its vectors (0 when it failed on every view). */
  std::size_t dimension = 0;
};

/** \brief The table of \a spec from the descriptors \a computed[view][k] of every
 * view, k indexing \a names (computeViewDescriptors()): the parts' values
 * concatenated, failed where any part failed (with that part's reason).
 * \throws pcl::BadArgumentException when a part's vectors differ in size between
 * views */
DescriptorTable
assembleDescriptor (const DescriptorSpec& spec,
                    const std::vector<std::string>& names,
                    const std::vector<std::vector<ViewDescriptor>>& computed);

} // namespace tda
} // namespace pcl
