#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The 640 values of PCL's ESF descriptor (pcl::ESFEstimation, Wohlkinger and
 * Vincze 2011) of \a cloud, with its random samples drawn from a generator seeded
 * with \a seed.
 *
 * pcl::ESFEstimation draws its 20000 point triples with rand() after
 * srand(time(nullptr)): its histogram changes from second to second, and threads
 * computing ESF at once share and reseed one generator. Here PCL's own ESF code
 * (pcl/features/impl/esf.hpp, compiled in this library for an output type PCL does
 * not instantiate, so that it is no second definition of PCL's) draws from a
 * per-thread std::mt19937_64 seeded with \a seed instead: the same cloud and seed
 * give the same histogram, on any thread.
 *
 * PCL's sampler loops for ever on a cloud of fewer than 3 points or on points
 * along a line (every triangle is rejected): such clouds are refused.
 * \throws pcl::BadArgumentException when \a cloud has fewer than 3 points or its
 * points are (nearly) collinear */
std::vector<float>
computeSeededESF (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                  std::uint64_t seed);

} // namespace tda
} // namespace pcl
