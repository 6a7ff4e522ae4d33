#include <pcl/common/io.h>
#include <pcl/tda/apps/pcd_data.h>
#include <pcl/exceptions.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

namespace {

/** White space as the C locale has it (PCD data separates values by it). */
bool
isSpace (char c)
{
  return std::isspace (static_cast<unsigned char> (c)) != 0;
}

/** The token that starts at \a begin, for a message: at most 32 characters. */
std::string
token (const char* begin)
{
  std::size_t length = 0;
  while (length < 32 && begin[length] != '\0' && !isSpace (begin[length]))
    ++length;
  return "'" + std::string (begin, length) + "'";
}

/** Stores \a value as an integer of type \a Integer at \a out when it is whole and in
 * the type's range. */
template <typename Integer>
bool
storeInteger (double value, std::uint8_t* out)
{
  // The bounds as doubles: the lowest is exact, the highest rounds up to 2^bits.
  constexpr double lowest =
      static_cast<double> (std::numeric_limits<Integer>::lowest());
  constexpr double above =
      2.0 * (static_cast<double> (std::numeric_limits<Integer>::max() / 2) + 1.0);
  if (!(value >= lowest && value < above) || value != std::floor (value))
    return false;
  const auto integer = static_cast<Integer> (value);
  std::memcpy (out, &integer, sizeof (integer));
  return true;
}

/** Reads the number at \a text (in a text that ends at \a text_end) as a value of
 * type \a datatype into \a out; \a text moves past it. False when the number does
 * not fit the type. */
bool
readValue (const char*& text,
           const char* text_end,
           std::uint8_t datatype,
           std::uint8_t* out)
{
  // std::from_chars first, several times faster than strtof and strtod and as
  // exact (the correctly rounded value); they read what it does not read whole or
  // in range (a leading '+', hexadecimal, overflow, underflow).
  if (datatype == pcl::PCLPointField::FLOAT32 ||
      datatype == pcl::PCLPointField::FLOAT64) {
    const auto read = [&] (auto value) {
      const auto [ptr, error] = std::from_chars (text, text_end, value);
      if (error != std::errc{} || ptr == text || (*ptr != '\0' && !isSpace (*ptr)))
        return false;
      text = ptr;
      std::memcpy (out, &value, sizeof (value));
      return true;
    };
    if (datatype == pcl::PCLPointField::FLOAT32 ? read (0.0f) : read (0.0))
      return true;
  }
  char* end = nullptr;
  errno = 0;
  if (datatype == pcl::PCLPointField::FLOAT32) {
    const float value = std::strtof (text, &end);
    text = end;
    std::memcpy (out, &value, sizeof (value));
    return errno != ERANGE || !std::isinf (value); // an underflow is a tiny value
  }
  // Whole numbers of up to 64 bits as they are, before strtod rounds them.
  if (datatype == pcl::PCLPointField::INT64 || datatype == pcl::PCLPointField::UINT64) {
    const bool is_signed = datatype == pcl::PCLPointField::INT64;
    const long long signed_value = is_signed ? std::strtoll (text, &end, 10) : 0;
    const unsigned long long unsigned_value =
        is_signed || *text == '-' ? 0 : std::strtoull (text, &end, 10);
    if (end != nullptr && errno == 0 && (*end == '\0' || isSpace (*end))) {
      text = end;
      if (is_signed)
        std::memcpy (out, &signed_value, sizeof (signed_value));
      else
        std::memcpy (out, &unsigned_value, sizeof (unsigned_value));
      return true;
    }
    errno = 0;
  }
  const double value = std::strtod (text, &end);
  text = end;
  switch (datatype) {
  case pcl::PCLPointField::FLOAT64:
    std::memcpy (out, &value, sizeof (value));
    return errno != ERANGE || !std::isinf (value);
  case pcl::PCLPointField::INT8:
    return storeInteger<std::int8_t> (value, out);
  case pcl::PCLPointField::UINT8:
    return storeInteger<std::uint8_t> (value, out);
  case pcl::PCLPointField::INT16:
    return storeInteger<std::int16_t> (value, out);
  case pcl::PCLPointField::UINT16:
    return storeInteger<std::uint16_t> (value, out);
  case pcl::PCLPointField::INT32:
    return storeInteger<std::int32_t> (value, out);
  case pcl::PCLPointField::UINT32:
    return storeInteger<std::uint32_t> (value, out);
  case pcl::PCLPointField::INT64:
    return storeInteger<std::int64_t> (value, out);
  default:
    return storeInteger<std::uint64_t> (value, out);
  }
}

/** The ASCII data: one number per value, the points one after the other (the layout
 * check has made sure of the lines and that every word is a number). */
void
readASCII (const std::string& text, pcl::PCLPointCloud2& cloud)
{
  const char* at = text.c_str();
  const char* const text_end = at + text.size();
  const std::size_t points = std::size_t{cloud.width} * cloud.height;
  for (std::size_t p = 0; p < points; ++p)
    for (const auto& field : cloud.fields) {
      const int size = pcl::getFieldSize (field.datatype);
      std::uint8_t* out = &cloud.data[p * cloud.point_step + field.offset];
      for (std::uint32_t c = 0; c < field.count; ++c, out += size) {
        while (isSpace (*at))
          ++at;
        const char* number = at;
        const bool fits =
            *number != '\0' && readValue (at, text_end, field.datatype, out);
        if (!fits || at == number || (*at != '\0' && !isSpace (*at)))
          PCL_THROW_EXCEPTION (pcl::IOException,
                               "point " << p + 1 << " of the ASCII data has "
                                        << token (number) << " for field '"
                                        << field.name << "', which is not a value of "
                                        << "its type");
      }
    }
}

/** Binary data stored one field after the other, for all points, as PCL's
 * binary_compressed writer does: back to one point after the other. */
void
interleaveFields (const std::vector<std::uint8_t>& by_field, pcl::PCLPointCloud2& cloud)
{
  const std::size_t points = std::size_t{cloud.width} * cloud.height;
  const std::uint8_t* in = by_field.data();
  for (const auto& field : cloud.fields) {
    const std::size_t bytes =
        std::size_t{field.count} * pcl::getFieldSize (field.datatype);
    std::uint8_t* out = cloud.data.data() + field.offset;
    for (std::size_t p = 0; p < points; ++p, in += bytes, out += cloud.point_step)
      std::memcpy (out, in, bytes);
  }
}

/** Whether no float or double of the cloud is NaN or infinite. */
bool
allFinite (const pcl::PCLPointCloud2& cloud)
{
  const std::size_t points = std::size_t{cloud.width} * cloud.height;
  for (const auto& field : cloud.fields) {
    const bool is_float = field.datatype == pcl::PCLPointField::FLOAT32;
    if (!is_float && field.datatype != pcl::PCLPointField::FLOAT64)
      continue;
    for (std::size_t p = 0; p < points; ++p)
      for (std::uint32_t c = 0; c < field.count; ++c) {
        const std::uint8_t* at = &cloud.data[p * cloud.point_step + field.offset];
        double value;
        if (is_float) {
          float single;
          std::memcpy (&single, at + c * sizeof (float), sizeof (float));
          value = single;
        }
        else
          std::memcpy (&value, at + c * sizeof (double), sizeof (double));
        if (!std::isfinite (value))
          return false;
      }
  }
  return true;
}

/** Reads \a size bytes of \a file into \a out. */
void
readBytes (std::istream& file, std::uint8_t* out, std::size_t size)
{
  if (!file.read (reinterpret_cast<char*> (out), static_cast<std::streamsize> (size)))
    PCL_THROW_EXCEPTION (pcl::IOException,
                         "the file ends before its " << size << " bytes of data");
}

} // namespace

