#include <pcl/common/io.h>
#include <pcl/tda/apps/pcd_file_check.h>
#include <pcl/exceptions.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace pcl {
namespace tda {

namespace {

/** Header and data lines longer than this are refused (or, after DATA, cut). */
constexpr std::size_t MAX_LINE = 65536;

/** LZF turns 3 bytes into at most 264 (its longest back reference). */
constexpr std::uint64_t MAX_LZF_EXPANSION = 88;

/** The header keywords in the order of PCD v0.7 (COLUMNS: FIELDS of old files). */
const std::array<const char*, 11> KEYWORDS = {"VERSION",
                                              "FIELDS",
                                              "COLUMNS",
                                              "SIZE",
                                              "TYPE",
                                              "COUNT",
                                              "WIDTH",
                                              "HEIGHT",
                                              "VIEWPOINT",
                                              "POINTS",
                                              "DATA"};

/** Reads one line without its '\n' into \a line, keeping at most MAX_LINE
 * characters; \a cut tells whether more were skipped. False at the end of the
 * file. */
bool
readLine (std::istream& in, std::string& line, bool& cut)
{
  using Traits = std::char_traits<char>;
  std::streambuf& buffer = *in.rdbuf(); // faster than in.get(), for the ASCII data
  line.clear();
  cut = false;
  int c = buffer.sbumpc();
  if (c == Traits::eof())
    return false;
  for (; c != Traits::eof() && c != '\n'; c = buffer.sbumpc()) {
    if (line.size() < MAX_LINE)
      line.push_back (static_cast<char> (c));
    else
      cut = true;
  }
  return true;
}

/** Calls \a visit (a std::string_view) on each word of \a line as PCL's reader
 * splits it: trimmed of white space, then split at spaces, tabs and CRs (so a
 * vertical tab inside stays in a word). */
template <typename Visit>
void
forEachWord (std::string_view line, Visit visit)
{
  constexpr std::string_view WHITE_SPACE = " \t\r\n\v\f";
  constexpr std::string_view SEPARATORS = " \t\r";
  const auto first = line.find_first_not_of (WHITE_SPACE);
  if (first == std::string_view::npos)
    return;
  const std::string_view trimmed =
      line.substr (first, line.find_last_not_of (WHITE_SPACE) + 1 - first);
  for (auto begin = std::size_t{0}; begin != std::string_view::npos;) {
    const auto end = trimmed.find_first_of (SEPARATORS, begin);
    visit (trimmed.substr (begin, end - begin));
    begin = trimmed.find_first_not_of (SEPARATORS, end);
  }
}

/** The words of \a line (forEachWord()). */
std::vector<std::string>
words (const std::string& line)
{
  std::vector<std::string> result;
  forEachWord (line, [&result] (std::string_view word) { result.emplace_back (word); });
  return result;
}

/** The index of \a word in KEYWORDS, or -1. PCL takes every word that starts with a
 * keyword for it; \a prefix_only asks that question. */
int
keywordIndex (const std::string& word, bool prefix_only = false)
{
  for (std::size_t k = 0; k < KEYWORDS.size(); ++k)
    if (prefix_only ? word.rfind (KEYWORDS[k], 0) == 0 : word == KEYWORDS[k])
      return static_cast<int> (k);
  return -1;
}

/** \a word in quotes for a message: at most 32 characters, the unprintable ones as
 * '?'. */
std::string
quote (const std::string& word)
{
  std::string shown = "'";
  for (std::size_t i = 0; i < word.size() && i < 32; ++i)
    shown += std::isprint (static_cast<unsigned char> (word[i])) ? word[i] : '?';
  return shown + (word.size() > 32 ? "...'" : "'");
}

/** \a word as a whole decimal number in [0, maximum]. */
std::uint64_t
parseCount (const std::string& word,
            std::uint64_t maximum,
            const std::string& keyword,
            std::size_t line)
{
  const bool digits = !word.empty() && word.size() <= 19 &&
                      std::all_of (word.begin(), word.end(), [] (char c) {
                        return c >= '0' && c <= '9';
                      });
  const std::uint64_t value = digits ? std::strtoull (word.c_str(), nullptr, 10) : 0;
  if (!digits || value > maximum)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "line " << line << ": " << keyword
                                 << " needs whole numbers from 0 to " << maximum
                                 << ", not " << quote (word));
  return value;
}

/** True when \a word is a whole number, as strtod reads it (nan and inf too).
 * std::from_chars first, several times faster: what it reads whole, strtod does;
 * strtod for the rest (a leading '+', hexadecimal). */
bool
isNumber (std::string_view word)
{
  if (word.empty())
    return false;
  double value;
  if (std::from_chars (word.data(), word.data() + word.size(), value).ptr ==
      word.data() + word.size())
    return true;
  const std::string text (word);
  char* end = nullptr;
  std::strtod (text.c_str(), &end);
  return end == text.c_str() + text.size();
}

/** Little-endian 32-bit unsigned integer at \a bytes. */
std::uint64_t
littleEndian32 (const unsigned char* bytes)
{
  return bytes[0] | (bytes[1] << 8) | (bytes[2] << 16) |
         (static_cast<std::uint64_t> (bytes[3]) << 24);
}

/** The header lines, parsed in order into \a layout. */
class HeaderParser {
public:
  explicit HeaderParser (PCDLayout& layout) : layout_ (layout) {}

