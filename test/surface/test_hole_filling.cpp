/** HoleFilling on generated surfaces: new points on the true surface, inside the
 * holes, spaced like the cloud, the input kept unchanged, and the filled holes gone
 * from H1; the thesis' centroid mode; bad input. */
#include <pcl/common/io.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/tda/features/hole_boundary_estimation.h>
#include <pcl/tda/generators/hole_surfaces.h>
#include <pcl/tda/surface/hole_filling.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace {

using pcl::tda::HoleSurface;
using pcl::tda::HoleSurfaceKind;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

struct Detected {
  HoleSurface surface;
  Cloud::Ptr cloud;
  std::vector<pcl::tda::HoleRim> holes;
};

Detected
detect (HoleSurfaceKind kind, std::uint64_t seed, float noise = 0.0f)
{
  pcl::tda::HoleSurfaceParameters parameters;
  parameters.kind = kind;
  parameters.seed = seed;
  parameters.noise_sigma = noise;
  Detected detected{
      pcl::tda::generateHoleSurface (parameters), Cloud::Ptr (new Cloud), {}};
  pcl::copyPointCloud (*detected.surface.cloud, *detected.cloud);
  pcl::tda::HoleBoundaryEstimation<pcl::PointXYZ, pcl::Boundary> estimation;
  estimation.setInputCloud (detected.cloud);
  pcl::PointCloud<pcl::Boundary> flags;
  estimation.compute (flags);
  detected.holes = estimation.getHoles();
  return detected;
}

/** The distance of \a p to the generated surface (plane z = 0, or the sphere). */
double
surfaceDistance (HoleSurfaceKind kind, const pcl::PointXYZ& p)
{
  if (kind == HoleSurfaceKind::SPHERE)
    return std::abs (p.getVector3fMap().norm() - pcl::tda::HOLE_SPHERE_RADIUS);
  return std::abs (p.z);
}

TEST (HoleFilling, SurfaceModeFillsEachHoleOnTheSurface)
{
  for (const HoleSurfaceKind kind : {HoleSurfaceKind::PLANE, HoleSurfaceKind::SPHERE})
    for (const float noise : {0.0f, 0.1f}) {
      SCOPED_TRACE (::testing::Message()
                    << "kind " << static_cast<int> (kind) << " noise " << noise);
      const Detected detected = detect (kind, 1, noise);
      ASSERT_FALSE (detected.holes.empty());
      pcl::tda::HoleFilling<pcl::PointXYZ> filler;
      filler.setInputCloud (detected.cloud);
      filler.setHoles (detected.holes);
      Cloud filled;
      ASSERT_TRUE (filler.reconstruct (filled));
      // The input first, unchanged.
      ASSERT_GT (filled.size(), detected.cloud->size());
      for (std::size_t i = 0; i < detected.cloud->size(); ++i)
        ASSERT_EQ (filled[i].getVector3fMap(), (*detected.cloud)[i].getVector3fMap());
      const float h = detected.surface.spacing;
      const float sigma = noise * h;
      // Every new point on the true surface and inside a true hole (or in a gap of
      // the sampling just beside it, inside the rim).
      for (std::size_t i = detected.cloud->size(); i < filled.size(); ++i) {
        EXPECT_LT (surfaceDistance (kind, filled[i]), 3.0f * sigma + 0.05f * h);
        bool inside = false;
        for (const auto& hole : detected.surface.holes)
          inside |= (filled[i].getVector3fMap() - hole.center).norm() <
                    hole.radius + 2.0f * h;
        EXPECT_TRUE (inside) << i;
      }
      // Where the holes' true samples were: near them, and covering them.
      pcl::KdTreeFLANN<pcl::PointXYZ> to_cut, to_new;
      Cloud::Ptr cut (new Cloud), added (new Cloud);
      pcl::copyPointCloud (*detected.surface.cut, *cut);
      for (std::size_t i = detected.cloud->size(); i < filled.size(); ++i)
        added->push_back (filled[i]);
      to_cut.setInputCloud (cut);
      to_new.setInputCloud (added);
      std::vector<float> to_truth;
      pcl::Indices nearest (1);
      std::vector<float> squared (1);
      for (const auto& point : *added) {
        to_cut.nearestKSearch (point, 1, nearest, squared);
        to_truth.push_back (std::sqrt (squared[0]));
      }
      std::nth_element (
          to_truth.begin(), to_truth.begin() + to_truth.size() / 2, to_truth.end());
      EXPECT_LE (to_truth[to_truth.size() / 2], h); // median distance to a true sample
      std::size_t covered = 0, in_found_holes = 0;
      for (const auto& truth : *detected.surface.cut) {
        bool found = false; // the true hole is one of the detected ones
        for (const auto& rim : detected.holes)
          found |=
              (rim.centroid - detected.surface.holes[truth.label - 1].center).norm() <
              detected.surface.holes[truth.label - 1].radius;
        if (!found)
          continue;
        ++in_found_holes;
        to_new.nearestKSearch (
            pcl::PointXYZ (truth.x, truth.y, truth.z), 1, nearest, squared);
        covered += std::sqrt (squared[0]) <= 1.5f * h;
      }
      EXPECT_GT (covered, in_found_holes * 4 / 5); // the filled holes are covered
      // Per hole about as many points as the hole's area holds (h^2 each).
      const auto& counts = filler.getNewPointCounts();
      ASSERT_EQ (counts.size(), detected.holes.size());
      for (std::size_t k = 0; k < counts.size(); ++k) {
        const double expected = detected.holes[k].area / (h * h);
        EXPECT_GT (counts[k], 0.5 * expected) << "hole " << k;
        EXPECT_LT (counts[k], 1.5 * expected + 2.0) << "hole " << k;
      }
    }
}

