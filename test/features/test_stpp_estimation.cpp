/** STPPEstimation: the thesis' raw pairing vector on hand-made clouds against
 * hand-computed values (Fig 6.2 layout), the signature on clouds of known topology
 * (a ring has long-lived 1-cycles, a disc none), invariance to input order, thread
 * count and scale, and bad input. */
#include <pcl/common/io.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/features/stpp_estimation.h>
#include <pcl/tda/generators/shapes.h>
#include <pcl/tda/search/point_spacing.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Estimation = pcl::tda::STPPEstimation<pcl::PointXYZ, pcl::tda::STPPSignature>;
using pcl::tda::STPP_NEGATIVE;
using pcl::tda::STPP_UNPAIRED;
using pcl::tda::STPPHomology;

Cloud::Ptr
squareCorners ()
{
  Cloud::Ptr cloud (new Cloud);
  // Input order differs from the canonical (x, y, z) order on purpose.
  cloud->push_back ({1.0f, 1.0f, 0.0f});
  cloud->push_back ({0.0f, 0.0f, 0.0f});
  cloud->push_back ({1.0f, 0.0f, 0.0f});
  cloud->push_back ({0.0f, 1.0f, 0.0f});
  return cloud;
}

/** Points of the flat annulus inner <= |p| <= outer (inner 0: a disc), on a
 * jittered grid of cell h. */
Cloud::Ptr
annulus (float inner, float outer, float h, unsigned seed)
{
  std::mt19937 random (seed);
  std::uniform_real_distribution<float> jitter (-0.3f * h, 0.3f * h);
  Cloud::Ptr cloud (new Cloud);
  for (float x = -outer; x <= outer; x += h)
    for (float y = -outer; y <= outer; y += h) {
      const float px = x + jitter (random), py = y + jitter (random);
      const float r = std::hypot (px, py);
      if (r >= inner && r <= outer)
        cloud->push_back ({px, py, 0.0f});
    }
  return cloud;
}

pcl::tda::STPPSignature
signatureOf (const Cloud::Ptr& cloud,
             unsigned threads = 1,
             STPPHomology homology = STPPHomology::BETTI_0_1)
{
  Estimation stpp;
  stpp.setInputCloud (cloud);
  stpp.setNumberOfThreads (threads);
  stpp.setHomology (homology);
  pcl::PointCloud<pcl::tda::STPPSignature> output;
  stpp.compute (output);
  EXPECT_EQ (output.size(), 1u);
  return output.empty() ? pcl::tda::STPPSignature() : output[0];
}

float
longLivedCycles (const pcl::tda::STPPSignature& signature, std::size_t level)
{
  return signature.histogram[pcl::tda::STPP_BETTI1_OFFSET +
                             level * pcl::tda::STPP_BETTI1_PER_LEVEL +
                             pcl::tda::STPP_CURVE_SAMPLES + 1];
}

bool
sameSignature (const pcl::tda::STPPSignature& a, const pcl::tda::STPPSignature& b)
{
  return std::memcmp (a.histogram, b.histogram, sizeof (a.histogram)) == 0;
}

TEST (STPPEstimation, PairingVectorOfFourPointsWithoutDiagonals)
{
  // Canonical order: v0 (0,0), v1 (0,1), v2 (1,0), v3 (1,1). At r = 1.2 the edges
  // are the four sides, all of length 1, ordered by their vertices: e0 = v0v1,
  // e1 = v0v2, e2 = v1v3, e3 = v2v3. e0, e1, e2 kill v1, v2, v3 (elder rule); e3
  // closes the square: a 1-cycle that no triangle fills.
  Estimation stpp;
  stpp.setInputCloud (squareCorners());
  stpp.setRadius (1.2);
  pcl::PointCloud<pcl::tda::STPPSignature> output;
  stpp.compute (output);
  ASSERT_EQ (output.size(), 1u);
  const std::vector<std::int64_t> expected{STPP_UNPAIRED,
                                           0,
                                           1,
                                           2,
                                           STPP_NEGATIVE,
                                           STPP_NEGATIVE,
                                           STPP_NEGATIVE,
                                           STPP_UNPAIRED};
  EXPECT_EQ (stpp.getPairingVector(), expected);
}