bool
writePCDBinary (std::ostream& out,
                const pcl::PCLPointCloud2& cloud,
                const Eigen::Vector4f& origin,
                const Eigen::Quaternionf& orientation)
{
  std::vector<pcl::PCLPointField> fields;
  for (const auto& field : cloud.fields)
    if (field.name != "_")
      fields.push_back (field);
  std::string names, sizes, types, counts;
  std::size_t packed_step = 0;
  for (const auto& field : fields) {
    const int size = pcl::getFieldSize (field.datatype);
    names += " " + field.name;
    sizes += " " + std::to_string (size);
    types += std::string (" ") + pcl::getFieldType (field.datatype);
    counts += " " + std::to_string (field.count);
    packed_step += std::size_t{field.count} * size;
  }
  const std::size_t points = std::size_t{cloud.width} * cloud.height;
  out << "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS" << names
      << "\nSIZE" << sizes << "\nTYPE" << types << "\nCOUNT" << counts << "\nWIDTH "
      << cloud.width << "\nHEIGHT " << cloud.height << "\nVIEWPOINT " << origin.x()
      << " " << origin.y() << " " << origin.z() << " " << orientation.w() << " "
      << orientation.x() << " " << orientation.y() << " " << orientation.z()
      << "\nPOINTS " << points << "\nDATA binary\n";
  std::vector<char> data (points * packed_step);
  char* at = data.data();
  for (std::size_t p = 0; p < points; ++p)
    for (const auto& field : fields) {
      const std::size_t bytes =
          std::size_t{field.count} * pcl::getFieldSize (field.datatype);
      std::memcpy (at, &cloud.data[p * cloud.point_step + field.offset], bytes);
      at += bytes;
    }
  out.write (data.data(), static_cast<std::streamsize> (data.size()));
  return static_cast<bool> (out.flush());
}

