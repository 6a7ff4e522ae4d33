#pragma once

#include <cmath>
#include <cstdint>

namespace pcl {
namespace tda {

/** \brief A colour in CIELAB (CIE 1976 L*a*b*): L* in [0, 100], a* and b* roughly in
 * [-128, 128]. Euclidean distances in this space (deltaE76()) follow perceived colour
 * differences, which is why region growing compares colours here (thesis Sec 4.2.3,
 * Eq 4.5) and not in RGB. */
struct LabColor {
  float l = 0.0f;
  float a = 0.0f;
  float b = 0.0f;
};

/** \brief Converts an 8-bit sRGB colour to CIELAB with the standard formulas: the
 * sRGB transfer function (IEC 61966-2-1) to linear RGB, the sRGB matrix to CIE XYZ,
 * and CIE 1976 L*a*b* relative to the D65 white (Xn 0.95047, Yn 1, Zn 1.08883), with
 * the exact CIE constants epsilon = 216/24389 and kappa = 24389/27. Computed in double
 * precision; white (255, 255, 255) gives (100, 0, 0) to within 1e-4. */
LabColor
rgbToLab (std::uint8_t r, std::uint8_t g, std::uint8_t b);

/** \brief The CIE 1976 colour difference Delta E*ab (thesis Eq 4.5): the Euclidean
 * distance of two CIELAB colours. About 2.3 is a just noticeable difference. */
inline float
deltaE76 (const LabColor& first, const LabColor& second)
{
  const float dl = first.l - second.l;
  const float da = first.a - second.a;
  const float db = first.b - second.b;
  return std::sqrt (dl * dl + da * da + db * db);
}

} // namespace tda
} // namespace pcl
