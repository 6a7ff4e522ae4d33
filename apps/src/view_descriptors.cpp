#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/features/cvfh.h>
#include <pcl/features/grsd.h>
#include <pcl/features/normal_3d.h>
#include <pcl/features/our_cvfh.h>
#include <pcl/features/vfh.h>
#include <pcl/tda/apps/coordinate_check.h>
#include <pcl/tda/apps/seeded_esf.h>
#include <pcl/tda/apps/view_descriptors.h>
#include <pcl/tda/common/coordinate_scale.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/tda/features/stpp_estimation.h>
#include <pcl/tda/features/topological_covariance_estimation.h>
#include <pcl/tda/search/canonical_order.h>
#include <pcl/tda/search/point_spacing.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <numeric>
#include <sstream>
#include <type_traits>

namespace pcl {
namespace tda {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using ColorCloud = pcl::PointCloud<pcl::PointXYZRGB>;
using Normals = pcl::PointCloud<pcl::Normal>;
using Clock = std::chrono::steady_clock;

/** OUR-CVFH's refinement factor: a region keeps the points whose normal is within
 * this times the angle threshold (0.125 rad) of the region's mean normal. PCL's
 * default, 1, can leave a region of one or two points on a curved surface, and
 * PCL's reference frame of such a region is made of uninitialised memory (random
 * histograms, or a crash): 26 (3.25 rad > pi) keeps every point. */
constexpr float OURCVFH_REFINEMENT = 26.0f;

double
millisecondsSince (Clock::time_point start)
{
  return std::chrono::duration<double, std::milli> (Clock::now() - start).count();
}

/** What the descriptors of one view are computed from. */
struct ViewInput {
  /** The finite points of the view, with its sensor origin, and with their
   * colours. */
  Cloud::Ptr points;
  ColorCloud::Ptr colored_points;
  /** The points that have a normal, with and without colour, and their normals
   * (null until estimated). */
  Cloud::Ptr surface;
  ColorCloud::Ptr colored_surface;
  Normals::Ptr normals;
  /** The radius of the normals (NORMAL_RADIUS_PER_SPACING times the spacing). */
  double radius = 0.0;
  /** Why the view has no normals, when it has none. */
  std::string normal_failure;
  std::uint64_t seed = 0;
  TopologicalSettings topological;
};

[[noreturn]] void
fail (const std::string& reason)
{
  PCL_THROW_EXCEPTION (pcl::ComputeFailedException, reason);
}

/** Fails for the topological descriptor \a name, which gave no output for
 * \a points, saying why (the class's own message is not printed while the views
 * are described in parallel). */
template <typename PointT>
[[noreturn]] void
failTopological (const std::string& name,
                 const pcl::PointCloud<PointT>& points,
                 const TopologicalSettings& settings)
{
  const std::size_t distinct = countFinitePositions (points).distinct;
  if (distinct <= SURFACE_SPACING_NEIGHBORS)
    fail (name + " gave no signature: " + std::to_string (distinct) +
          " distinct finite points, at least " +
          std::to_string (SURFACE_SPACING_NEIGHBORS + 1) + " are needed");
  fail (name +
        " gave no signature: its complex could not be built, over the memory "
        "limit of " +
        formatBytes (static_cast<double> (settings.memory_limit)) +
        " (a smaller -radius or a larger -memory), or for a -radius too small for "
        "the cloud's extent");
}

/** Estimates the normals of \a input (pcl::NormalEstimation) and keeps the points
 * that have one. */
void
estimateNormals (ViewInput& input)
{
  input.radius = NORMAL_RADIUS_PER_SPACING * pointSpacing (*input.points, 0.5, 1);
  if (input.radius <= 0.0) {
    input.normal_failure = "fewer than 2 distinct points, no normals";
    return;
  }
  // On the points divided by a power of two (exact), so that float sums of squares
  // neither underflow nor overflow (a view in units of 1e-25 had no normal); the
  // same normals in metres. The viewpoint, the origin, stays where it is.
  const double scale = cloudScale (*input.points);
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud (scaledPositions (*input.points, scale));
  estimation.setRadiusSearch (input.radius / scale);
  Normals all;
  estimation.compute (all);
  input.surface.reset (new Cloud);
  input.colored_surface.reset (new ColorCloud);
  input.normals.reset (new Normals);
  input.surface->sensor_origin_ = input.points->sensor_origin_;
  input.colored_surface->sensor_origin_ = input.points->sensor_origin_;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (pcl::isNormalFinite (all[i])) {
      input.surface->push_back ((*input.points)[i]);
      input.colored_surface->push_back ((*input.colored_points)[i]);
      input.normals->push_back (all[i]);
    }
  if (input.surface->size() < 3) {
    std::ostringstream reason;
    reason << "fewer than 3 points have a normal (radius " << input.radius << ")";
    input.normal_failure = reason.str();
  }
}

/** The histogram of a one-point descriptor output. */
template <typename Signature>
std::vector<float>
singleHistogram (const pcl::PointCloud<Signature>& output, const std::string& name)
{
  if (output.size() != 1)
    fail ("PCL's " + name + " gave no histogram");
  const float* values = output[0].histogram;
  return {values, values + Signature::descriptorSize()};
}

/** The mean of the histograms of a clustered descriptor (CVFH, OUR-CVFH). */
std::vector<float>
meanHistogram (const pcl::PointCloud<pcl::VFHSignature308>& output,
               const std::string& name)
{
  if (output.empty())
    fail ("PCL's " + name + " gave no histogram");
  std::vector<double> sum (pcl::VFHSignature308::descriptorSize(), 0.0);
  for (const auto& signature : output)
    for (std::size_t d = 0; d < sum.size(); ++d)
      sum[d] += signature.histogram[d];
  std::vector<float> mean (sum.size());
  for (std::size_t d = 0; d < sum.size(); ++d)
    mean[d] = static_cast<float> (sum[d] / static_cast<double> (output.size()));
  return mean;
}

template <typename Estimation>
void
setSurface (Estimation& estimation, const ViewInput& input)
{
  estimation.setInputCloud (input.surface);
  estimation.setInputNormals (input.normals);
}

std::vector<float>
vfh (const ViewInput& input)
{
  pcl::VFHEstimation<pcl::PointXYZ, pcl::Normal, pcl::VFHSignature308> estimation;
  setSurface (estimation, input);
  const Eigen::Vector4f& origin = input.surface->sensor_origin_;
  estimation.setViewPoint (origin[0], origin[1], origin[2]);
  pcl::PointCloud<pcl::VFHSignature308> output;
  estimation.compute (output);
  return singleHistogram (output, "VFH");
}

using CVFH = pcl::CVFHEstimation<pcl::PointXYZ, pcl::Normal, pcl::VFHSignature308>;
using OURCVFH =
    pcl::OURCVFHEstimation<pcl::PointXYZ, pcl::Normal, pcl::VFHSignature308>;

/** CVFH or OUR-CVFH, set up alike: the mean of its histograms. */
template <typename Estimation>
std::vector<float>
clusteredVFH (const ViewInput& input, const std::string& name)
{
  Estimation estimation;
  setSurface (estimation, input);
  const Eigen::Vector4f& origin = input.surface->sensor_origin_;
  estimation.setViewPoint (origin[0], origin[1], origin[2]);
  estimation.setClusterTolerance (static_cast<float> (input.radius));
  estimation.setRadiusNormals (static_cast<float> (input.radius));
  if constexpr (std::is_same_v<Estimation, OURCVFH>)
    estimation.setRefineClusters (OURCVFH_REFINEMENT);
  pcl::PointCloud<pcl::VFHSignature308> output;
  estimation.compute (output);
  return meanHistogram (output, name);
}

std::vector<float>
grsd (const ViewInput& input)
{
  pcl::GRSDEstimation<pcl::PointXYZ, pcl::Normal, pcl::GRSDSignature21> estimation;
  setSurface (estimation, input);
  estimation.setRadiusSearch (input.radius);
  pcl::PointCloud<pcl::GRSDSignature21> output;
  estimation.compute (output);
  return singleHistogram (output, "GRSD");
}

std::vector<float>
esf (const ViewInput& input)
{
  return computeSeededESF (input.points, input.seed);
}

std::vector<float>
stpp (const ViewInput& input, STPPHomology homology)
{
  STPPEstimation<pcl::PointXYZ, STPPSignature> estimation;
  estimation.setInputCloud (input.points);
  estimation.setHomology (homology);
  estimation.setRadius (input.topological.radius);
  estimation.setMemoryLimit (input.topological.memory_limit);
  estimation.setNumberOfThreads (1); // the views are computed in parallel
  pcl::PointCloud<STPPSignature> output;
  estimation.compute (output);
  if (output.size() != 1)
    failTopological ("STPP", *input.points, input.topological);
  checkToolCoordinates (*input.points, estimation.getLevelRadii().front(), "radius");
  return stppSignatureValues (output[0], homology);
}

std::vector<float>
covariance (const ViewInput& input)
{
  TopologicalCovarianceEstimation<pcl::PointXYZRGB, pcl::Normal, CovarianceSignature>
      estimation;
  estimation.setInputCloud (input.colored_surface);
  estimation.setInputNormals (input.normals);
  estimation.setRadius (input.topological.radius);
  estimation.setMemoryLimit (input.topological.memory_limit);
  estimation.setNumberOfThreads (1); // the views are computed in parallel
  pcl::PointCloud<CovarianceSignature> output;
  estimation.compute (output);
  if (output.size() != 1)
    failTopological ("The topological covariance descriptor",
                     *input.colored_surface,
                     input.topological);
  checkToolCoordinates (*input.colored_surface, estimation.getUsedRadius(), "radius");
  return singleHistogram (output, "covariance");
}

/** A descriptor the tool computes on each view. */
struct Definition {
  std::string name;
  bool needs_normals;
  std::function<std::vector<float> (const ViewInput&)> compute;
};

const std::vector<Definition>&
definitions ()
{
  static const std::vector<Definition> list{
      {"stpp",
       false,
       [] (const ViewInput& input) { return stpp (input, STPPHomology::BETTI_0_1); }},
      {"stpp0",
       false,
       [] (const ViewInput& input) { return stpp (input, STPPHomology::BETTI_0); }},
      {"stpp1",
       false,
       [] (const ViewInput& input) { return stpp (input, STPPHomology::BETTI_1); }},
      {"covariance", true, covariance},
      {"vfh", true, vfh},
      {"esf", false, esf},
      {"grsd", true, grsd},
      {"cvfh",
       true,
       [] (const ViewInput& input) { return clusteredVFH<CVFH> (input, "CVFH"); }},
      {"ourcvfh",
       true,
       [] (const ViewInput& input) {
         return clusteredVFH<OURCVFH> (input, "OUR-CVFH");
       }},
  };
  return list;
}

const Definition&
definition (const std::string& name)
{
  for (const Definition& known : definitions())
    if (known.name == name)
      return known;
  PCL_THROW_EXCEPTION (pcl::BadArgumentException, "Unknown descriptor " << name);
}

} // namespace

const std::vector<std::string>&
viewDescriptorNames ()
{
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const Definition& known : definitions())
      all.push_back (known.name);
    return all;
  }();
  return names;
}