bool
lzfDecompress (const std::uint8_t* in,
               std::size_t size,
               std::uint8_t* out,
               std::size_t out_size)
{
  const std::uint8_t* const in_end = in + size;
  std::uint8_t* const out_begin = out;
  std::uint8_t* const out_end = out + out_size;
  while (in < in_end) {
    const unsigned control = *in++;
    if (control < 32) { // a run of control + 1 bytes as they are
      const std::size_t length = control + 1;
      if (length > static_cast<std::size_t> (in_end - in) ||
          length > static_cast<std::size_t> (out_end - out))
        return false;
      std::memcpy (out, in, length);
      in += length;
      out += length;
      continue;
    }
    // A copy of earlier output: a length of 3 to 264 bytes, a distance of 1 to 8192.
    std::size_t length = control >> 5;
    if (length == 7) {
      if (in == in_end)
        return false;
      length += *in++;
    }
    length += 2;
    if (in == in_end)
      return false;
    const std::size_t distance = ((control & 0x1fu) << 8) + *in++ + 1;
    if (distance > static_cast<std::size_t> (out - out_begin) ||
        length > static_cast<std::size_t> (out_end - out))
      return false;
    for (const std::uint8_t* from = out - distance; length > 0; --length) // may overlap
      *out++ = *from++;
  }
  return out == out_end;
}

void
readPCDData (std::istream& file, const PCDLayout& layout, pcl::PCLPointCloud2& cloud)
{
  cloud = layout.header;
  const std::size_t bytes =
      std::size_t{cloud.width} * cloud.height * std::size_t{cloud.point_step};
  cloud.data.assign (bytes, 0);
  if (bytes == 0) // no points: nothing to read
    return;
  file.clear();
  file.seekg (static_cast<std::streamoff> (layout.data_offset));
  switch (layout.data) {
  case PCDData::BINARY:
    readBytes (file, cloud.data.data(), bytes);
    break;
  case PCDData::BINARY_COMPRESSED: {
    // After the two 4-byte sizes, which the layout check has read.
    const auto compressed = static_cast<std::size_t> (layout.compressed_size);
    file.seekg (static_cast<std::streamoff> (layout.data_offset + 8));
    std::vector<std::uint8_t> packed (compressed), by_field (bytes);
    readBytes (file, packed.data(), compressed);
    if (!lzfDecompress (packed.data(), compressed, by_field.data(), bytes))
      PCL_THROW_EXCEPTION (pcl::IOException,
                           "the compressed data is corrupt: it does not decompress to "
                               << bytes << " bytes");
    interleaveFields (by_field, cloud);
    break;
  }
  case PCDData::ASCII: {
    file.seekg (0, std::ios::end);
    const std::streamoff end = file.tellg();
    const auto length = static_cast<std::size_t> (
        end > static_cast<std::streamoff> (layout.data_offset)
            ? end - static_cast<std::streamoff> (layout.data_offset)
            : 0);
    std::string text (length, '\0');
    file.seekg (static_cast<std::streamoff> (layout.data_offset));
    readBytes (file, reinterpret_cast<std::uint8_t*> (&text[0]), length);
    readASCII (text, cloud);
    break;
  }
  }
  cloud.is_dense = allFinite (cloud);
}

} // namespace tda
} // namespace pcl
