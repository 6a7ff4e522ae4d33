#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief An RGB colour. */
using RGB = std::array<std::uint8_t, 3>;

/** \brief An RGB picture for the tools' PNG outputs of clouds and screenshots:
 * pixels and filled rectangles, saved as PNG by libpng. */
class RGBImage {
public:
  /** \brief A \a width x \a height picture of colour \a background. */
  RGBImage (std::size_t width, std::size_t height, const RGB& background);

  std::size_t
  width () const
  {
    return width_;
  }

  std::size_t
  height () const
  {
    return height_;
  }

  /** \brief Sets the pixel (x, y); pixels outside the picture are ignored. */
  void
  set (long x, long y, const RGB& color);

  /** \brief Fills the rectangle of corner (x, y) and size w x h. */
  void
  fill (long x, long y, long w, long h, const RGB& color);

  /** \brief Copies \a image into this picture, its top left corner at (x, y);
   * what falls outside is cut off. */
  void
  paste (const RGBImage& image, long x, long y);

  /** \brief Writes the picture as a PNG file, atomically.
   * \throws pcl::IOException when the file cannot be written */
  void
  savePNG (const std::string& path) const;

  /** \brief The pixels, row by row, 3 bytes each. */
  const std::vector<std::uint8_t>&
  pixels () const
  {
    return rgb_;
  }

private:
  std::size_t width_, height_;
  std::vector<std::uint8_t> rgb_;
};

} // namespace tda
} // namespace pcl