TEST (STPPEstimation, PairingVectorOfTheFullComplexOnFourPoints)
{
  // At r = 1.5 the diagonals e4 = v0v3 and e5 = v1v2 (length sqrt 2) join. The
  // triangles all have value sqrt 2 and are ordered by their edges, youngest
  // first: t0 = (e4, e2, e0), t1 = (e4, e3, e1), t2 = (e5, e1, e0),
  // t3 = (e5, e3, e2). The reduction pairs e4-t0, then (t1 + t0 has youngest
  // edge e3) e3-t1, then e5-t2; t3 closes the 2-sphere.
  const std::vector<std::int64_t> vertices{STPP_UNPAIRED, 0, 1, 2};
  const std::vector<std::int64_t> edges{
      STPP_NEGATIVE, STPP_NEGATIVE, STPP_NEGATIVE, 1, 0, 2};
  for (const STPPHomology homology :
       {STPPHomology::BETTI_0, STPPHomology::BETTI_1, STPPHomology::BETTI_0_1}) {
    Estimation stpp;
    stpp.setInputCloud (squareCorners());
    stpp.setRadius (1.5);
    stpp.setHomology (homology);
    pcl::PointCloud<pcl::tda::STPPSignature> output;
    stpp.compute (output);
    ASSERT_EQ (output.size(), 1u);
    std::vector<std::int64_t> expected;
    if (homology != STPPHomology::BETTI_1)
      expected = vertices;
    if (homology != STPPHomology::BETTI_0)
      expected.insert (expected.end(), edges.begin(), edges.end());
    EXPECT_EQ (stpp.getPairingVector(), expected);
  }
}

TEST (STPPEstimation, BettiCurvesOfFourPoints)
{
  // Level 0 at r = 1.2: all four points apart below 1, one component from 1 on;
  // the square's 1-cycle is born at 1 and never dies.
  Estimation stpp;
  stpp.setInputCloud (squareCorners());
  stpp.setRadius (1.2);
  pcl::PointCloud<pcl::tda::STPPSignature> output;
  stpp.compute (output);
  ASSERT_EQ (output.size(), 1u);
  const float* h0 = output[0].histogram + pcl::tda::STPP_BETTI0_OFFSET;
  const float* h1 = output[0].histogram + pcl::tda::STPP_BETTI1_OFFSET;
  for (std::size_t j = 0; j < pcl::tda::STPP_CURVE_SAMPLES; ++j) {
    const double t = 1.2 * static_cast<double> (j + 1) / pcl::tda::STPP_CURVE_SAMPLES;
    EXPECT_FLOAT_EQ (h0[j], t < 1.0 ? 1.0f : 0.25f) << "t = " << t;
    EXPECT_FLOAT_EQ (h1[j], t < 1.0 ? 0.0f : 0.25f) << "t = " << t;
  }
  EXPECT_FLOAT_EQ (h0[pcl::tda::STPP_CURVE_SAMPLES], 1.0f);     // log2(1 + 1)
  EXPECT_FLOAT_EQ (h1[pcl::tda::STPP_CURVE_SAMPLES], 1.0f);     // 1 essential
  EXPECT_FLOAT_EQ (h1[pcl::tda::STPP_CURVE_SAMPLES + 1], 0.0f); // born at 1 > r/2
  // Size: twice the RMS distance to the centre, sqrt(0.5) each.
  EXPECT_NEAR (stpp.getCloudSize(), 2.0 * std::sqrt (0.5), 1e-9);
  EXPECT_FLOAT_EQ (output[0].histogram[pcl::tda::STPP_SIZE_OFFSET],
                   static_cast<float> (std::log10 (2.0 * std::sqrt (0.5))));
}

