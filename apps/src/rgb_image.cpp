#include <pcl/tda/apps/rgb_image.h>
#include <pcl/tda/common/atomic_file.h>

#include <png.h>

#include <algorithm>

namespace pcl {
namespace tda {

RGBImage::RGBImage (std::size_t width, std::size_t height, const RGB& background)
: width_ (width), height_ (height), rgb_ (3 * width * height)
{
  for (std::size_t i = 0; i < width * height; ++i)
    std::copy (background.begin(), background.end(), rgb_.begin() + 3 * i);
}

void
RGBImage::set (long x, long y, const RGB& color)
{
  if (x < 0 || y < 0 || x >= static_cast<long> (width_) ||
      y >= static_cast<long> (height_))
    return;
  std::copy (color.begin(),
             color.end(),
             rgb_.begin() + 3 * (static_cast<std::size_t> (y) * width_ +
                                 static_cast<std::size_t> (x)));
}

void
RGBImage::fill (long x, long y, long w, long h, const RGB& color)
{
  for (long v = y; v < y + h; ++v)
    for (long u = x; u < x + w; ++u)
      set (u, v, color);
}

void
RGBImage::paste (const RGBImage& image, long x, long y)
{
  for (std::size_t v = 0; v < image.height_; ++v)
    for (std::size_t u = 0; u < image.width_; ++u) {
      const auto* pixel = &image.rgb_[3 * (v * image.width_ + u)];
      set (x + static_cast<long> (u),
           y + static_cast<long> (v),
           {pixel[0], pixel[1], pixel[2]});
    }
}

void
RGBImage::savePNG (const std::string& path) const
{
  replaceFileAtomically (path, [this] (const std::string& temporary) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32> (width_);
    image.height = static_cast<png_uint_32> (height_);
    image.format = PNG_FORMAT_RGB;
    const bool written =
        png_image_write_to_file (&image, temporary.c_str(), 0, rgb_.data(), 0, nullptr);
    png_image_free (&image);
    return written;
  });
}

} // namespace tda
} // namespace pcl
