#include <pcl/tda/common/cielab.h>
#include <pcl/point_types.h>
#include <pcl/point_types_conversion.h>

#include <gtest/gtest.h>

#include <cstdint>

namespace {

using pcl::tda::deltaE76;
using pcl::tda::LabColor;
using pcl::tda::rgbToLab;

void
expectLab (
    std::uint8_t r, std::uint8_t g, std::uint8_t b, double l, double a, double b_star)
{
  const LabColor lab = rgbToLab (r, g, b);
  EXPECT_NEAR (lab.l, l, 2e-3) << int (r) << " " << int (g) << " " << int (b);
  EXPECT_NEAR (lab.a, a, 2e-3) << int (r) << " " << int (g) << " " << int (b);
  EXPECT_NEAR (lab.b, b_star, 2e-3) << int (r) << " " << int (g) << " " << int (b);
}

} // namespace

// Published sRGB (D65) -> CIELAB values (Lindbloom's calculator and the sRGB
// primaries' well-known coordinates).
TEST (CIELab, PublishedReferenceValues)
{
  expectLab (0, 0, 0, 0.0, 0.0, 0.0);
  expectLab (255, 255, 255, 100.0, 0.0, 0.0);
  expectLab (255, 0, 0, 53.2408, 80.0925, 67.2032);
  expectLab (0, 255, 0, 87.7347, -86.1827, 83.1793);
  expectLab (0, 0, 255, 32.2970, 79.1875, -107.8602);
  expectLab (128, 128, 128, 53.5850, 0.0, 0.0);
}

// PCL's own conversion rounds its constants (7.787, 0.008856, four-digit matrix) and
// works in float: within a few hundredths of ours on every colour of a coarse grid.
TEST (CIELab, AgreesWithPCLConversion)
{
  double worst = 0.0;
  for (int r = 0; r < 256; r += 15)
    for (int g = 0; g < 256; g += 15)
      for (int b = 0; b < 256; b += 15) {
        pcl::PointXYZRGB point;
        point.r = static_cast<std::uint8_t> (r);
        point.g = static_cast<std::uint8_t> (g);
        point.b = static_cast<std::uint8_t> (b);
        pcl::PointXYZLAB reference;
        pcl::PointXYZRGBtoXYZLAB (point, reference);
        const LabColor ours = rgbToLab (point.r, point.g, point.b);
        worst = std::max (worst,
                          static_cast<double> (deltaE76 (
                              ours, {reference.L, reference.a, reference.b})));
      }
  EXPECT_LT (worst, 0.1);
}

TEST (CIELab, DeltaE76IsTheEuclideanDistance)
{
  EXPECT_FLOAT_EQ (deltaE76 ({50.0f, 0.0f, 0.0f}, {53.0f, 4.0f, 0.0f}), 5.0f);
  EXPECT_FLOAT_EQ (deltaE76 ({10.0f, -3.0f, 7.0f}, {10.0f, -3.0f, 7.0f}), 0.0f);
  // Black and white are 100 apart; the sRGB red and green about 170.
  EXPECT_NEAR (deltaE76 (rgbToLab (0, 0, 0), rgbToLab (255, 255, 255)), 100.0, 1e-3);
  EXPECT_NEAR (deltaE76 (rgbToLab (255, 0, 0), rgbToLab (0, 255, 0)), 170.565, 1e-2);
}
