#pragma once

// PNG pictures read back in tests (libpng): their size and pixels.

#include <png.h>

#include <array>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace pcl {
namespace tda {
namespace test {

using Color = std::array<std::uint8_t, 3>;

/** A PNG picture read back: its size and pixels (RGB, row by row). */
struct Picture {
  unsigned width = 0, height = 0;
  std::vector<std::uint8_t> rgb;

  /** How many pixels have exactly the colour \a color. */
  std::size_t
  count (const Color& color) const
  {
    std::size_t n = 0;
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
      n += rgb[i] == color[0] && rgb[i + 1] == color[1] && rgb[i + 2] == color[2];
    return n;
  }

  /** How many colours the picture has. */
  std::size_t
  numColors () const
  {
    std::set<std::uint32_t> colors;
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
      colors.insert (rgb[i] << 16 | rgb[i + 1] << 8 | rgb[i + 2]);
    return colors.size();
  }
};

/** The picture \a path; size 0 x 0 when it cannot be read. */
inline Picture
readPNG (const std::string& path)
{
  Picture picture;
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file (&image, path.c_str()))
    return picture;
  image.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> pixels (PNG_IMAGE_SIZE (image));
  if (!png_image_finish_read (&image, nullptr, pixels.data(), 0, nullptr))
    return picture;
  picture.width = image.width;
  picture.height = image.height;
  picture.rgb = std::move (pixels);
  return picture;
}

} // namespace test
} // namespace tda
} // namespace pcl
