// pcl::tda::gpu::VietorisRipsBuilder against the CPU builder: the same complex, bit for
// bit (vertices, point indices, edges, triangles, values, order), on random clouds
// with duplicates and non-finite points, on lattices whose distances hit the radius
// exactly, on generated scenes and on the real scans; with 1 and 2 threads; the same
// refusals and messages over the memory limit and on bad input.

#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/generators/hole_surfaces.h>
#include <pcl/tda/generators/tabletop_scenes.h>
#include <pcl/tda/gpu/vietoris_rips_builder.h>
#include <pcl/tda/search/point_spacing.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "builder_progress_check.h"
#include "complex_difference.h"
#include "test_data.h"
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

using namespace pcl::tda;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

namespace {

/** The settings both builders get. */
struct BuildSettings {
  double radius = 0.1;
  int dimension = 2;
  unsigned int threads = 0;
  std::size_t memory_limit = 0; // 0: the default
};

template <typename Builder, typename CloudPtr>
bool
build (Builder& builder,
       const CloudPtr& cloud,
       const BuildSettings& settings,
       FilteredComplex& complex)
{
  builder.setInputCloud (cloud);
  builder.setRadius (settings.radius);
  builder.setMaxDimension (settings.dimension);
  builder.setNumberOfThreads (settings.threads);
  if (settings.memory_limit > 0)
    builder.setMemoryLimit (settings.memory_limit);
  return builder.compute (complex);
}

/** Builds with both builders and expects the same complex and skipped points.
 * \return the number of simplices */
template <typename PointT>
std::size_t
expectSameAsCPU (const typename pcl::PointCloud<PointT>::ConstPtr& cloud,
                 const BuildSettings& settings)
{
  VietorisRipsBuilder<PointT> cpu;
  gpu::VietorisRipsBuilder<PointT> device;
  FilteredComplex expected, actual;
  const bool built = build (cpu, cloud, settings, expected);
  EXPECT_EQ (build (device, cloud, settings, actual), built);
  EXPECT_EQ (test::complexDifference (expected, actual), "");
  EXPECT_EQ (device.getNumSkippedPoints(), cpu.getNumSkippedPoints());
  return expected.numSimplices();
}

/** A random cloud of \a n points of one of several kinds, with duplicates and
 * non-finite points in some. */
Cloud::Ptr
randomCloud (std::mt19937& random, std::size_t n, int kind)
{
  Cloud::Ptr cloud (new Cloud);
  std::uniform_real_distribution<float> unit (-1.0f, 1.0f);
  std::normal_distribution<float> blob (0.0f, 0.05f);
  std::uniform_int_distribution<int> lattice (-6, 6);
  for (std::size_t i = 0; i < n; ++i) {
    pcl::PointXYZ p;
    switch (kind) {
    case 0: // uniform in a cube
      p = {unit (random), unit (random), unit (random)};
      break;
    case 1: // a few Gaussian blobs
    {
      const float centre = 0.5f * static_cast<float> (i % 4);
      p = {centre + blob (random), blob (random), centre + blob (random)};
      break;
    }
    case 2: // a lattice of step 1/4: distances of exactly r, many ties
      p = {
          0.25f * lattice (random), 0.25f * lattice (random), 0.25f * lattice (random)};
      break;
    case 3: // a flat sheet, far from the origin
      p = {1000.0f + unit (random), -500.0f + unit (random), 3.0f};
      break;
    default: // a few positions, many duplicates
      p = {0.1f * static_cast<float> (i % 7),
           0.1f * static_cast<float> (i % 5),
           0.1f * static_cast<float> (i % 3)};
      break;
    }
    cloud->push_back (p);
  }
  if (n > 8 && random() % 2 == 0) {
    (*cloud)[1] = (*cloud)[0];      // a duplicate point
    (*cloud)[2].x = std::nanf (""); // a NaN point
    (*cloud)[3].z = INFINITY;       // an infinite point
    (*cloud)[5] = (*cloud)[4];
    (*cloud)[5].x = std::nextafter ((*cloud)[4].x, 2.0f); // one ulp away
    (*cloud)[6] = {0.0f, 0.0f, -0.0f};                    // signed zeros
    (*cloud)[7] = {-0.0f, 0.0f, 0.0f};
  }
  return cloud;
}

/** The messages that a compute() prints, without the gpu class' namespace and
 * without the notice of a CUDA build that finds no device. */
template <typename Builder>
std::string
messages (Builder& builder, FilteredComplex& complex)
{
  testing::internal::CaptureStderr();
  builder.compute (complex);
  std::istringstream lines (testing::internal::GetCapturedStderr());
  std::string out, line;
  while (std::getline (lines, line))
    if (line.find ("No CUDA device") == std::string::npos)
      out += line + "\n";
  for (std::size_t at; (at = out.find ("gpu::")) != std::string::npos;)
    out.erase (at, 5);
  return out;
}

} // namespace