TEST (HoleFilling, FilledHolesAreGoneFromH1)
{
  const Detected detected = detect (HoleSurfaceKind::PLANE, 2);
  ASSERT_EQ (detected.holes.size(), 3u);
  pcl::tda::HoleFilling<pcl::PointXYZ> filler;
  filler.setInputCloud (detected.cloud);
  filler.setHoles (detected.holes);
  Cloud::Ptr filled (new Cloud);
  ASSERT_TRUE (filler.reconstruct (*filled));
  pcl::tda::HoleBoundaryEstimation<pcl::PointXYZ, pcl::Boundary> again;
  again.setInputCloud (filled);
  pcl::PointCloud<pcl::Boundary> flags;
  again.compute (flags);
  EXPECT_TRUE (again.getHoles().empty());
}

TEST (HoleFilling, CentroidModeOnePointPerHoleAtItsCentre)
{
  const Detected detected = detect (HoleSurfaceKind::PLANE, 3);
  pcl::tda::HoleFilling<pcl::PointXYZ> filler;
  filler.setInputCloud (detected.cloud);
  filler.setHoles (detected.holes);
  filler.setMode (pcl::tda::HoleFilling<pcl::PointXYZ>::Mode::CENTROID);
  Cloud filled;
  ASSERT_TRUE (filler.reconstruct (filled));
  ASSERT_EQ (filled.size(), detected.cloud->size() + detected.holes.size());
  for (std::size_t k = 0; k < detected.holes.size(); ++k) {
    const auto& p = filled[detected.cloud->size() + k];
    EXPECT_LT ((p.getVector3fMap() - detected.holes[k].centroid).norm(), 1e-5f);
    // The rims of round holes centre on the holes.
    float nearest = 1e9f;
    for (const auto& hole : detected.surface.holes)
      nearest = std::min (nearest, (p.getVector3fMap() - hole.center).norm());
    EXPECT_LT (nearest, detected.surface.spacing);
  }
}

TEST (HoleFilling, SameNewPointsInAnyUnit)
{
  // The cloud and its holes scaled by a power of two (exact in float), to units where
  // float squared distances overflow (2^90) or underflow (2^-90): the same new
  // points, scaled alike, up to float rounding.
  const Detected detected = detect (HoleSurfaceKind::SPHERE, 2, 0.1f);
  pcl::tda::HoleFilling<pcl::PointXYZ> filler;
  filler.setInputCloud (detected.cloud);
  filler.setHoles (detected.holes);
  Cloud expected;
  ASSERT_TRUE (filler.reconstruct (expected));
  ASSERT_GT (expected.size(), detected.cloud->size());
  for (const int exponent : {90, -90}) {
    SCOPED_TRACE (::testing::Message() << "unit 2^" << exponent);
    const float unit = std::ldexp (1.0f, exponent);
    Cloud::Ptr scaled (new Cloud);
    for (const auto& p : *detected.cloud)
      scaled->push_back (pcl::PointXYZ (p.x * unit, p.y * unit, p.z * unit));
    pcl::tda::HoleFilling<pcl::PointXYZ> scaled_filler;
    scaled_filler.setInputCloud (scaled);
    scaled_filler.setHoles (detected.holes); // rims are indices: the same
    Cloud filled;
    ASSERT_TRUE (scaled_filler.reconstruct (filled));
    ASSERT_EQ (filled.size(), expected.size());
    for (std::size_t i = detected.cloud->size(); i < filled.size(); ++i)
      EXPECT_LT (
          (filled[i].getVector3fMap() / unit - expected[i].getVector3fMap()).norm(),
          1e-6f)
          << i;
  }
}