TEST (STPPEstimation, RingHasLongLivedCyclesAndDiscNone)
{
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const auto ring = signatureOf (annulus (0.5f, 1.0f, 0.02f, seed));
    const auto disc = signatureOf (annulus (0.0f, 1.0f, 0.02f, seed));
    // Level 0 is a random sample of the cloud, whose gaps may live long; the
    // coarse copies have none. At level 3 (r about 0.8) the ring's hole is filled.
    for (std::size_t level = 1; level < pcl::tda::STPP_LEVELS; ++level)
      EXPECT_EQ (longLivedCycles (disc, level), 0.0f)
          << "seed " << seed << " level " << level;
    for (std::size_t level = 1; level + 1 < pcl::tda::STPP_LEVELS; ++level)
      EXPECT_FLOAT_EQ (longLivedCycles (ring, level), 1.0f)
          << "seed " << seed << " level " << level;
  }
}

TEST (STPPEstimation, TorusHasTwoLongLivedCyclesAtTheCoarseLevels)
{
  pcl::tda::TorusParameters parameters;
  parameters.num_points = 6000;
  parameters.seed = 3;
  const pcl::tda::SyntheticShape torus = pcl::tda::generateTorus (parameters);
  Cloud::Ptr cloud (new Cloud);
  pcl::copyPointCloud (*torus.cloud, *cloud);
  const auto signature = signatureOf (cloud);
  // The size of this torus is about 2.3 and its tube radius 0.4: levels 1 and 2
  // (r about 0.29 and 0.57) see the surface whole with both loops open (log2(1 +
  // 2)); at level 3 (r about 1.15) the tube's loop is filled.
  EXPECT_FLOAT_EQ (longLivedCycles (signature, 1), static_cast<float> (std::log2 (3)));
  EXPECT_FLOAT_EQ (longLivedCycles (signature, 2), static_cast<float> (std::log2 (3)));
}

TEST (STPPEstimation, SameSignatureForAnyInputOrderAndThreadCount)
{
  const Cloud::Ptr cloud = annulus (0.3f, 1.0f, 0.015f, 11);
  const auto reference = signatureOf (cloud, 1);
  Estimation stpp;
  stpp.setInputCloud (cloud);
  pcl::PointCloud<pcl::tda::STPPSignature> output;
  stpp.compute (output);
  const std::vector<std::int64_t> pairing = stpp.getPairingVector();
  std::mt19937 random (5);
  for (int trial = 0; trial < 4; ++trial) {
    Cloud::Ptr shuffled (new Cloud (*cloud));
    std::shuffle (shuffled->begin(), shuffled->end(), random);
    for (const unsigned threads : {1u, 2u, 4u}) {
      EXPECT_TRUE (sameSignature (signatureOf (shuffled, threads), reference))
          << "trial " << trial << ", " << threads << " threads";
      Estimation other;
      other.setInputCloud (shuffled);
      other.setNumberOfThreads (threads);
      other.compute (output);
      EXPECT_EQ (other.getPairingVector(), pairing);
    }
  }
}

TEST (STPPEstimation, ScaledCopyDiffersOnlyInTheSizeValue)
{
  // Scaling by 2 is exact in floating point, so every length doubles exactly.
  const Cloud::Ptr cloud = annulus (0.4f, 1.0f, 0.02f, 2);
  Cloud::Ptr scaled (new Cloud (*cloud));
  for (auto& p : *scaled)
    p.getVector3fMap() *= 2.0f;
  const auto small = signatureOf (cloud);
  const auto large = signatureOf (scaled);
  for (std::size_t i = 0; i < pcl::tda::STPP_SIZE_OFFSET; ++i)
    EXPECT_EQ (small.histogram[i], large.histogram[i]) << "value " << i;
  EXPECT_NEAR (large.histogram[pcl::tda::STPP_SIZE_OFFSET] -
                   small.histogram[pcl::tda::STPP_SIZE_OFFSET],
               std::log10 (2.0),
               1e-6);
  Estimation invariant;
  invariant.setInputCloud (scaled);
  invariant.setScaleInvariant (true);
  pcl::PointCloud<pcl::tda::STPPSignature> output;
  invariant.compute (output);
  ASSERT_EQ (output.size(), 1u);
  EXPECT_EQ (output[0].histogram[pcl::tda::STPP_SIZE_OFFSET], 0.0f);
}