TEST (GPUVietorisRipsBuilder, SameComplexAsCPUOnRandomClouds)
{
  // Per kind of randomCloud(): the most points and the radii, for a few dozen
  // neighbours per point at most (the lattice's radii are multiples of its step).
  struct Kind {
    std::size_t max_points;
    double min_radius, max_radius;
  };
  const Kind kinds[] = {{3000, 0.02, 0.3},
                        {3000, 0.003, 0.02},
                        {3000, 0.25, 0.5},
                        {3000, 0.01, 0.1},
                        {600, 0.05, 0.12}};
  std::mt19937 random (13);
  std::size_t simplices = 0;
  for (int k = 0; k < 200; ++k) {
    const int kind = k % 5;
    const std::size_t n = 10 + random() % kinds[kind].max_points;
    BuildSettings settings;
    settings.radius =
        kind == 2 ? 0.25 * (1 + random() % 2)
                  : std::uniform_real_distribution<> (kinds[kind].min_radius,
                                                      kinds[kind].max_radius) (random);
    settings.dimension = k % 7 == 6 ? 1 : 2;
    settings.threads = 1 + k % 2;
    SCOPED_TRACE ("case " + std::to_string (k) + ", kind " + std::to_string (kind) +
                  ", " + std::to_string (n) + " points, radius " +
                  std::to_string (settings.radius));
    simplices +=
        expectSameAsCPU<pcl::PointXYZ> (randomCloud (random, n, kind), settings);
  }
  EXPECT_GT (simplices, 1000000u);
}

TEST (GPUVietorisRipsBuilder, SameComplexAsCPUOnTinyAndDegenerateClouds)
{
  Cloud::Ptr cloud (new Cloud);
  cloud->push_back ({0.0f, 0.0f, 0.0f});
  expectSameAsCPU<pcl::PointXYZ> (cloud, {}); // one point: no edge
  cloud->push_back ({1.0f, 0.0f, 0.0f});
  expectSameAsCPU<pcl::PointXYZ> (cloud, {}); // two points apart: no edge
  BuildSettings exact;
  exact.radius = 1.0; // an edge of length exactly r is in
  EXPECT_EQ (expectSameAsCPU<pcl::PointXYZ> (cloud, exact), 3u);
  cloud->push_back ({1e30f, 0.0f, 0.0f}); // a far outlier: clamped cell coordinates
  cloud->push_back ({1e30f, 0.0f, 1.0f});
  cloud->push_back ({-1e30f, -1e30f, 0.0f});
  EXPECT_EQ (expectSameAsCPU<pcl::PointXYZ> (cloud, exact), 7u);
  Cloud::Ptr same (new Cloud);
  for (int i = 0; i < 50; ++i) // 50 points at one position: 1225 edges of length 0
    same->push_back ({0.5f, 0.5f, 0.5f});
  EXPECT_EQ (expectSameAsCPU<pcl::PointXYZ> (same, {}), 50u + 1225u + 19600u);
}