bool
isViewDescriptor (const std::string& name)
{
  const auto& names = viewDescriptorNames();
  return std::find (names.begin(), names.end(), name) != names.end();
}

std::vector<ViewDescriptor>
computeViewDescriptors (const pcl::PointCloud<pcl::PointXYZRGB>& view,
                        const std::vector<std::string>& names,
                        std::uint64_t seed,
                        const TopologicalSettings& topological)
{
  ViewInput input;
  input.seed = seed;
  input.topological = topological;
  // The finite points in canonical order: PCL's normals (sums over neighbours in
  // the order of the points) and descriptors then do not depend on the file's order.
  pcl::Indices all (view.size());
  std::iota (all.begin(), all.end(), 0);
  std::size_t non_finite = 0;
  input.colored_points.reset (new ColorCloud);
  for (const pcl::index_t index : canonicalOrder (view, all, non_finite))
    input.colored_points->push_back (view[index]);
  input.colored_points->sensor_origin_ = view.sensor_origin_;
  input.colored_points->sensor_orientation_ = view.sensor_orientation_;
  input.points.reset (new Cloud);
  pcl::copyPointCloud (*input.colored_points, *input.points);

  std::vector<const Definition*> wanted;
  bool normals = false;
  for (const std::string& name : names) {
    wanted.push_back (&definition (name));
    normals = normals || wanted.back()->needs_normals;
  }
  double normal_milliseconds = 0.0;
  if (normals) {
    const Clock::time_point start = Clock::now();
    estimateNormals (input);
    normal_milliseconds = millisecondsSince (start);
  }

  std::vector<ViewDescriptor> result (wanted.size());
  for (std::size_t k = 0; k < wanted.size(); ++k) {
    ViewDescriptor& descriptor = result[k];
    if (wanted[k]->needs_normals) {
      descriptor.normal_milliseconds = normal_milliseconds;
      if (!input.normal_failure.empty()) {
        descriptor.failure = input.normal_failure;
        continue;
      }
    }
    const Clock::time_point start = Clock::now();
    try {
      if (input.points->empty())
        fail ("the view has no finite point");
      descriptor.values = wanted[k]->compute (input);
      if (!std::all_of (descriptor.values.begin(),
                        descriptor.values.end(),
                        [] (float value) { return std::isfinite (value); }))
        fail ("non-finite values");
    }
    catch (const std::exception& error) {
      descriptor.values.clear();
      descriptor.failure = errorMessage (error);
    }
    descriptor.milliseconds = millisecondsSince (start);
  }
  return result;
}

} // namespace tda
} // namespace pcl