  /** Takes line number \a number; true once DATA has been read. */
  bool
  parse (const std::vector<std::string>& line, std::size_t number)
  {
    number_ = number;
    const int keyword = keywordIndex (line[0]);
    if (keyword < 0)
      fail (quote (line[0]) + " is not a PCD header line");
    const std::string name = KEYWORDS[keyword];
    // FIELDS and COLUMNS share a rank.
    const int rank = keyword <= 1 ? keyword : keyword - 1;
    if (rank <= last_rank_)
      fail (name + " is repeated or out of order (PCD v0.7 order: VERSION, FIELDS, "
                   "SIZE, TYPE, COUNT, WIDTH, HEIGHT, VIEWPOINT, POINTS, DATA)");
    last_rank_ = rank;
    const std::vector<std::string> values (line.begin() + 1, line.end());
    auto& fields = layout_.header.fields;
    if (name == "FIELDS" || name == "COLUMNS")
      parseFields (values);
    else if (name == "SIZE" || name == "TYPE" || name == "COUNT")
      parseFieldValues (name, values);
    else if (name == "WIDTH" || name == "HEIGHT" || name == "POINTS") {
      if (fields.empty() || sizes_.empty())
        fail (name + " before FIELDS and SIZE");
      if (values.size() != 1)
        fail (name + " needs one number");
      const std::uint64_t value = parseCount (values[0], 0xffffffffu, name, number_);
      (name == "WIDTH"    ? width_
       : name == "HEIGHT" ? height_
                          : points_) = static_cast<std::int64_t> (value);
    }
    else if (name == "VIEWPOINT") {
      if (values.size() != 7 || !std::all_of (values.begin(), values.end(), isNumber))
        fail ("VIEWPOINT needs 7 numbers (tx ty tz qw qx qy qz)");
    }
    else if (name == "DATA") {
      if (values.size() != 1 || (values[0] != "ascii" && values[0] != "binary" &&
                                 values[0] != "binary_compressed"))
        fail ("DATA must be ascii, binary or binary_compressed");
      layout_.data = values[0] == "ascii"    ? PCDData::ASCII
                     : values[0] == "binary" ? PCDData::BINARY
                                             : PCDData::BINARY_COMPRESSED;
      finish();
      return true;
    }
    return false;
  }

  /** The number of values per point (the sum of the counts). */
  std::uint64_t
  valuesPerPoint () const
  {
    std::uint64_t values = 0;
    for (const auto& field : layout_.header.fields)
      values += field.count;
    return values;
  }

  /** WIDTH x HEIGHT. */
  std::uint64_t
  points () const
  {
    return static_cast<std::uint64_t> (layout_.header.width) * layout_.header.height;
  }

private:
  [[noreturn]] void
  fail (const std::string& problem) const
  {
    PCL_THROW_EXCEPTION (pcl::IOException, "line " << number_ << ": " << problem);
  }