TEST (GPUVietorisRipsBuilder, SameComplexAsCPUOnGeneratedScenes)
{
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    TabletopParameters tabletop;
    tabletop.seed = seed;
    tabletop.point_spacing = 0.008f;
    const TabletopScene scene = generateTabletopScene (tabletop);
    ASSERT_GT (scene.cloud->size(), 5000u);
    BuildSettings settings;
    settings.radius = 0.02;
    settings.threads = static_cast<unsigned int> (1 + seed % 2);
    SCOPED_TRACE ("tabletop scene, seed " + std::to_string (seed));
    EXPECT_GT (expectSameAsCPU<pcl::PointXYZRGBL> (scene.cloud, settings), 100000u);
  }
  for (const HoleSurfaceKind kind :
       {HoleSurfaceKind::PLANE, HoleSurfaceKind::SPHERE, HoleSurfaceKind::TORUS}) {
    HoleSurfaceParameters parameters;
    parameters.kind = kind;
    const HoleSurface surface = generateHoleSurface (parameters);
    Cloud::Ptr cloud (new Cloud);
    pcl::copyPointCloud (*surface.cloud, *cloud);
    BuildSettings settings;
    settings.radius = 2.5 * surface.spacing;
    SCOPED_TRACE (std::string ("hole surface ") + holeSurfaceKindName (kind));
    EXPECT_GT (expectSameAsCPU<pcl::PointXYZ> (cloud, settings), 10000u);
  }
}

TEST (GPUVietorisRipsBuilder, SameComplexAsCPUOnRealScans)
{
  // Every scan at two radii, in units of its spacing (average degrees of ~10 and
  // ~25 on surfaces); the organized scenes hold NaN points.
  for (const std::string name : {"bunny.pcd",
                                 "milk.pcd",
                                 "car6.pcd",
                                 "rops_cloud.pcd",
                                 "noisy_slice_displaced.pcd",
                                 "sac_plane_test.pcd",
                                 "table_scene_mug_stereo_textured.pcd",
                                 "kinect_frame.pcd"}) {
    PCL_TDA_REQUIRE_DATA (name);
    Cloud::Ptr cloud (new Cloud);
    ASSERT_EQ (pcl::io::loadPCDFile (test::dataFile (name), *cloud), 0) << name;
    const double spacing = pointSpacing (*cloud);
    ASSERT_GT (spacing, 0.0) << name;
    for (const double multiple : {2.0, 3.0}) {
      BuildSettings settings;
      settings.radius = multiple * spacing;
      settings.threads = 2;
      SCOPED_TRACE (name + " at radius " + std::to_string (settings.radius));
      EXPECT_GT (expectSameAsCPU<pcl::PointXYZ> (cloud, settings), cloud->size());
    }
  }
}

TEST (GPUVietorisRipsBuilder, SameComplexForThreadsShuffledInputAndIndices)
{
  std::mt19937 random (17);
  // Kinds of randomCloud() with a radius that gives them a few neighbours each.
  const std::pair<int, double> cases[] = {{0, 0.08}, {1, 0.008}, {3, 0.02}};
  for (const auto& [kind, radius] : cases) {
    const Cloud::Ptr cloud = randomCloud (random, 20000, kind);
    Cloud::Ptr shuffled (new Cloud (*cloud));
    std::shuffle (shuffled->begin(), shuffled->end(), random);
    BuildSettings settings;
    settings.radius = radius;
    settings.threads = 1;
    gpu::VietorisRipsBuilder<pcl::PointXYZ> builder;
    FilteredComplex one, two, other;
    ASSERT_TRUE (build (builder, cloud, settings, one));
    EXPECT_GT (one.numTriangles(), 1000u);
    settings.threads = 2;
    ASSERT_TRUE (build (builder, cloud, settings, two));
    EXPECT_EQ (test::complexDifference (one, two), "");
    ASSERT_TRUE (build (builder, shuffled, settings, other));
    ASSERT_EQ (test::complexDifference (one, other, false), "");
    for (std::size_t v = 0; v < other.numVertices(); ++v) {
      const auto& p = (*shuffled)[other.pointIndices()[v]];
      const auto& q = (*cloud)[one.pointIndices()[v]];
      ASSERT_TRUE (p.x == q.x && p.y == q.y && p.z == q.z);
    }
  }

  // Indices: the complex of the indexed points, as the CPU builder's.
  const Cloud::Ptr cloud = randomCloud (random, 5000, 0);
  pcl::IndicesPtr indices (new pcl::Indices);
  for (int i = 0; i < 5000; i += 3)
    indices->push_back (i);
  VietorisRipsBuilder<pcl::PointXYZ> cpu;
  gpu::VietorisRipsBuilder<pcl::PointXYZ> device;
  cpu.setIndices (indices);
  device.setIndices (indices);
  BuildSettings settings;
  settings.radius = 0.15;
  FilteredComplex expected, actual;
  ASSERT_TRUE (build (cpu, cloud, settings, expected));
  ASSERT_TRUE (build (device, cloud, settings, actual));
  EXPECT_EQ (actual.numVertices(), indices->size());
  EXPECT_EQ (test::complexDifference (expected, actual), "");
}

