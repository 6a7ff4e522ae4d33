/** TopologicalCovarianceEstimation: the log-Euclidean vector against the closed
 * form of a rank-one covariance, the per-point Betti-0 values against the elder
 * rule on hand-made clouds, invariance to input order and threads, and bad input
 * (no normals, mismatched normals, NaN normals, too few points). */
#include <pcl/tda/features/covariance_signature.h>
#include <pcl/tda/features/stpp_levels.h>
#include <pcl/tda/features/topological_covariance_estimation.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

namespace {

using pcl::tda::COVARIANCE_FEATURES;
using pcl::tda::COVARIANCE_SIGNATURE_SIZE;
using Estimation =
    pcl::tda::TopologicalCovarianceEstimation<pcl::PointXYZRGB,
                                              pcl::Normal,
                                              pcl::tda::CovarianceSignature>;

/** The value of the upper-triangle vector at (i, j), i <= j. */
float
entry (const float* values, std::size_t i, std::size_t j)
{
  std::size_t k = 0;
  for (std::size_t row = 0; row < i; ++row)
    k += COVARIANCE_FEATURES - row;
  return values[k + (j - i)];
}

TEST (LogCovarianceVector, RankOneCovarianceHasTheClosedForm)
{
  // Two points f and -f: the covariance is 2 f f^T, so with epsilon on the
  // diagonal log C = log(eps) I + (log(2 |f|^2 + eps) - log(eps)) u u^T, u = f/|f|.
  Eigen::Matrix<double, 1, COVARIANCE_FEATURES> f;
  for (std::size_t i = 0; i < COVARIANCE_FEATURES; ++i)
    f (static_cast<Eigen::Index> (i)) = 0.1 * static_cast<double> (i + 1);
  pcl::tda::CovarianceFeatures features (2, COVARIANCE_FEATURES);
  features.row (0) = f;
  features.row (1) = -f;
  const double eps = 1e-3;
  float values[COVARIANCE_SIGNATURE_SIZE];
  pcl::tda::logCovarianceVector (features, eps, values);
  const double norm2 = f.squaredNorm();
  const double jump = std::log (2.0 * norm2 + eps) - std::log (eps);
  for (std::size_t i = 0; i < COVARIANCE_FEATURES; ++i)
    for (std::size_t j = i; j < COVARIANCE_FEATURES; ++j) {
      const double u =
          f (static_cast<Eigen::Index> (i)) * f (static_cast<Eigen::Index> (j)) / norm2;
      const double expected =
          (i == j ? std::log (eps) + jump * u : std::sqrt (2.0) * jump * u);
      EXPECT_NEAR (entry (values, i, j), expected, 1e-4) << i << "," << j;
    }
}

TEST (VertexDeathValues, ElderRuleOnFourPoints)
{
  // The square of side 1 (see test_stpp_estimation): v1, v2, v3 die at 1.
  std::vector<pcl::tda::Point3d> points{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
  pcl::tda::FilteredComplex complex;
  pcl::tda::PersistenceResult result;
  ASSERT_TRUE (pcl::tda::levelPersistence (
      points, 1.2, pcl::tda::STPPHomology::BETTI_0, 1u << 30, 1, complex, result));
  const std::vector<double> deaths = pcl::tda::vertexDeathValues (complex, result);
  ASSERT_EQ (deaths.size(), 4u);
  EXPECT_TRUE (std::isinf (deaths[0]));
  for (std::size_t v = 1; v < 4; ++v)
    EXPECT_DOUBLE_EQ (deaths[v], 1.0);
}

/** A coloured, slightly curved patch with its normals and a few stray points. */
void
makePatch (unsigned seed,
           pcl::PointCloud<pcl::PointXYZRGB>::Ptr& cloud,
           pcl::PointCloud<pcl::Normal>::Ptr& normals)
{
  std::mt19937 random (seed);
  std::uniform_real_distribution<float> coordinate (-0.05f, 0.05f);
  cloud.reset (new pcl::PointCloud<pcl::PointXYZRGB>);
  normals.reset (new pcl::PointCloud<pcl::Normal>);
  for (int i = 0; i < 1500; ++i) {
    const float x = coordinate (random), y = coordinate (random);
    pcl::PointXYZRGB p (static_cast<std::uint8_t> (120 + 1000 * x),
                        static_cast<std::uint8_t> (80 + 1000 * y),
                        60);
    p.x = x;
    p.y = y;
    p.z = 3.0f * x * x;
    cloud->push_back (p);
    const Eigen::Vector3f n = Eigen::Vector3f (-6.0f * x, 0.0f, 1.0f).normalized();
    normals->push_back (pcl::Normal (n.x(), n.y(), n.z()));
  }
}

pcl::PointCloud<pcl::tda::CovarianceSignature>
signatureOf (const pcl::PointCloud<pcl::PointXYZRGB>::Ptr& cloud,
             const pcl::PointCloud<pcl::Normal>::Ptr& normals,
             unsigned threads = 1)
{
  Estimation estimation;
  estimation.setInputCloud (cloud);
  estimation.setInputNormals (normals);
  estimation.setNumberOfThreads (threads);
  pcl::PointCloud<pcl::tda::CovarianceSignature> output;
  estimation.compute (output);
  return output;
}

TEST (TopologicalCovarianceEstimation, SameSignatureForAnyInputOrderAndThreadCount)
{
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr cloud;
  pcl::PointCloud<pcl::Normal>::Ptr normals;
  makePatch (1, cloud, normals);
  const auto reference = signatureOf (cloud, normals);
  ASSERT_EQ (reference.size(), 1u);
  std::mt19937 random (3);
  for (int trial = 0; trial < 3; ++trial) {
    std::vector<std::size_t> order (cloud->size());
    std::iota (order.begin(), order.end(), 0);
    std::shuffle (order.begin(), order.end(), random);
    pcl::PointCloud<pcl::PointXYZRGB>::Ptr shuffled (
        new pcl::PointCloud<pcl::PointXYZRGB>);
    pcl::PointCloud<pcl::Normal>::Ptr shuffled_normals (
        new pcl::PointCloud<pcl::Normal>);
    for (const std::size_t i : order) {
      shuffled->push_back ((*cloud)[i]);
      shuffled_normals->push_back ((*normals)[i]);
    }
    for (const unsigned threads : {1u, 2u}) {
      const auto other = signatureOf (shuffled, shuffled_normals, threads);
      ASSERT_EQ (other.size(), 1u);
      EXPECT_EQ (std::memcmp (other[0].histogram,
                              reference[0].histogram,
                              sizeof (reference[0].histogram)),
                 0)
          << "trial " << trial << ", " << threads << " threads";
    }
  }
}

// Through a pcl::Feature reference (as a pipeline holding feature estimators calls
// them): one point, the signature (it was one point per input point, all but the
// first zero); with no index, empty (it wrote through a null pointer).
TEST (TopologicalCovarianceEstimation, OneSignatureThroughTheFeatureBase)
{
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr cloud;
  pcl::PointCloud<pcl::Normal>::Ptr normals;
  makePatch (2, cloud, normals);
  Estimation estimation;
  estimation.setInputCloud (cloud);
  estimation.setInputNormals (normals);
  pcl::Feature<pcl::PointXYZRGB, pcl::tda::CovarianceSignature>& feature = estimation;
  pcl::PointCloud<pcl::tda::CovarianceSignature> output;
  feature.compute (output);
  ASSERT_EQ (output.size(), 1u);
  EXPECT_EQ (output.width, 1u);
  EXPECT_EQ (output.height, 1u);
  const auto reference = signatureOf (cloud, normals);
  ASSERT_EQ (reference.size(), 1u);
  EXPECT_EQ (std::memcmp (output[0].histogram,
                          reference[0].histogram,
                          sizeof (reference[0].histogram)),
             0);

  estimation.setIndices (pcl::make_shared<pcl::Indices>());
  feature.compute (output);
  EXPECT_TRUE (output.empty());
  EXPECT_EQ (estimation.getUsedRadius(), 0.0);
}

TEST (TopologicalCovarianceEstimation, BettiValuesSeeStrayPoints)
{
  // Stray points far from the patch keep their components through every step:
  // their Betti-0 values are 1 where the patch's are mostly below, so the
  // variance of the Betti features grows.
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr cloud;
  pcl::PointCloud<pcl::Normal>::Ptr normals;
  makePatch (2, cloud, normals);
  const auto clean = signatureOf (cloud, normals);
  for (int i = 0; i < 60; ++i) {
    pcl::PointXYZRGB stray = (*cloud)[static_cast<std::size_t> (i)];
    stray.z += 0.02f + 0.001f * static_cast<float> (i);
    stray.x += 0.2f;
    cloud->push_back (stray);
    normals->push_back ((*normals)[static_cast<std::size_t> (i)]);
  }
  const auto stray = signatureOf (cloud, normals);
  ASSERT_EQ (clean.size(), 1u);
  ASSERT_EQ (stray.size(), 1u);
  for (std::size_t s = 9; s < COVARIANCE_FEATURES; ++s)
    EXPECT_GT (entry (stray[0].histogram, s, s), entry (clean[0].histogram, s, s))
        << "step " << s - 9;
}

TEST (TopologicalCovarianceEstimation, PointsWithoutColourHaveConstantColourEntries)
{
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr cloud;
  pcl::PointCloud<pcl::Normal>::Ptr normals;
  makePatch (4, cloud, normals);
  pcl::PointCloud<pcl::PointXYZ>::Ptr positions (new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : *cloud)
    positions->push_back (pcl::PointXYZ (p.x, p.y, p.z));
  pcl::tda::TopologicalCovarianceEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud (positions);
  estimation.setInputNormals (normals);
  pcl::PointCloud<pcl::tda::CovarianceSignature> output;
  estimation.compute (output);
  ASSERT_EQ (output.size(), 1u);
  const float log_eps = static_cast<float> (std::log (
      pcl::tda::TopologicalCovarianceEstimation<pcl::PointXYZ,
                                                pcl::Normal>::REGULARIZATION));
  for (std::size_t i = 3; i < 6; ++i)
    EXPECT_NEAR (entry (output[0].histogram, i, i), log_eps, 1e-3);
}

TEST (TopologicalCovarianceEstimation, FiniteOnAnExactGridInAnyUnit)
{
  // A flat grid of one colour and one normal, in units where positions vary by 1e8
  // and more: the constant features' eigenvalues, the regularization, were computed
  // below 0 and the signature was all NaN from a spacing of 1000 on.
  for (const float spacing : {1.0f, 1e3f, 1e5f, 1e10f}) {
    pcl::PointCloud<pcl::PointXYZRGB>::Ptr cloud (
        new pcl::PointCloud<pcl::PointXYZRGB>);
    pcl::PointCloud<pcl::Normal>::Ptr normals (new pcl::PointCloud<pcl::Normal>);
    for (int i = 0; i < 20; ++i)
      for (int j = 0; j < 20; ++j) {
        pcl::PointXYZRGB point;
        point.r = point.g = point.b = 128;
        point.x = static_cast<float> (i) * spacing;
        point.y = static_cast<float> (j) * spacing;
        point.z = 0.0f;
        cloud->push_back (point);
        normals->push_back (pcl::Normal (0.0f, 0.0f, 1.0f));
      }
    pcl::tda::TopologicalCovarianceEstimation<pcl::PointXYZRGB, pcl::Normal> estimation;
    estimation.setInputCloud (cloud);
    estimation.setInputNormals (normals);
    pcl::PointCloud<pcl::tda::CovarianceSignature> output;
    estimation.compute (output);
    ASSERT_EQ (output.size(), 1u) << spacing;
    for (std::size_t k = 0; k < pcl::tda::COVARIANCE_SIGNATURE_SIZE; ++k)
      ASSERT_TRUE (std::isfinite (output[0].histogram[k])) << spacing << " value " << k;
  }
}

TEST (TopologicalCovarianceEstimation, BadInputGivesAnEmptyOutput)
{
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr cloud;
  pcl::PointCloud<pcl::Normal>::Ptr normals;
  makePatch (5, cloud, normals);
  pcl::PointCloud<pcl::tda::CovarianceSignature> output;

  Estimation no_normals;
  no_normals.setInputCloud (cloud);
  no_normals.compute (output);
  EXPECT_TRUE (output.empty());

  pcl::PointCloud<pcl::Normal>::Ptr fewer (new pcl::PointCloud<pcl::Normal> (*normals));
  fewer->resize (fewer->size() - 1);
  EXPECT_TRUE (signatureOf (cloud, fewer).empty());

  pcl::PointCloud<pcl::Normal>::Ptr nan_normals (new pcl::PointCloud<pcl::Normal>);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  nan_normals->resize (cloud->size(), pcl::Normal (nan, nan, nan));
  EXPECT_TRUE (signatureOf (cloud, nan_normals).empty());

  // NaN normals at some points: those points are left out, the rest described.
  pcl::PointCloud<pcl::Normal>::Ptr some_nan (
      new pcl::PointCloud<pcl::Normal> (*normals));
  for (std::size_t i = 0; i < some_nan->size(); i += 10)
    (*some_nan)[i] = pcl::Normal (nan, nan, nan);
  EXPECT_EQ (signatureOf (cloud, some_nan).size(), 1u);

  Estimation bad_radius;
  bad_radius.setInputCloud (cloud);
  bad_radius.setInputNormals (normals);
  bad_radius.setRadius (-1.0);
  bad_radius.compute (output);
  EXPECT_TRUE (output.empty());

  // Too few points for the spacing the radius comes from: refused by name.
  Estimation few_points;
  few_points.setInputCloud (cloud);
  few_points.setInputNormals (normals);
  few_points.setMaxPoints (1);
  few_points.compute (output);
  EXPECT_TRUE (output.empty());
}

} // namespace