TEST (STPPEstimation, CoarseLevelsBarelyDependOnThePointCount)
{
  // Four times the points: the coarse copies have the same spacing, so the coarse
  // levels' curves move little and their counts not at all.
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const auto sparse = signatureOf (annulus (0.3f, 1.0f, 0.02f, seed));
    const auto dense = signatureOf (annulus (0.3f, 1.0f, 0.01f, seed));
    for (std::size_t level = 1; level < pcl::tda::STPP_LEVELS; ++level) {
      const std::size_t betti0 =
          pcl::tda::STPP_BETTI0_OFFSET + level * pcl::tda::STPP_BETTI0_PER_LEVEL;
      const std::size_t betti1 =
          pcl::tda::STPP_BETTI1_OFFSET + level * pcl::tda::STPP_BETTI1_PER_LEVEL;
      for (std::size_t j = 0; j < pcl::tda::STPP_CURVE_SAMPLES; ++j) {
        EXPECT_NEAR (sparse.histogram[betti0 + j], dense.histogram[betti0 + j], 0.15)
            << "seed " << seed << " level " << level << " sample " << j;
        EXPECT_NEAR (sparse.histogram[betti1 + j], dense.histogram[betti1 + j], 0.05)
            << "seed " << seed << " level " << level << " sample " << j;
      }
      // At level 3 the coarse copy's spacing (about 0.25) is close to the hole's
      // radius (0.3): whether the hole lives long there is not settled.
      if (level + 1 == pcl::tda::STPP_LEVELS)
        continue;
      for (const std::size_t count : {betti0 + pcl::tda::STPP_CURVE_SAMPLES,
                                      betti1 + pcl::tda::STPP_CURVE_SAMPLES,
                                      betti1 + pcl::tda::STPP_CURVE_SAMPLES + 1})
        EXPECT_EQ (sparse.histogram[count], dense.histogram[count])
            << "seed " << seed << " level " << level << " value " << count;
    }
    // The sublevel sets are taken on level 1's coarse copy: their profiles move
    // little, their ranges and pieces not at all.
    for (std::size_t k = 0; k < pcl::tda::STPP_SUBLEVEL_FUNCTIONS; ++k) {
      const std::size_t first =
          pcl::tda::STPP_SUBLEVEL_OFFSET + k * pcl::tda::STPP_SUBLEVEL_PER_FUNCTION;
      for (std::size_t j = 0; j < pcl::tda::STPP_CURVE_SAMPLES; ++j) {
        EXPECT_NEAR (sparse.histogram[first + j], dense.histogram[first + j], 0.05)
            << "seed " << seed << " function " << k << " sample " << j;
        EXPECT_EQ (sparse.histogram[first + pcl::tda::STPP_CURVE_SAMPLES + j],
                   dense.histogram[first + pcl::tda::STPP_CURVE_SAMPLES + j])
            << "seed " << seed << " function " << k << " sample " << j;
      }
      EXPECT_NEAR (sparse.histogram[first + 2 * pcl::tda::STPP_CURVE_SAMPLES],
                   dense.histogram[first + 2 * pcl::tda::STPP_CURVE_SAMPLES],
                   0.03)
          << "seed " << seed << " function " << k;
    }
  }
}

TEST (STPPEstimation, HomologyPartsMatchTheFullSignature)
{
  const Cloud::Ptr cloud = annulus (0.3f, 1.0f, 0.02f, 8);
  const auto both = signatureOf (cloud, 1, STPPHomology::BETTI_0_1);
  const auto betti0 = signatureOf (cloud, 1, STPPHomology::BETTI_0);
  const auto betti1 = signatureOf (cloud, 1, STPPHomology::BETTI_1);
  for (std::size_t i = 0; i < pcl::tda::STPP_SIGNATURE_SIZE; ++i) {
    const bool in_betti0 = i < pcl::tda::STPP_BETTI1_OFFSET;
    const bool is_size = i == pcl::tda::STPP_SIZE_OFFSET;
    EXPECT_EQ (betti0.histogram[i], in_betti0 || is_size ? both.histogram[i] : 0.0f);
    EXPECT_EQ (betti1.histogram[i], !in_betti0 ? both.histogram[i] : 0.0f);
  }
  EXPECT_EQ (pcl::tda::stppSignatureValues (both, STPPHomology::BETTI_0).size(),
             pcl::tda::STPP_BETTI1_OFFSET + 1);
  EXPECT_EQ (pcl::tda::stppSignatureValues (both, STPPHomology::BETTI_1).size(),
             pcl::tda::STPP_SIZE_OFFSET - pcl::tda::STPP_BETTI1_OFFSET + 1);
}

