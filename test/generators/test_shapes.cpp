// Tests of the shapes with known topology: determinism, exact counts, distances to
// the surface, and the Betti numbers Ripser finds around the suggested radius.

#include <pcl/tda/common/diagram_io.h>
#include <pcl/tda/generators/shapes.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include "generators/generator_test_utils.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

using pcl::tda::CircleParameters;
using pcl::tda::SphereParameters;
using pcl::tda::SyntheticShape;
using pcl::tda::TorusParameters;
using pcl::tda::test::identical;
using pcl::tda::test::TemporaryFolder;
using Cloud = pcl::PointCloud<pcl::PointXYZRGBL>;

namespace {

double
distanceToCircle (const pcl::PointXYZRGBL& p, double radius)
{
  return std::hypot (std::hypot (p.x, p.y) - radius, p.z);
}

double
distanceToTorus (const pcl::PointXYZRGBL& p, double major, double minor)
{
  return std::abs (std::hypot (std::hypot (p.x, p.y) - major, p.z) - minor);
}

double
distanceToSphere (const pcl::PointXYZRGBL& p, double radius)
{
  return std::abs (p.getVector3fMap().cast<double>().norm() - radius);
}

/** Largest and mean distance of the cloud to a surface. */
std::pair<double, double>
distanceStatistics (const Cloud& cloud,
                    const std::function<double (const pcl::PointXYZRGBL&)>& distance)
{
  double largest = 0.0, sum = 0.0;
  for (const auto& p : cloud) {
    const double d = distance (p);
    largest = std::max (largest, d);
    sum += d;
  }
  return {largest, sum / cloud.size()};
}

/** One of each shape with its distance function, for parameterised checks. */
struct ShapeCase {
  std::string name;
  std::function<SyntheticShape (float noise, std::uint64_t seed)> generate;
  std::function<double (const pcl::PointXYZRGBL&)> distance;
  std::size_t num_points;
};

std::vector<ShapeCase>
shapeCases ()
{
  return {{"circle",
           [] (float noise, std::uint64_t seed) {
             CircleParameters p;
             p.noise_sigma = noise;
             p.seed = seed;
             return pcl::tda::generateCircle (p);
           },
           [] (const pcl::PointXYZRGBL& p) {
             return distanceToCircle (p, CircleParameters().radius);
           },
           CircleParameters().num_points},
          {"torus",
           [] (float noise, std::uint64_t seed) {
             TorusParameters p;
             p.noise_sigma = noise;
             p.seed = seed;
             return pcl::tda::generateTorus (p);
           },
           [] (const pcl::PointXYZRGBL& p) {
             return distanceToTorus (
                 p, TorusParameters().major_radius, TorusParameters().minor_radius);
           },
           TorusParameters().num_points},
          {"sphere",
           [] (float noise, std::uint64_t seed) {
             SphereParameters p;
             p.noise_sigma = noise;
             p.seed = seed;
             return pcl::tda::generateSphere (p);
           },
           [] (const pcl::PointXYZRGBL& p) {
             return distanceToSphere (p, SphereParameters().radius);
           },
           SphereParameters().num_points}};
}

/** Runs Ripser on the cloud up to threshold and returns its intervals. */
pcl::tda::PersistenceDiagram
runRipser (const Cloud& cloud, double threshold, const std::string& folder)
{
  const std::string input = folder + "/points.txt";
  const std::string output = folder + "/ripser.txt";
  {
    std::ofstream file (input);
    file.precision (9);
    for (const auto& p : cloud)
      file << p.x << ' ' << p.y << ' ' << p.z << '\n';
  }
  const std::string command = std::string (RIPSER_EXECUTABLE) +
                              " --format point-cloud --dim 1 --threshold " +
                              std::to_string (threshold) + " " + input + " > " + output;
  EXPECT_EQ (0, std::system (command.c_str())) << command;
  return pcl::tda::loadDiagram (output);
}

int
bettiAt (const pcl::tda::PersistenceDiagram& intervals, int dim, double r)
{
  return static_cast<int> (std::count_if (
      intervals.begin(), intervals.end(), [&] (const pcl::tda::PersistenceInterval& i) {
        return i.dimension == dim && i.birth <= r && r < i.death;
      }));
}

} // namespace

TEST (SyntheticShapes, SameSeedGivesIdenticalCloudsAndOtherSeedsDiffer)
{
  for (const ShapeCase& shape : shapeCases()) {
    SCOPED_TRACE (shape.name);
    const SyntheticShape a = shape.generate (0.01f, 42);
    const SyntheticShape b = shape.generate (0.01f, 42);
    const SyntheticShape c = shape.generate (0.01f, 43);
    EXPECT_TRUE (identical (*a.cloud, *b.cloud));
    EXPECT_EQ (a.suggested_radius, b.suggested_radius);
    EXPECT_FALSE (identical (*a.cloud, *c.cloud));
  }
}

TEST (SyntheticShapes, ExactPointCountsAndGroundTruth)
{
  const std::map<std::string, std::pair<int, int>> betti = {
      {"circle", {1, 1}}, {"torus", {1, 2}}, {"sphere", {1, 0}}};
  for (const ShapeCase& shape : shapeCases()) {
    SCOPED_TRACE (shape.name);
    const SyntheticShape s = shape.generate (0.01f, 1);
    EXPECT_EQ (shape.num_points, s.cloud->size());
    EXPECT_EQ (s.cloud->size(), std::size_t (s.cloud->width) * s.cloud->height);
    EXPECT_EQ (betti.at (shape.name).first, s.beta0);
    EXPECT_EQ (betti.at (shape.name).second, s.beta1);
    EXPECT_GT (s.suggested_radius, 0.0f);
    for (const auto& p : *s.cloud)
      ASSERT_EQ (pcl::tda::SHAPE_LABEL, p.label);
  }
  CircleParameters circle;
  circle.num_points = 777;
  EXPECT_EQ (777u, pcl::tda::generateCircle (circle).cloud->size());
  TorusParameters torus;
  torus.num_points = 3001;
  EXPECT_EQ (3001u, pcl::tda::generateTorus (torus).cloud->size());
  SphereParameters sphere;
  sphere.num_points = 1201;
  EXPECT_EQ (1201u, pcl::tda::generateSphere (sphere).cloud->size());
}