TEST (GPUVietorisRipsBuilder, KeepsOpenMPThreadSettingAndReportsBackend)
{
  std::mt19937 random (19);
  const Cloud::Ptr cloud = randomCloud (random, 2000, 0);
  const int before = omp_get_max_threads();
  gpu::VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (cloud);
  builder.setRadius (0.2);
  builder.setNumberOfThreads (before == 1 ? 2 : 1);
  FilteredComplex complex;
  testing::internal::CaptureStderr();
  ASSERT_TRUE (builder.compute (complex));
  ASSERT_TRUE (builder.compute (complex));
  const std::string notices = testing::internal::GetCapturedStderr();
  EXPECT_EQ (omp_get_max_threads(), before);

  std::string why;
  const gpu::DeviceBackend expected = gpu::selectBackend (why);
  EXPECT_EQ (builder.getBackend(), expected);
  if (gpu::builtWithCUDA() && expected == gpu::DeviceBackend::OPENMP) {
    // A CUDA build without a device says so, once, and runs on OpenMP.
    EXPECT_FALSE (why.empty());
    const auto first = notices.find ("No CUDA device");
    ASSERT_NE (first, std::string::npos) << notices;
    EXPECT_EQ (notices.find ("No CUDA device", first + 1), std::string::npos);
    EXPECT_NE (notices.find ("running on the OpenMP backend"), std::string::npos);
  }
  if (!gpu::builtWithCUDA()) {
    EXPECT_TRUE (why.empty());
    EXPECT_EQ (builder.getBackend(), gpu::DeviceBackend::OPENMP);
    EXPECT_TRUE (notices.empty()) << notices;
  }
  EXPECT_EQ (gpu::backendName (gpu::DeviceBackend::OPENMP), "OpenMP");
  EXPECT_EQ (gpu::backendName (gpu::DeviceBackend::CUDA), "CUDA");
}

TEST (GPUVietorisRipsBuilder, RefusesBadInputAsCPU)
{
  VietorisRipsBuilder<pcl::PointXYZ> cpu;
  gpu::VietorisRipsBuilder<pcl::PointXYZ> device;
  FilteredComplex complex;
  const auto expectSameRefusal = [&] (const std::string& what) {
    const std::string expected = messages (cpu, complex);
    EXPECT_FALSE (device.compute (complex)) << what;
    EXPECT_EQ (messages (device, complex), expected) << what;
    EXPECT_FALSE (expected.empty()) << what;
    EXPECT_EQ (complex.numSimplices(), 0u) << what;
  };
  cpu.setRadius (0.1);
  device.setRadius (0.1);
  expectSameRefusal ("no input");

  Cloud::Ptr empty (new Cloud);
  cpu.setInputCloud (empty);
  device.setInputCloud (empty);
  expectSameRefusal ("empty input");

  Cloud::Ptr all_nan (new Cloud);
  for (int i = 0; i < 10; ++i)
    all_nan->push_back ({NAN, NAN, NAN});
  cpu.setInputCloud (all_nan);
  device.setInputCloud (all_nan);
  expectSameRefusal ("no finite point");
  EXPECT_EQ (device.getNumSkippedPoints(), 10u);

  std::mt19937 random (5);
  const Cloud::Ptr cloud = randomCloud (random, 200, 0);
  cpu.setInputCloud (cloud);
  device.setInputCloud (cloud);
  for (const double radius : {0.0, -1.0, double (NAN), double (INFINITY)}) {
    cpu.setRadius (radius);
    device.setRadius (radius);
    expectSameRefusal ("radius " + std::to_string (radius));
  }
  cpu.setRadius (0.5);
  device.setRadius (0.5);
  cpu.setMaxDimension (3);
  device.setMaxDimension (3);
  expectSameRefusal ("dimension 3");
}