TEST (HoleFilling, OtherFieldsCopiedFromTheNearestRimPoint)
{
  const Detected detected = detect (HoleSurfaceKind::PLANE, 4);
  pcl::PointCloud<pcl::PointXYZL>::Ptr labelled (new pcl::PointCloud<pcl::PointXYZL>);
  *labelled = *detected.surface.cloud;
  pcl::tda::HoleFilling<pcl::PointXYZL> filler;
  filler.setInputCloud (labelled);
  filler.setHoles (detected.holes);
  pcl::PointCloud<pcl::PointXYZL> filled;
  ASSERT_TRUE (filler.reconstruct (filled));
  ASSERT_GT (filled.size(), labelled->size());
  const pcl::Indices& sources = filler.getNewPointSources();
  ASSERT_EQ (sources.size(), filled.size() - labelled->size());
  for (std::size_t i = labelled->size(); i < filled.size(); ++i) {
    const pcl::PointXYZL* nearest = nullptr;
    float best = 1e9f;
    for (const auto& hole : detected.holes)
      for (const auto index : hole.rim) {
        const float d =
            ((*labelled)[index].getVector3fMap() - filled[i].getVector3fMap()).norm();
        if (d < best) {
          best = d;
          nearest = &(*labelled)[index];
        }
      }
    ASSERT_NE (nearest, nullptr);
    EXPECT_EQ (filled[i].label, nearest->label);
    const pcl::PointXYZL& source = (*labelled)[sources[i - labelled->size()]];
    EXPECT_FLOAT_EQ ((source.getVector3fMap() - filled[i].getVector3fMap()).norm(),
                     best);
  }
  // A second run starts the list again.
  ASSERT_TRUE (filler.reconstruct (filled));
  EXPECT_EQ (sources.size(), filled.size() - labelled->size());
}

TEST (HoleFilling, BadInput)
{
  const Detected detected = detect (HoleSurfaceKind::PLANE, 5);
  Cloud filled;
  {
    pcl::tda::HoleFilling<pcl::PointXYZ> filler; // no input
    EXPECT_FALSE (filler.reconstruct (filled));
    EXPECT_TRUE (filled.empty());
  }
  {
    pcl::tda::HoleFilling<pcl::PointXYZ> filler; // rims of another cloud
    Cloud::Ptr small (new Cloud);
    small->resize (10);
    filler.setInputCloud (small);
    filler.setHoles (detected.holes);
    EXPECT_FALSE (filler.reconstruct (filled));
    EXPECT_TRUE (filled.empty());
  }
  for (const double spacing : {-1.0, std::nan ("")}) {
    pcl::tda::HoleFilling<pcl::PointXYZ> filler;
    filler.setInputCloud (detected.cloud);
    filler.setHoles (detected.holes);
    filler.setSpacing (spacing);
    EXPECT_FALSE (filler.reconstruct (filled));
    EXPECT_TRUE (filled.empty());
  }
  // A spacing far finer than the cloud's: grids of petabytes, refused at once (they
  // were allocated: std::bad_alloc, or 17 GB over a minute at 1e-5). CENTROID mode
  // has no grid.
  for (const double spacing : {1e-6, 1e-9}) {
    pcl::tda::HoleFilling<pcl::PointXYZ> filler;
    filler.setInputCloud (detected.cloud);
    filler.setHoles (detected.holes);
    filler.setSpacing (spacing);
    EXPECT_FALSE (filler.reconstruct (filled)) << spacing;
    EXPECT_TRUE (filled.empty());
    filler.setMode (pcl::tda::HoleFilling<pcl::PointXYZ>::Mode::CENTROID);
    EXPECT_TRUE (filler.reconstruct (filled)) << spacing;
  }
  {
    // A mode outside the enum (it searched a tree never built: a segfault).
    using Filler = pcl::tda::HoleFilling<pcl::PointXYZ>;
    Filler filler;
    filler.setInputCloud (detected.cloud);
    filler.setHoles (detected.holes);
    EXPECT_EQ (filler.getHoles().size(), detected.holes.size());
    filler.setMode (static_cast<Filler::Mode> (2));
    EXPECT_FALSE (filler.reconstruct (filled));
    EXPECT_TRUE (filled.empty());
    // Indices, which it ignored: refused, but those of every point in order.
    filler.setMode (Filler::Mode::CENTROID);
    filler.setIndices (pcl::make_shared<pcl::Indices> (pcl::Indices{0, 1, 2}));
    EXPECT_FALSE (filler.reconstruct (filled));
    EXPECT_TRUE (filled.empty());
    auto all = pcl::make_shared<pcl::Indices> (detected.cloud->size());
    std::iota (all->begin(), all->end(), 0);
    filler.setIndices (all);
    ASSERT_TRUE (filler.reconstruct (filled));
    EXPECT_EQ (filled.size(), detected.cloud->size() + detected.holes.size());
  }
  {
    pcl::tda::HoleFilling<pcl::PointXYZ> filler; // no holes: the input as it is
    filler.setInputCloud (detected.cloud);
    ASSERT_TRUE (filler.reconstruct (filled));
    EXPECT_EQ (filled.size(), detected.cloud->size());
    // Also a segment of one point, whose spacing cannot be measured.
    Cloud::Ptr one (new Cloud);
    one->push_back (pcl::PointXYZ (1.0f, 2.0f, 3.0f));
    filler.setInputCloud (one);
    ASSERT_TRUE (filler.reconstruct (filled));
    ASSERT_EQ (filled.size(), 1u);
    EXPECT_EQ (filled[0].x, 1.0f);
  }
}

} // namespace
