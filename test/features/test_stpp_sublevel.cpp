/** The sublevel-set values of the STPP signature: shapeFunctions() on a cloud along
 * a line, sublevelValues() on hand-made paths against hand-computed values, and the
 * signature's sublevel values on a cylinder and a dumbbell against their closed
 * forms. */
#include <pcl/tda/features/stpp_estimation.h>
#include <pcl/tda/features/stpp_sublevel.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using pcl::tda::STPP_CURVE_SAMPLES;
using pcl::tda::STPP_SUBLEVEL_PER_FUNCTION;

constexpr double PI = 3.14159265358979323846;

/** The curve sample t_j of sublevelValues() over [low, high]. */
double
sample (double low, double high, std::size_t j)
{
  return low + (high - low) * (static_cast<double> (j) + 0.5) /
                   static_cast<double> (STPP_CURVE_SAMPLES);
}

/** Uniform random points on the surface of a sphere. */
void
addSphere (Cloud& cloud,
           const Eigen::Vector3f& centre,
           float radius,
           int points,
           std::mt19937& random)
{
  std::normal_distribution<float> normal;
  for (int i = 0; i < points; ++i) {
    const Eigen::Vector3f d (normal (random), normal (random), normal (random));
    const Eigen::Vector3f p = centre + radius * d.normalized();
    cloud.push_back ({p.x(), p.y(), p.z()});
  }
}

/** The sublevel-set values of \a cloud's STPP signature, with its size. */
std::vector<float>
sublevelPart (const Cloud::Ptr& cloud, double& size)
{
  pcl::tda::STPPEstimation<pcl::PointXYZ, pcl::tda::STPPSignature> stpp;
  stpp.setInputCloud (cloud);
  pcl::PointCloud<pcl::tda::STPPSignature> output;
  stpp.compute (output);
  EXPECT_EQ (output.size(), 1u);
  size = stpp.getCloudSize();
  if (output.empty())
    return {};
  const float* begin = output[0].histogram + pcl::tda::STPP_SUBLEVEL_OFFSET;
  return {begin,
          begin + pcl::tda::STPP_SUBLEVEL_FUNCTIONS * STPP_SUBLEVEL_PER_FUNCTION};
}

TEST (STPPSublevel, ShapeFunctionsOfPointsOnALine)
{
  // Positions 0, 1, 2, 3, 10 along u: centroid at 3.2, a long tail on the far side,
  // so the principal axis points along +u whichever way the points are listed.
  const Eigen::Vector3d u = Eigen::Vector3d (1.0, 2.0, 2.0) / 3.0;
  const std::vector<double> positions{0.0, 1.0, 2.0, 3.0, 10.0};
  for (const double direction : {1.0, -1.0}) {
    std::vector<pcl::tda::Point3d> points;
    for (const double s : positions) {
      const Eigen::Vector3d p = Eigen::Vector3d (5.0, -1.0, 2.0) + direction * s * u;
      points.push_back ({p.x(), p.y(), p.z()});
    }
    const double size = 2.0;
    const auto functions = pcl::tda::shapeFunctions (points, size);
    for (std::size_t i = 0; i < positions.size(); ++i) {
      const double along = direction * (positions[i] - 3.2);
      EXPECT_NEAR (functions[0][i], std::abs (along) / size, 1e-12);
      EXPECT_NEAR (functions[1][i], direction * along / size, 1e-12)
          << "direction " << direction << " point " << i;
      EXPECT_NEAR (functions[2][i], 0.0, 1e-12);
      EXPECT_NEAR (functions[3][i], 0.0, 1e-12);
    }
  }
}

TEST (STPPSublevel, SublevelValuesOfAPathWithTwoValleys)
{
  // The path v0 - v1 - v2 - v3 - v4 with f = 0, 2, 1, 2, 0 (range [0, 2]; edge
  // values are the builder's and play no part). Below 1: v0 and v4 apart; from 1
  // on v2 too, three components; from 2 on all joined.
  const pcl::tda::FilteredComplex path = pcl::tda::FilteredComplex::fromLists (
      5, {{0, 1, 1.0}, {1, 2, 1.0}, {2, 3, 1.0}, {3, 4, 1.0}}, {});
  const std::vector<double> f{0.0, 2.0, 1.0, 2.0, 0.0};
  std::vector<float> values (STPP_SUBLEVEL_PER_FUNCTION);
  pcl::tda::sublevelValues (path, f, values.data());
  for (std::size_t j = 0; j < STPP_CURVE_SAMPLES; ++j) {
    const bool valley = sample (0.0, 2.0, j) >= 1.0;
    EXPECT_FLOAT_EQ (values[j], valley ? 0.6f : 0.4f) << "sample " << j;
    EXPECT_FLOAT_EQ (values[STPP_CURVE_SAMPLES + j],
                     static_cast<float> (std::log2 (valley ? 4.0 : 3.0)))
        << "sample " << j;
  }
  EXPECT_FLOAT_EQ (values[2 * STPP_CURVE_SAMPLES], 2.0f);
}