// Through a pcl::Feature reference (as a pipeline holding feature estimators calls
// them): one point, the signature, as with the class itself (it was one point per
// input point, all but the first zero).
TEST (STPPEstimation, OneSignatureThroughTheFeatureBase)
{
  const Cloud::Ptr cloud = annulus (0.3f, 1.0f, 0.015f, 11);
  Estimation stpp;
  stpp.setInputCloud (cloud);
  pcl::Feature<pcl::PointXYZ, pcl::tda::STPPSignature>& feature = stpp;
  pcl::PointCloud<pcl::tda::STPPSignature> output;
  feature.compute (output);
  ASSERT_EQ (output.size(), 1u);
  EXPECT_EQ (output.width, 1u);
  EXPECT_EQ (output.height, 1u);
  EXPECT_TRUE (sameSignature (output[0], signatureOf (cloud, 1)));
}

TEST (STPPEstimation, SignatureIsARegisteredPointType)
{
  const auto fields = pcl::getFields<pcl::tda::STPPSignature>();
  ASSERT_EQ (fields.size(), 1u);
  EXPECT_EQ (fields[0].name, "stpp");
  EXPECT_EQ (fields[0].count, pcl::tda::STPP_SIGNATURE_SIZE);
  EXPECT_EQ (pcl::tda::STPPSignature::descriptorSize(),
             static_cast<int> (pcl::tda::STPP_SIGNATURE_SIZE));
}

TEST (STPPEstimation, BadInputGivesAnEmptyOutput)
{
  pcl::PointCloud<pcl::tda::STPPSignature> output;
  Estimation stpp;
  stpp.compute (output); // no input
  EXPECT_TRUE (output.empty());

  stpp.setInputCloud (Cloud::Ptr (new Cloud));
  stpp.compute (output);
  EXPECT_TRUE (output.empty());

  Cloud::Ptr nans (new Cloud);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < 20; ++i)
    nans->push_back ({nan, nan, nan});
  stpp.setInputCloud (nans);
  stpp.compute (output);
  EXPECT_TRUE (output.empty());

  Cloud::Ptr same (new Cloud);
  for (int i = 0; i < 20; ++i)
    same->push_back ({1.0f, 2.0f, 3.0f});
  stpp.setInputCloud (same);
  stpp.compute (output);
  EXPECT_TRUE (output.empty());
  EXPECT_TRUE (stpp.getPairingVector().empty());

  stpp.setInputCloud (annulus (0.3f, 1.0f, 0.05f, 1));
  for (const double radius : {-1.0,
                              std::numeric_limits<double>::infinity(),
                              std::numeric_limits<double>::quiet_NaN()}) {
    stpp.setRadius (radius);
    stpp.compute (output);
    EXPECT_TRUE (output.empty()) << "radius " << radius;
  }
  stpp.setRadius (0.0);
  stpp.setMemoryLimit (1000);
  stpp.compute (output);
  EXPECT_TRUE (output.empty());
  EXPECT_EQ (stpp.getCloudSize(), 0.0); // a refused run leaves no result
  stpp.setMemoryLimit (pcl::tda::defaultMemoryLimit());

  // Too few points for the spacing the radius comes from: refused by name.
  stpp.setMaxPoints (pcl::tda::SURFACE_SPACING_NEIGHBORS);
  stpp.compute (output);
  EXPECT_TRUE (output.empty());
  stpp.setRadius (0.2); // a given radius needs no spacing
  stpp.compute (output);
  EXPECT_EQ (output.size(), 1u);

  stpp.setHomology (static_cast<pcl::tda::STPPHomology> (7)); // no such homology
  stpp.compute (output);
  EXPECT_TRUE (output.empty());
}

} // namespace
