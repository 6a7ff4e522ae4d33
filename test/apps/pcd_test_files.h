#pragma once

// PCD files for the tests of the tools' input layer: a header writer, and malformed
// files with the words of the message that must refuse each.

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace pcl {
namespace tda {
namespace test {

/** Writes \a content to \a path, replacing it. */
inline void
writeFile (const std::string& path, const std::string& content)
{
  std::ofstream (path, std::ios::binary | std::ios::trunc) << content;
}

/** A PCD v0.7 header of one value per field; \a width 0 means \a points. */
inline std::string
pcdHeader (const std::string& fields,
           const std::string& sizes,
           const std::string& types,
           std::uint64_t points,
           const std::string& data,
           std::uint64_t width = 0,
           std::uint64_t height = 1)
{
  std::string counts = "1";
  for (const char c : fields)
    if (c == ' ')
      counts += " 1";
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS " + fields +
         "\nSIZE " + sizes + "\nTYPE " + types + "\nCOUNT " + counts + "\nWIDTH " +
         std::to_string (width == 0 ? points : width) + "\nHEIGHT " +
         std::to_string (height) + "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
         std::to_string (points) + "\nDATA " + data + "\n";
}

/** Malformed PCD files, each with words of the message that refuses it. */
inline std::vector<std::pair<std::string, std::string>>
malformedPCDFiles ()
{
  const std::string fields = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  const std::string ascii_points = "1 2 3\n4 5 6\n7 8 9\n1 1 1\n2 2 2\n";
  const auto xyz = [] (std::uint64_t points, const std::string& data) {
    return pcdHeader ("x y z", "4 4 4", "F F F", points, data);
  };
  std::string double_beyond_float (24, '\0');
  const double huge = 1e300;
  std::memcpy (&double_beyond_float[0], &huge, sizeof (huge));
  /** Binary compressed data: its two sizes and \a bytes bytes. */
  const auto compressed = [] (std::uint32_t compressed_size,
                              std::uint32_t uncompressed_size,
                              std::size_t bytes) {
    std::string data (8 + bytes, '\0');
    for (int i = 0; i < 4; ++i) {
      data[i] = static_cast<char> (compressed_size >> (8 * i));
      data[4 + i] = static_cast<char> (uncompressed_size >> (8 * i));
    }
    return data;
  };
  return {
      {"", "the file is empty"},
      {"this is not a point cloud\n", "'this' is not a PCD header line"},
      {"VERSION .7\n" + fields + "WIDTH -5\nHEIGHT 1\nPOINTS -5\nDATA ascii\n" +
           ascii_points,
       "WIDTH needs whole numbers from 0 to 4294967295, not '-5'"},
      {"VERSION .7\n" + fields + "WIDTH 5\nHEIGHT 1\nPOINTS 4000000000\nDATA ascii\n" +
           ascii_points,
       "WIDTH x HEIGHT = 5 x 1 is not POINTS 4000000000"},
      {xyz (4000000000u, "ascii") + ascii_points,
       "POINTS 4000000000 is over the 2147483647 points"},
      {pcdHeader ("x y z", "4 4 4", "F F F", 5, "ascii", 5, 2) + ascii_points,
       "WIDTH x HEIGHT = 5 x 2 is not POINTS 5"},
      {pcdHeader ("x y z", "4 4 3", "F F F", 5, "ascii") + ascii_points,
       "field 'z' has SIZE 3"},
      {pcdHeader ("x y z", "4 4 4", "F F X", 5, "ascii") + ascii_points,
       "field 'z' has TYPE 'X'"},
      {pcdHeader ("x y z", "4 4 2", "F F F", 5, "ascii") + ascii_points,
       "field 'z' has TYPE 'F' and SIZE 2, which is no PCD type"},
      {pcdHeader ("x y z", "4 4 four", "F F F", 5, "ascii") + ascii_points,
       "SIZE needs whole numbers from 0 to 8, not 'four'"},
      {"FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 0 1\nPOINTS 5\nDATA ascii\n" +
           ascii_points,
       "field 'y' has COUNT 0"},
      {"FIELDS x y z\nSIZE 4 4\nTYPE F F F\nPOINTS 5\nDATA ascii\n" + ascii_points,
       "SIZE has 2 values for 3 fields"},
      {fields + "POINTS 5\nWIDTH 5\nDATA ascii\n" + ascii_points,
       "WIDTH is repeated or out of order"},
      {fields + "FIELDS x y z\nPOINTS 5\nDATA ascii\n" + ascii_points,
       "FIELDS is repeated or out of order"},
      {"FIELDS x y x\nSIZE 4 4 4\nTYPE F F F\nPOINTS 5\nDATA ascii\n" + ascii_points,
       "field 'x' is named twice"},
      {"SIZE 4 4 4\nTYPE F F F\nPOINTS 5\nDATA ascii\n", "SIZE before FIELDS"},
      {fields + "POINTS 5\n", "the header has no DATA line"},
      {fields + "POINTS 5\nDATA text\n" + ascii_points,
       "DATA must be ascii, binary or binary_compressed"},
      {"FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nVIEWPOINT 0 0 0 1\nPOINTS 5\nDATA "
       "ascii\n" +
           ascii_points,
       "VIEWPOINT needs 7 numbers"},
      {fields + "  \nPOINTS 5\nDATA ascii\n" + ascii_points, "line 5 is blank"},
      {fields + "WIDTH 5\nDATA ascii\n" + ascii_points, "DATA before POINTS"},
      {fields + "HEIGHT 1\nPOINTS 5\nDATA ascii\n" + ascii_points,
       "HEIGHT without WIDTH"},
      {"# " + std::string (70000, 'a') + "\n" + xyz (5, "ascii") + ascii_points,
       "line 1 is over 65536 characters long"},
      {xyz (5, "binary") + std::string (30, '\0'),
       "5 points of 12 bytes need 60 bytes of binary data, the file has 30"},
      {xyz (5, "binary") + std::string (60, '\0') + "0123456789",
       "the file has 10 bytes after the 60 of its 5 points, and they are not zeros"},
      {xyz (5, "binary") + "POINTS 999999999\n" + std::string (43, '\0'),
       "the data after DATA starts with 'POINTS'"},
      {xyz (5, "binary_compressed") + "1234", "the compressed data has no sizes"},
      {xyz (5, "binary_compressed") + compressed (1000, 60, 10),
       "the compressed data claims 1000 bytes, the file has 10"},
      {xyz (5, "binary_compressed") + compressed (10, 59, 10),
       "decompresses to 59 bytes, not the 60 of 5 points"},
      {xyz (1000, "binary_compressed") + compressed (10, 12000, 10),
       "1000 points (12000 bytes) cannot come from 10 compressed bytes"},
      {xyz (1000, "ascii") + ascii_points,
       "1000 points of 3 values cannot fit in 30 bytes of ASCII data"},
      {xyz (5, "ascii") + "1.000 2.000 3.000\n4.000 5.000 6.000\n7.000 8.000 9.000\n",
       "the ASCII data has 3 of the 5 points"},
      {xyz (5, "ascii") + "1 2 3\n4 5\n7 8 9 1\n1 1 1\n2 2 2\n",
       "point 2 of the ASCII data has 2 values, not 3"},
      {xyz (5, "ascii") + "1 2 3\n4 5 abc\n7 8 9\n1 1 1\n2 2 2\n",
       "point 2 of the ASCII data has 'abc', which is not a number"},
      {xyz (5, "ascii") + ascii_points + "3 3 3\n",
       "the ASCII data has more lines than the 5 points"},
      {pcdHeader ("x y", "4 4", "F F", 5, "ascii") + "1 2\n1 2\n1 2\n1 2\n1 2\n",
       "has no 'z' field"},
      {"FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 3 1 1\nPOINTS 1\nDATA ascii\n1 2 "
       "3 4 5\n",
       "field 'x' has 3 values per point (COUNT), not 1"},
      {"FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 2000000000\nPOINTS 1\nDATA "
       "binary\n",
       "the fields take over 4294967295 bytes per point"},
      {pcdHeader ("x y z", "8 8 8", "F F F", 1, "binary") + double_beyond_float,
       "point 0 has x = 1e+300, beyond the range of a float"},
      {pcdHeader ("x y z", "8 8 8", "F F F", 200000000, "binary") +
           std::string (24, '\0'),
       "200000000 points of 24 bytes are over the 4294967295 bytes"},
  };
}

} // namespace test
} // namespace tda
} // namespace pcl