TEST (STPPSublevel, APieceThatLastsLessThanAStepIsNotCounted)
{
  // The path with f = 0, 1, 0.9, 1, 0 (range [0, 1], one step 0.125): v2 is born
  // at 0.9 and joins the others at 1, so at t_7 = 0.9375 it is below t but lives
  // 0.1: two pieces are counted there, v0's and v4's.
  const pcl::tda::FilteredComplex path = pcl::tda::FilteredComplex::fromLists (
      5, {{0, 1, 1.0}, {1, 2, 1.0}, {2, 3, 1.0}, {3, 4, 1.0}}, {});
  std::vector<float> values (STPP_SUBLEVEL_PER_FUNCTION);
  pcl::tda::sublevelValues (path, {0.0, 1.0, 0.9, 1.0, 0.0}, values.data());
  EXPECT_FLOAT_EQ (values[STPP_CURVE_SAMPLES - 1], 0.6f);
  EXPECT_FLOAT_EQ (values[2 * STPP_CURVE_SAMPLES - 1],
                   static_cast<float> (std::log2 (3.0)));
}

TEST (STPPSublevel, CylinderHasALinearProfileInOnePiece)
{
  // An open tube of radius 0.5 and length 4 along x, sampled uniformly: its area
  // below x = t grows linearly, and at a distance t from the centre it is the band
  // |x| <= sqrt(t^2 - 0.25). Every sublevel set is one piece.
  for (unsigned seed = 1; seed <= 3; ++seed) {
    std::mt19937 random (seed);
    std::uniform_real_distribution<float> along (-2.0f, 2.0f), angle (0.0f, 2.0f * PI);
    Cloud::Ptr cloud (new Cloud);
    for (int i = 0; i < 20000; ++i) {
      const float a = angle (random);
      cloud->push_back ({along (random), 0.5f * std::cos (a), 0.5f * std::sin (a)});
    }
    double size = 0.0;
    const std::vector<float> part = sublevelPart (cloud, size);
    ASSERT_FALSE (part.empty());
    const float* radial = part.data();
    const float* axis = part.data() + STPP_SUBLEVEL_PER_FUNCTION;
    const double low = 0.5 / size, high = std::sqrt (4.25) / size;
    for (std::size_t j = 0; j < STPP_CURVE_SAMPLES; ++j) {
      EXPECT_NEAR (axis[j], (static_cast<double> (j) + 0.5) / 8.0, 0.03)
          << "seed " << seed << " sample " << j;
      const double t = sample (low, high, j) * size;
      EXPECT_NEAR (radial[j], std::sqrt (t * t - 0.25) / 2.0, 0.04)
          << "seed " << seed << " sample " << j;
      for (std::size_t k = 0; k < pcl::tda::STPP_SUBLEVEL_FUNCTIONS; ++k)
        EXPECT_FLOAT_EQ (part[k * STPP_SUBLEVEL_PER_FUNCTION + STPP_CURVE_SAMPLES + j],
                         1.0f)
            << "seed " << seed << " function " << k << " sample " << j;
    }
    EXPECT_NEAR (axis[2 * STPP_CURVE_SAMPLES], 4.0 / size, 0.05) << "seed " << seed;
    EXPECT_NEAR (radial[2 * STPP_CURVE_SAMPLES], high - low, 0.05) << "seed " << seed;
  }
}

TEST (STPPSublevel, DumbbellIsTwoPiecesFromTheFarSphereOn)
{
  // Two spheres of radius 0.5 at x = -2 and x = 2, far apart at every level's
  // radius. Along x (range [-2.5, 2.5]) a sphere's area below a plane grows
  // linearly over its diameter: one piece until the second sphere is reached, two
  // after. Both spheres are at distances 1.5 to 2.5 from the centre, so the
  // sublevel sets of the distance are two pieces (once both have points).
  for (unsigned seed = 1; seed <= 3; ++seed) {
    std::mt19937 random (seed);
    Cloud::Ptr cloud (new Cloud);
    addSphere (*cloud, {-2.0f, 0.0f, 0.0f}, 0.5f, 8000, random);
    addSphere (*cloud, {2.0f, 0.0f, 0.0f}, 0.5f, 8000, random);
    double size = 0.0;
    const std::vector<float> part = sublevelPart (cloud, size);
    ASSERT_FALSE (part.empty());
    const float* radial = part.data();
    const float* axis = part.data() + STPP_SUBLEVEL_PER_FUNCTION;
    const auto below = [] (double t) {
      const double near_sphere = std::clamp (t + 2.5, 0.0, 1.0);
      const double far_sphere = std::clamp (t - 1.5, 0.0, 1.0);
      return (near_sphere + far_sphere) / 2.0;
    };
    for (std::size_t j = 0; j < STPP_CURVE_SAMPLES; ++j) {
      const double t = sample (-2.5, 2.5, j);
      EXPECT_NEAR (axis[j], below (t), 0.04) << "seed " << seed << " sample " << j;
      if (t < 1.4 || t > 1.6) {
        EXPECT_FLOAT_EQ (axis[STPP_CURVE_SAMPLES + j],
                         static_cast<float> (std::log2 (t < 1.4 ? 2.0 : 3.0)))
            << "seed " << seed << " sample " << j;
      }
      if (j >= 2) {
        EXPECT_FLOAT_EQ (radial[STPP_CURVE_SAMPLES + j],
                         static_cast<float> (std::log2 (3.0)))
            << "seed " << seed << " sample " << j;
      }
    }
    EXPECT_NEAR (axis[2 * STPP_CURVE_SAMPLES], 5.0 / size, 0.03) << "seed " << seed;
  }
}

} // namespace
