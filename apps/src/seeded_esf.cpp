// PCL's ESF with a seeded generator (see seeded_esf.h). Everything PCL's
// implementation includes is included first, so that the two macros below reach
// nothing but the body of pcl/features/impl/esf.hpp.
#include <pcl/common/centroid.h>
#include <pcl/common/distances.h>
#include <pcl/common/transforms.h>
#include <pcl/features/esf.h>
#include <pcl/tda/apps/seeded_esf.h>
#include <pcl/exceptions.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <random>
#include <vector>

namespace {

/** The generator of the ESF computed on this thread. */
thread_local std::mt19937_64 esf_generator;

/** A replacement of rand(): a number in [0, RAND_MAX]. */
int
esfRandom ()
{
  return static_cast<int> (esf_generator() %
                           (static_cast<std::uint64_t> (RAND_MAX) + 1));
}

} // namespace

// PCL's computeESF() calls srand(time(nullptr)), then rand(): seeding is ours.
#define srand(seed) static_cast<void> (0)
#define rand() esfRandom()
#include <pcl/features/impl/esf.hpp>
#undef rand
#undef srand

namespace pcl {
namespace tda {
namespace {

/** The output type of our ESF: PCL instantiates ESFEstimation only for
 * pcl::ESFSignature640, so the code above defines a class of its own. */
using SeededESFEstimation = pcl::ESFEstimation<pcl::PointXYZ, pcl::Histogram<640>>;

/** Refuses the clouds on which PCL's sampler never ends. */
void
checkSampleable (const pcl::PointCloud<pcl::PointXYZ>& cloud)
{
  if (cloud.size() < 3)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "ESF needs at least 3 points, the view has " << cloud.size());
  Eigen::Matrix3f covariance = Eigen::Matrix3f::Zero();
  Eigen::Vector4f centroid = Eigen::Vector4f::Zero();
  pcl::computeMeanAndCovarianceMatrix (cloud, covariance, centroid);
  float radius = 0.0f;
  for (const auto& point : cloud)
    radius = std::max (radius, (point.getVector3fMap() - centroid.head<3>()).norm());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> solver (covariance);
  // PCL scales the cloud to a sphere of radius 32 and rejects triangles of area
  // below 0.03: the second axis must not be much thinner than that.
  const float scale = radius > 0.0f ? 32.0f / radius : 0.0f;
  if (!(std::sqrt (std::max (solver.eigenvalues()[1], 0.0f)) * scale >= 0.1f))
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         "ESF cannot sample a view whose points lie on a line");
}

} // namespace

std::vector<float>
computeSeededESF (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                  std::uint64_t seed)
{
  checkSampleable (*cloud);
  esf_generator.seed (seed);
  SeededESFEstimation esf;
  esf.setInputCloud (cloud);
  pcl::PointCloud<pcl::Histogram<640>> output;
  esf.compute (output);
  if (output.size() != 1)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException, "PCL's ESF gave no histogram");
  return {output[0].histogram, output[0].histogram + 640};
}

} // namespace tda
} // namespace pcl
