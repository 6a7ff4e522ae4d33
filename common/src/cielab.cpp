#include <pcl/tda/common/cielab.h>

#include <array>
#include <cmath>

namespace pcl {
namespace tda {
namespace {

/** The sRGB transfer function inverted: 8-bit level to linear intensity in [0, 1]. */
const std::array<double, 256>&
linearLevels ()
{
  static const std::array<double, 256> levels = [] {
    std::array<double, 256> table{};
    for (std::size_t i = 0; i < table.size(); ++i) {
      const double v = static_cast<double> (i) / 255.0;
      table[i] = v <= 0.04045 ? v / 12.92 : std::pow ((v + 0.055) / 1.055, 2.4);
    }
    return table;
  }();
  return levels;
}

/** The CIE function f of L*a*b*, on a tristimulus value relative to the white. */
double
labFunction (double t)
{
  constexpr double epsilon = 216.0 / 24389.0;
  constexpr double kappa = 24389.0 / 27.0;
  return t > epsilon ? std::cbrt (t) : (kappa * t + 16.0) / 116.0;
}

} // namespace

LabColor
rgbToLab (std::uint8_t r, std::uint8_t g, std::uint8_t b)
{
  const std::array<double, 256>& linear = linearLevels();
  const double lr = linear[r], lg = linear[g], lb = linear[b];
  // sRGB (D65) to CIE XYZ, then relative to the D65 white.
  const double x = (0.4124564 * lr + 0.3575761 * lg + 0.1804375 * lb) / 0.95047;
  const double y = 0.2126729 * lr + 0.7151522 * lg + 0.0721750 * lb;
  const double z = (0.0193339 * lr + 0.1191920 * lg + 0.9503041 * lb) / 1.08883;
  const double fx = labFunction (x), fy = labFunction (y), fz = labFunction (z);
  return {static_cast<float> (116.0 * fy - 16.0),
          static_cast<float> (500.0 * (fx - fy)),
          static_cast<float> (200.0 * (fy - fz))};
}

} // namespace tda
} // namespace pcl