  void
  parseFields (const std::vector<std::string>& names)
  {
    if (names.empty())
      fail ("FIELDS names no field");
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] != "_" &&
          std::find (names.begin(), names.begin() + i, names[i]) != names.begin() + i)
        fail ("field " + quote (names[i]) + " is named twice");
      pcl::PCLPointField field;
      field.name = names[i];
      field.count = 1;
      layout_.header.fields.push_back (field);
    }
  }

  /** SIZE, TYPE or COUNT: one value per field. */
  void
  parseFieldValues (const std::string& name, const std::vector<std::string>& values)
  {
    auto& fields = layout_.header.fields;
    if (fields.empty())
      fail (name + " before FIELDS");
    if (values.size() != fields.size())
      fail (name + " has " + std::to_string (values.size()) + " values for " +
            std::to_string (fields.size()) + " fields");
    if (name == "TYPE" && sizes_.empty())
      fail ("TYPE before SIZE");
    if (name == "COUNT" && !types_known_)
      fail ("COUNT before TYPE");
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (name == "SIZE") {
        const std::uint64_t size = parseCount (values[i], 8, name, number_);
        if (size != 1 && size != 2 && size != 4 && size != 8)
          fail ("field " + quote (fields[i].name) + " has SIZE " + values[i] +
                ": sizes are 1, 2, 4 or 8");
        sizes_.push_back (static_cast<int> (size));
      }
      else if (name == "TYPE") {
        const int type = values[i].size() == 1 && std::strchr ("FIUB", values[i][0])
                             ? pcl::getFieldType (sizes_[i], values[i][0])
                             : -1;
        if (type < 0)
          fail ("field " + quote (fields[i].name) + " has TYPE " + quote (values[i]) +
                " and SIZE " + std::to_string (sizes_[i]) + ", which is no PCD type");
        fields[i].datatype = static_cast<std::uint8_t> (type);
      }
      else {
        fields[i].count = static_cast<pcl::uindex_t> (
            parseCount (values[i], MAX_PCD_DATA_BYTES, name, number_));
        if (fields[i].count == 0)
          fail ("field " + quote (fields[i].name) + " has COUNT 0");
      }
    }
    types_known_ = types_known_ || name == "TYPE";
  }

  /** Checks the required lines and the sizes; fills the layout. */
  void
  finish ()
  {
    if (!types_known_)
      fail ("DATA before FIELDS, SIZE and TYPE");
    if (points_ < 0)
      fail ("DATA before POINTS");
    if (height_ >= 0 && width_ < 0)
      fail ("HEIGHT without WIDTH");
    auto& header = layout_.header;
    header.width = static_cast<pcl::uindex_t> (width_ < 0 ? points_ : width_);
    header.height = static_cast<pcl::uindex_t> (height_ < 0 ? 1 : height_);
    if (points() != static_cast<std::uint64_t> (points_))
      fail ("WIDTH x HEIGHT = " + std::to_string (header.width) + " x " +
            std::to_string (header.height) + " is not POINTS " +
            std::to_string (points_));
    if (points() > MAX_PCD_POINTS)
      fail ("POINTS " + std::to_string (points_) + " is over the " +
            std::to_string (MAX_PCD_POINTS) + " points PCL can index");
    std::uint64_t offset = 0;
    for (std::size_t i = 0; i < header.fields.size(); ++i) {
      header.fields[i].offset = static_cast<pcl::uindex_t> (offset);
      offset += static_cast<std::uint64_t> (sizes_[i]) * header.fields[i].count;
      if (offset > MAX_PCD_DATA_BYTES)
        fail ("the fields take over " + std::to_string (MAX_PCD_DATA_BYTES) +
              " bytes per point");
    }
    if (offset * points() > MAX_PCD_DATA_BYTES)
      fail (std::to_string (points()) + " points of " + std::to_string (offset) +
            " bytes are over the " + std::to_string (MAX_PCD_DATA_BYTES) +
            " bytes PCL's reader can hold");
    header.point_step = static_cast<pcl::uindex_t> (offset);
    header.row_step = header.point_step * header.width;
  }

  PCDLayout& layout_;
  std::size_t number_ = 0;
  int last_rank_ = -1;
  std::vector<int> sizes_;
  bool types_known_ = false;
  std::int64_t width_ = -1, height_ = -1, points_ = -1;
};

/** PCL's reader goes on reading header lines after DATA as long as they are empty
 * or comments: refuses data that starts with what it would take for a header line.
 */
void
checkNoHeaderAfterData (std::istream& file)
{
  std::string line;
  bool cut = false;
  while (readLine (file, line, cut)) {
    if (line.empty())
      continue;
    const std::vector<std::string> first = words (line.substr (0, 64));
    if (first.empty() || first[0][0] != '#') {
      if (!first.empty() && keywordIndex (first[0], true) >= 0)
        PCL_THROW_EXCEPTION (pcl::IOException,
                             "the data after DATA starts with "
                                 << quote (first[0])
                                 << ", which PCL's reader takes for a header line");
      return;
    }
  }
}

/** One line of numbers per point, as many as \a values, and nothing else. */
void
checkASCIIData (std::istream& file, std::uint64_t points, std::uint64_t values)
{
  std::string line;
  bool cut = false;
  std::uint64_t point = 0;
  while (readLine (file, line, cut)) {
    if (line.empty())
      continue; // PCL's reader skips empty lines
    std::uint64_t count = 0;
    std::string_view not_a_number;
    forEachWord (line, [&] (std::string_view number) {
      ++count;
      if (not_a_number.empty() && !isNumber (number))
        not_a_number = number;
    });
    if (point == points) {
      if (count == 0)
        continue;
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "the ASCII data has more lines than the " << points
                                                                     << " points");
    }
    ++point;
    if (cut)
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "point " << point << " of the ASCII data is over "
                                    << MAX_LINE << " characters long");
    if (count != values)
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "point " << point << " of the ASCII data has " << count
                                    << " values, not " << values);
    if (!not_a_number.empty())
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "point " << point << " of the ASCII data has "
                                    << quote (std::string (not_a_number))
                                    << ", which is not a number");
  }
  if (point < points)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "the ASCII data has " << point << " of the " << points
                                               << " points");
}

