#include <pcl/io/png_io.h>
#include <pcl/tda/apps/rgb_image.h>
#include <pcl/tda/common/atomic_file.h>

#include <algorithm>
#include <fstream>

namespace pcl {
namespace tda {
namespace {

constexpr int GLYPH_WIDTH = 5;
constexpr int GLYPH_HEIGHT = 8;
/** Pixels between two characters, before scaling. */
constexpr int GLYPH_GAP = 1;

/** The glyphs of ' ' to '~': 8 rows of 5 bits, the first row in the highest bits,
 * the leftmost pixel the highest bit of its row; row 7 is below the baseline. */
constexpr std::uint64_t GLYPHS[95] = {
    0x0000000000ULL, // space
    0x2108420080ULL, // '!'
    0x5294000000ULL, // '"'
    0x52beafa940ULL, // '#'
    0x23e8e2f880ULL, // '$'
    0xc644444c60ULL, // '%'
    0x64a88ac9a0ULL, // '&'
    0x2108000000ULL, // '''
    0x1110841040ULL, // '('
    0x4104211100ULL, // ')'
    0x012aea9000ULL, // '*'
    0x0109f21000ULL, // '+'
    0x0000001088ULL, // ','
    0x0001f00000ULL, // '-'
    0x0000003180ULL, // '.'
    0x0044444000ULL, // '/'
    0x74675cc5c0ULL, // '0'
    0x23084211c0ULL, // '1'
    0x74422223e0ULL, // '2'
    0xf88820c5c0ULL, // '3'
    0x11952f8840ULL, // '4'
    0xfc3c10c5c0ULL, // '5'
    0x3221e8c5c0ULL, // '6'
    0xf844442100ULL, // '7'
    0x7462e8c5c0ULL, // '8'
    0x7462f08980ULL, // '9'
    0x0318063000ULL, // ':'
    0x0318063088ULL, // ';'
    0x1111041040ULL, // '<'
    0x003e0f8000ULL, // '='
    0x4104111100ULL, // '>'
    0x7442220080ULL, // '?'
    0x7442dad5c0ULL, // '@'
    0x7463f8c620ULL, // 'A'
    0xf463e8c7c0ULL, // 'B'
    0x74610845c0ULL, // 'C'
    0xe4a318cb80ULL, // 'D'
    0xfc21e843e0ULL, // 'E'
    0xfc21e84200ULL, // 'F'
    0x746178c5e0ULL, // 'G'
    0x8c63f8c620ULL, // 'H'
    0x71084211c0ULL, // 'I'
    0x3884214980ULL, // 'J'
    0x8ca98a4a20ULL, // 'K'
    0x84210843e0ULL, // 'L'
    0x8eeb58c620ULL, // 'M'
    0x8c7359c620ULL, // 'N'
    0x746318c5c0ULL, // 'O'
    0xf463e84200ULL, // 'P'
    0x74631ac9a0ULL, // 'Q'
    0xf463ea4a20ULL, // 'R'
    0x7c20e087c0ULL, // 'S'
    0xf908421080ULL, // 'T'
    0x8c6318c5c0ULL, // 'U'
    0x8c6318a880ULL, // 'V'
    0x8c635ad540ULL, // 'W'
    0x8c54454620ULL, // 'X'
    0x8c54421080ULL, // 'Y'
    0xf8444443e0ULL, // 'Z'
    0x72108421c0ULL, // '['
    0x0410410400ULL, // '\'
    0x70842109c0ULL, // ']'
    0x22a2000000ULL, // '^'
    0x00000003e0ULL, // '_'
    0x4104000000ULL, // '`'
    0x001c17c5e0ULL, // 'a'
    0x842d98c7c0ULL, // 'b'
    0x001d0845c0ULL, // 'c'
    0x085b38c5e0ULL, // 'd'
    0x001d1fc1c0ULL, // 'e'
    0x3251c42100ULL, // 'f'
    0x001f18bc2eULL, // 'g'
    0x842d98c620ULL, // 'h'
    0x20184211c0ULL, // 'i'
    0x100c210a4cULL, // 'j'
    0x84254c5240ULL, // 'k'
    0x61084211c0ULL, // 'l'
    0x00355ac620ULL, // 'm'
    0x002d98c620ULL, // 'n'
    0x001d18c5c0ULL, // 'o'
    0x003d18fa10ULL, // 'p'
    0x001f18bc21ULL, // 'q'
    0x002d984200ULL, // 'r'
    0x001f0707c0ULL, // 's'
    0x42388424c0ULL, // 't'
    0x002318cda0ULL, // 'u'
    0x002318a880ULL, // 'v'
    0x00231ad540ULL, // 'w'
    0x0022a22a20ULL, // 'x'
    0x002318bc2eULL, // 'y'
    0x003e2223e0ULL, // 'z'
    0x1108821040ULL, // '{'
    0x2108421080ULL, // '|'
    0x4108221100ULL, // '}'
    0x0011510000ULL, // '~'
};

/** The glyph of \a c, '?' for characters outside printable ASCII. */
std::uint64_t
glyph (char c)
{
  const auto code = static_cast<unsigned char> (c);
  return code >= 32 && code < 127 ? GLYPHS[code - 32] : GLYPHS['?' - 32];
}

} // namespace

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
RGBImage::text (
    long x, long y, const std::string& text, const RGB& color, int scale, bool vertical)
{
  long advance = 0; // along the text, in pixels
  for (const char c : text) {
    const std::uint64_t bits = glyph (c);
    for (int row = 0; row < GLYPH_HEIGHT; ++row)
      for (int column = 0; column < GLYPH_WIDTH; ++column) {
        const int bit =
            (GLYPH_HEIGHT - 1 - row) * GLYPH_WIDTH + (GLYPH_WIDTH - 1 - column);
        if (((bits >> bit) & 1) == 0)
          continue;
        const long along = advance + column * scale, across = row * scale;
        if (vertical)
          fill (x + across, y - along - scale, scale, scale, color);
        else
          fill (x + along, y + across, scale, scale, color);
      }
    advance += (GLYPH_WIDTH + GLYPH_GAP) * scale;
  }
}

long
RGBImage::textWidth (const std::string& text, int scale)
{
  return text.empty()
             ? 0
             : static_cast<long> (text.size()) * (GLYPH_WIDTH + GLYPH_GAP) * scale -
                   GLYPH_GAP * scale;
}

long
RGBImage::textHeight (int scale)
{
  return GLYPH_HEIGHT * scale;
}

void
RGBImage::savePNG (const std::string& path) const
{
  replaceFileAtomically (path, [this] (const std::string& temporary) {
    pcl::io::saveRgbPNGFile (
        temporary, rgb_.data(), static_cast<int> (width_), static_cast<int> (height_));
    // PCL's writer says nothing when it fails: check that a PNG was written.
    std::ifstream written (temporary, std::ios::binary);
    char signature[4] = {};
    written.read (signature, 4);
    return written && signature[1] == 'P' && signature[2] == 'N' && signature[3] == 'G';
  });
}

} // namespace tda
} // namespace pcl