TEST (SyntheticShapes, PointsLieOnTheSurfaceWithoutNoise)
{
  for (const ShapeCase& shape : shapeCases()) {
    SCOPED_TRACE (shape.name);
    const SyntheticShape s = shape.generate (0.0f, 5);
    EXPECT_LE (distanceStatistics (*s.cloud, shape.distance).first, 1e-5);
  }
}

TEST (SyntheticShapes, NoisyPointsStayWithinFourSigma)
{
  const float sigma = 0.01f;
  for (const ShapeCase& shape : shapeCases()) {
    SCOPED_TRACE (shape.name);
    const auto [largest, mean] =
        distanceStatistics (*shape.generate (sigma, 9).cloud, shape.distance);
    EXPECT_LE (largest, 4.0 * sigma + 1e-5);
    EXPECT_GT (largest, 2.0 * sigma); // the noise is really there
    EXPECT_GT (mean, 0.4 * sigma);
    EXPECT_LT (mean, 2.0 * sigma);
  }
}

TEST (SyntheticShapes, SuggestedRadiusScalesWithSpacingAndNoise)
{
  CircleParameters sparse, dense, noisy;
  sparse.num_points = 500;
  dense.num_points = 2000;
  noisy.noise_sigma = 0.03f;
  const float r_sparse = pcl::tda::generateCircle (sparse).suggested_radius;
  const float r_dense = pcl::tda::generateCircle (dense).suggested_radius;
  const float r_default =
      pcl::tda::generateCircle (CircleParameters()).suggested_radius;
  const float r_noisy = pcl::tda::generateCircle (noisy).suggested_radius;
  EXPECT_LT (r_dense, r_default);
  EXPECT_LT (r_default, r_sparse);
  EXPECT_LT (r_default, r_noisy);
  EXPECT_LT (r_noisy, 0.5f * CircleParameters().radius);
}

TEST (SyntheticShapes, RipserFindsTheBettiNumbersAroundTheSuggestedRadius)
{
  if (std::string (RIPSER_EXECUTABLE).empty() ||
      !std::filesystem::exists (RIPSER_EXECUTABLE))
    GTEST_SKIP() << "ripser not found (install the Debian package ripser)";
  const TemporaryFolder folder;
  for (const ShapeCase& shape : shapeCases())
    for (std::uint64_t seed : {0u, 1u, 2u}) {
      SCOPED_TRACE (shape.name + " seed " + std::to_string (seed));
      const SyntheticShape s = shape.generate (0.01f, seed);
      const double r = s.suggested_radius;
      const pcl::tda::PersistenceDiagram intervals =
          runRipser (*s.cloud, 1.3 * r, folder.path());
      ASSERT_FALSE (intervals.empty());
      EXPECT_EQ (s.beta0, bettiAt (intervals, 0, r));
      EXPECT_EQ (s.beta1, bettiAt (intervals, 1, r));
      // Robust: right on the whole range [0.75 r, 1.3 r), checked at every event.
      std::vector<double> radii = {0.75 * r};
      for (const pcl::tda::PersistenceInterval& i : intervals)
        for (const double v : {i.birth, i.death})
          if (v > 0.75 * r && v < 1.3 * r)
            radii.push_back (v);
      for (const double x : radii) {
        ASSERT_EQ (s.beta0, bettiAt (intervals, 0, x)) << "at radius " << x;
        ASSERT_EQ (s.beta1, bettiAt (intervals, 1, x)) << "at radius " << x;
      }
    }
}

TEST (SyntheticShapes, BadParametersThrow)
{
  CircleParameters circle;
  circle.num_points = 0;
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);
  circle = CircleParameters();
  circle.noise_sigma = -0.1f;
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);
  circle.noise_sigma = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);
  circle = CircleParameters();
  circle.radius = 0.0f;
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);
  circle = CircleParameters();
  circle.num_points = 20; // far too sparse for its Betti numbers
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);
  circle = CircleParameters();
  circle.noise_sigma = 0.2f; // noise swallows the hole
  EXPECT_THROW (pcl::tda::generateCircle (circle), pcl::BadArgumentException);

  TorusParameters torus;
  torus.minor_radius = torus.major_radius;
  EXPECT_THROW (pcl::tda::generateTorus (torus), pcl::BadArgumentException);
  torus = TorusParameters();
  torus.minor_radius = -0.2f;
  EXPECT_THROW (pcl::tda::generateTorus (torus), pcl::BadArgumentException);
  torus = TorusParameters();
  torus.num_points = 300;
  EXPECT_THROW (pcl::tda::generateTorus (torus), pcl::BadArgumentException);

  SphereParameters sphere;
  sphere.radius = std::numeric_limits<float>::infinity();
  EXPECT_THROW (pcl::tda::generateSphere (sphere), pcl::BadArgumentException);
  sphere = SphereParameters();
  sphere.num_points = 100;
  EXPECT_THROW (pcl::tda::generateSphere (sphere), pcl::BadArgumentException);
}