/** True when the \a size bytes of \a file from \a offset on are all zeros. */
bool
allZeros (std::istream& file, std::uint64_t offset, std::uint64_t size)
{
  file.clear();
  file.seekg (static_cast<std::streamoff> (offset));
  std::vector<char> chunk (65536);
  while (size > 0) {
    const auto length =
        static_cast<std::streamsize> (std::min<std::uint64_t> (size, chunk.size()));
    if (!file.read (chunk.data(), length))
      return false;
    if (std::any_of (
            chunk.begin(), chunk.begin() + length, [] (char c) { return c != 0; }))
      return false;
    size -= static_cast<std::uint64_t> (length);
  }
  return true;
}

/** The binary data: the header's points, then nothing or zeros (PCL's writer of
 * PCLPointCloud2 pads the file with up to a page of zeros, which its reader ignores);
 * or their compressed form, whose size goes into \a layout. */
void
checkBinaryData (std::istream& file,
                 PCDLayout& layout,
                 std::uint64_t points,
                 std::uint64_t available)
{
  const std::uint64_t bytes = points * layout.header.point_step;
  if (layout.data == PCDData::BINARY) {
    if (available < bytes)
      PCL_THROW_EXCEPTION (
          pcl::IOException,
          points << " points of " << layout.header.point_step << " bytes need " << bytes
                 << " bytes of binary data, the file has " << available);
    if (!allZeros (file, layout.data_offset + bytes, available - bytes))
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "the file has " << available - bytes << " bytes after the "
                                           << bytes << " of its " << points
                                           << " points, and they are not zeros");
    return;
  }
  std::array<unsigned char, 8> sizes{};
  file.clear();
  file.seekg (static_cast<std::streamoff> (layout.data_offset));
  if (available < sizes.size() ||
      !file.read (reinterpret_cast<char*> (sizes.data()), sizes.size()))
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "the compressed data has no sizes (" << available
                                                              << " bytes)");
  const std::uint64_t compressed = littleEndian32 (sizes.data());
  const std::uint64_t uncompressed = littleEndian32 (sizes.data() + 4);
  // PCL's writer pads the file to whole pages.
  if (compressed + sizes.size() > available)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "the compressed data claims " << compressed
                                                       << " bytes, the file has "
                                                       << available - sizes.size());
  if (uncompressed != bytes)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "the compressed data decompresses to "
                             << uncompressed << " bytes, not the " << bytes << " of "
                             << points << " points");
  if (bytes > compressed * MAX_LZF_EXPANSION)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         points << " points (" << bytes << " bytes) cannot come from "
                                << compressed << " compressed bytes");
  layout.compressed_size = compressed;
}

} // namespace

PCDLayout
readPCDLayout (std::istream& file, std::uint64_t file_size)
{
  PCDLayout layout;
  HeaderParser parser (layout);
  std::string line;
  bool cut = false;
  bool data_line = false;
  for (std::size_t number = 1; !data_line; ++number) {
    if (!readLine (file, line, cut))
      PCL_THROW_EXCEPTION (
          pcl::IOException,
          (number == 1 ? "the file is empty" : "the header has no DATA line"));
    if (cut)
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "line " << number << " is over " << MAX_LINE
                                   << " characters long");
    if (line.empty())
      continue; // as PCL's reader
    const std::vector<std::string> line_words = words (line);
    if (line_words.empty())
      PCL_THROW_EXCEPTION (pcl::IOException, "line " << number << " is blank");
    if (line_words[0][0] == '#')
      continue;
    data_line = parser.parse (line_words, number);
  }
  const std::streamoff offset = file.tellg();
  layout.data_offset = offset < 0 ? file_size : static_cast<std::uint64_t> (offset);
  const std::uint64_t points = parser.points();
  if (points == 0)
    return layout;
  checkNoHeaderAfterData (file);
  const std::uint64_t available =
      file_size > layout.data_offset ? file_size - layout.data_offset : 0;
  if (layout.data != PCDData::ASCII) {
    checkBinaryData (file, layout, points, available);
    return layout;
  }
  // A value takes a character and a separator at least.
  const std::uint64_t values = parser.valuesPerPoint();
  if (available + 1 < 2 * points * values)
    PCL_THROW_EXCEPTION (pcl::IOException,
                         points << " points of " << values << " values cannot fit in "
                                << available << " bytes of ASCII data");
  file.clear();
  file.seekg (static_cast<std::streamoff> (layout.data_offset));
  checkASCIIData (file, points, values);
  return layout;
}

} // namespace tda
} // namespace pcl