TEST (GPUVietorisRipsBuilder, RefusesOverTheMemoryLimitAsCPU)
{
  std::mt19937 random (5);
  const Cloud::Ptr cloud = randomCloud (random, 2000, 0);
  VietorisRipsBuilder<pcl::PointXYZ> cpu;
  gpu::VietorisRipsBuilder<pcl::PointXYZ> device;
  cpu.setInputCloud (cloud);
  device.setInputCloud (cloud);
  cpu.setRadius (0.3);
  device.setRadius (0.3);
  FilteredComplex complex;
  ASSERT_TRUE (cpu.compute (complex));
  const std::size_t edges = complex.numEdges(), triangles = complex.numTriangles();
  EXPECT_EQ (device.BYTES_PER_EDGE, cpu.BYTES_PER_EDGE);
  EXPECT_EQ (device.BYTES_PER_TRIANGLE, cpu.BYTES_PER_TRIANGLE);

  const auto expectSame = [&] (std::size_t limit, bool built, const std::string& what) {
    cpu.setMemoryLimit (limit);
    device.setMemoryLimit (limit);
    const std::string expected = messages (cpu, complex);
    EXPECT_EQ (complex.numSimplices() > 0, built) << what;
    EXPECT_EQ (messages (device, complex), expected) << what;
    EXPECT_EQ (complex.numSimplices() > 0, built) << what;
    if (!built) {
      EXPECT_NE (expected.find ("over the memory limit"), std::string::npos) << what;
    }
  };
  // Over the limit by the edges, by the triangles only, and just within it.
  expectSame (edges * cpu.BYTES_PER_EDGE - 1, false, "edges over");
  expectSame (edges * cpu.BYTES_PER_EDGE + triangles * cpu.BYTES_PER_TRIANGLE / 2,
              false,
              "triangles over");
  expectSame (
      edges * cpu.BYTES_PER_EDGE + triangles * cpu.BYTES_PER_TRIANGLE, true, "within");
  cpu.setMaxDimension (1);
  device.setMaxDimension (1);
  expectSame (edges * cpu.BYTES_PER_EDGE, true, "edges only, within");

  // Far over: refused on a sample in bounded time, with the same estimate (8,000
  // points within a radius covering all: 3.2e7 edges and 8.5e10 triangles).
  const Cloud::Ptr dense = randomCloud (random, 8000, 0);
  cpu.setInputCloud (dense);
  device.setInputCloud (dense);
  cpu.setMaxDimension (2);
  device.setMaxDimension (2);
  cpu.setRadius (4.0);
  device.setRadius (4.0);
  expectSame (std::size_t (1) << 30, false, "far over");
  const std::string refusal = messages (device, complex);
  EXPECT_NE (refusal.find ("(estimated from a sample)"), std::string::npos) << refusal;
  cpu.setRadius (0.3);
  device.setRadius (0.3);
  expectSame (std::size_t (64) << 20, false, "triangles far over");
}

// The build reports its progress in thousandths, never backwards, ending at 1000,
// and the complex is the same with a callback as without.
TEST (GPUVietorisRipsBuilder, ReportsProgress)
{
  std::mt19937 random (41);
  test::expectReportsProgress<gpu::VietorisRipsBuilder<pcl::PointXYZ>> (
      randomCloud (random, 20000, 0), 0.1, 4);
}
