// Tests of the tools' own PCD data reader (readPCDData(), lzfDecompress()) against
// PCL's reader and compressor: the same fields, bytes and is_dense on files of every
// encoding, every field type and count, organized and not, and on the real scans.

#include <pcl/common/io.h>
#include <pcl/io/lzf.h>
#include <pcl/io/pcd_io.h>
#include <pcl/tda/apps/cloud_files.h>
#include <pcl/tda/apps/pcd_data.h>
#include <pcl/tda/common/error_message.h>
#include <pcl/exceptions.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include "apps/pcd_test_files.h"
#include "test_data.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>

using namespace pcl::tda;

namespace {

std::string
temporaryPath (const std::string& name)
{
  return testing::TempDir() + "pcd_data_" +
         testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + name;
}

/** Writes a random value of \a datatype at \a out: integers over the type's whole
 * range (53 bits of 64-bit ones), floats over many magnitudes, NaN now and then. */
void
randomValue (std::uint8_t datatype, std::uint8_t* out, std::mt19937_64& random)
{
  const std::uint64_t bits = random();
  const auto store = [out] (auto value) { std::memcpy (out, &value, sizeof (value)); };
  const double magnitude =
      std::ldexp (std::uniform_real_distribution<double> (-1.0, 1.0) (random),
                  static_cast<int> (bits % 40) - 20);
  const bool nan = bits % 17 == 0;
  switch (datatype) {
  case pcl::PCLPointField::FLOAT32:
    return store (nan ? std::numeric_limits<float>::quiet_NaN()
                      : static_cast<float> (magnitude));
  case pcl::PCLPointField::FLOAT64:
    return store (nan ? std::numeric_limits<double>::quiet_NaN() : magnitude);
  case pcl::PCLPointField::INT64:
    // PCL's ASCII reader goes through a double: 64-bit values within its 53 bits.
    return store (static_cast<std::int64_t> (bits) >> 11);
  case pcl::PCLPointField::UINT64:
    return store (bits >> 11);
  default:
    std::memcpy (out, &bits, pcl::getFieldSize (datatype));
  }
}

/** A random cloud: x, y and z as floats, then up to four more fields of random types
 * and counts, organized when \a organized. */
pcl::PCLPointCloud2
randomCloud (std::mt19937_64& random, bool organized)
{
  const std::vector<std::uint8_t> types{pcl::PCLPointField::INT8,
                                        pcl::PCLPointField::UINT8,
                                        pcl::PCLPointField::INT16,
                                        pcl::PCLPointField::UINT16,
                                        pcl::PCLPointField::INT32,
                                        pcl::PCLPointField::UINT32,
                                        pcl::PCLPointField::INT64,
                                        pcl::PCLPointField::UINT64,
                                        pcl::PCLPointField::FLOAT32,
                                        pcl::PCLPointField::FLOAT64};
  pcl::PCLPointCloud2 cloud;
  std::uint32_t offset = 0;
  const auto add = [&] (const std::string& name, std::uint8_t datatype, int count) {
    pcl::PCLPointField field;
    field.name = name;
    field.offset = offset;
    field.datatype = datatype;
    field.count = static_cast<pcl::uindex_t> (count);
    cloud.fields.push_back (field);
    offset += static_cast<std::uint32_t> (count * pcl::getFieldSize (datatype));
  };
  for (const char* name : {"x", "y", "z"})
    add (name, pcl::PCLPointField::FLOAT32, 1);
  const int extra = static_cast<int> (random() % 5);
  for (int f = 0; f < extra; ++f)
    add ("field" + std::to_string (f),
         types[random() % types.size()],
         1 + static_cast<int> (random() % 3));
  cloud.point_step = offset;
  cloud.height = organized ? 1 + static_cast<pcl::uindex_t> (random() % 8) : 1;
  cloud.width = 1 + static_cast<pcl::uindex_t> (random() % 60);
  cloud.row_step = cloud.point_step * cloud.width;
  cloud.data.resize (std::size_t{cloud.row_step} * cloud.height);
  for (std::size_t p = 0; p < std::size_t{cloud.width} * cloud.height; ++p)
    for (const auto& field : cloud.fields)
      for (std::uint32_t c = 0; c < field.count; ++c)
        randomValue (field.datatype,
                     &cloud.data[p * cloud.point_step + field.offset +
                                 c * pcl::getFieldSize (field.datatype)],
                     random);
  return cloud;
}

/** Expects \a ours and PCL's \a reference to be the same cloud, byte for byte. */
void
expectSameCloud (const pcl::PCLPointCloud2& ours, const pcl::PCLPointCloud2& reference)
{
  ASSERT_EQ (ours.fields.size(), reference.fields.size());
  for (std::size_t f = 0; f < ours.fields.size(); ++f) {
    EXPECT_EQ (ours.fields[f].name, reference.fields[f].name);
    EXPECT_EQ (ours.fields[f].offset, reference.fields[f].offset);
    EXPECT_EQ (ours.fields[f].datatype, reference.fields[f].datatype);
    EXPECT_EQ (ours.fields[f].count, reference.fields[f].count);
  }
  EXPECT_EQ (ours.width, reference.width);
  EXPECT_EQ (ours.height, reference.height);
  EXPECT_EQ (ours.point_step, reference.point_step);
  EXPECT_EQ (ours.row_step, reference.row_step);
  EXPECT_EQ (ours.is_dense, reference.is_dense);
  ASSERT_EQ (ours.data.size(), reference.data.size());
  const auto differ =
      std::mismatch (ours.data.begin(), ours.data.end(), reference.data.begin());
  if (differ.first == ours.data.end())
    return;
  const std::size_t byte = differ.first - ours.data.begin();
  const auto field =
      std::find_if (ours.fields.rbegin(), ours.fields.rend(), [&] (const auto& f) {
        return f.offset <= byte % ours.point_step;
      });
  ADD_FAILURE() << "the data differ first at byte " << byte << ", point "
                << byte / ours.point_step << ", field '" << field->name << "' of type "
                << int (field->datatype);
}

/** readPCDData() on \a path, through the tools' input layer. */
pcl::PCLPointCloud2
readOurs (const std::string& path)
{
  pcl::PCLPointCloud2 cloud;
  loadPointCloudFile (path, cloud);
  return cloud;
}

/** The refusal of \a content by the tools' input layer, "" when it loads. */
std::string
refusal (const std::string& content)
{
  const std::string path = temporaryPath ("refused.pcd");
  pcl::tda::test::writeFile (path, content);
  try {
    readOurs (path);
  }
  catch (const pcl::IOException& error) {
    return errorMessage (error);
  }
  return "";
}

} // namespace

TEST (PCDData, SameAsPCLsReaderOnEveryEncodingAndType)
{
  std::mt19937_64 random (7);
  for (int trial = 0; trial < 60; ++trial) {
    const pcl::PCLPointCloud2 cloud = randomCloud (random, trial % 2 == 1);
    const std::string path = temporaryPath ("random.pcd");
    pcl::PCDWriter writer;
    for (int encoding = 0; encoding < 3; ++encoding) {
      SCOPED_TRACE ("trial " + std::to_string (trial) + ", encoding " +
                    std::to_string (encoding));
      std::remove (path.c_str()); // PCL's binary writer does not truncate a file
      const int written = encoding == 0   ? writer.writeASCII (path, cloud)
                          : encoding == 1 ? writer.writeBinary (path, cloud)
                                          : writer.writeBinaryCompressed (path, cloud);
      ASSERT_EQ (written, 0);
      pcl::PCLPointCloud2 reference;
      ASSERT_EQ (pcl::PCDReader().read (path, reference), 0);
      expectSameCloud (readOurs (path), reference);
    }
  }
}

TEST (PCDData, SameAsPCLsReaderWithPaddingFields)
{
  // PCL's binary writer keeps the padding of these point types as '_' fields.
  pcl::PointCloud<pcl::PointXYZRGBNormal> cloud;
  for (int i = 0; i < 40; ++i) {
    pcl::PointXYZRGBNormal point;
    point.getVector3fMap() = Eigen::Vector3f (0.1f * i, 1.0f / (i + 1), -0.5f * i);
    point.getNormalVector3fMap() = Eigen::Vector3f (0.0f, 0.6f, 0.8f);
    point.rgba = 0xff000000u | static_cast<std::uint32_t> (i * 12345);
    point.curvature = 0.01f * i;
    cloud.push_back (point);
  }
  const std::string path = temporaryPath ("padded.pcd");
  for (const bool binary : {true, false}) {
    ASSERT_EQ (pcl::io::savePCDFile (path, cloud, binary), 0);
    pcl::PCLPointCloud2 reference;
    ASSERT_EQ (pcl::PCDReader().read (path, reference), 0);
    expectSameCloud (readOurs (path), reference);
  }
}

TEST (PCDData, SameAsPCLsReaderOnTheRealScans)
{
  PCL_TDA_REQUIRE_DATA ("bunny.pcd");
  // ASCII, binary and binary_compressed files, organized (kinect_frame) and not.
  for (const char* name : {"bunny.pcd",
                           "car6.pcd",
                           "colored_cloud.pcd",
                           "kinect_frame.pcd",
                           "milk.pcd",
                           "milk_color.pcd",
                           "noisy_slice_displaced.pcd",
                           "rops_cloud.pcd",
                           "sac_plane_test.pcd",
                           "table_scene_mug_stereo_textured.pcd"}) {
    SCOPED_TRACE (name);
    pcl::PCLPointCloud2 reference;
    ASSERT_EQ (pcl::PCDReader().read (test::dataFile (name), reference), 0);
    expectSameCloud (readOurs (test::dataFile (name)), reference);
  }
}

/** Writes \a cloud with ours and with PCL's binary writer and expects PCL's reader
 * to read the same cloud and viewpoint from both files, and ours to read it too. */
template <typename PointT>
void
expectWrittenAsPCLWrites (const pcl::PointCloud<PointT>& cloud)
{
  const std::string ours_path = temporaryPath ("ours.pcd");
  const std::string pcl_path = temporaryPath ("pcl.pcd");
  savePointCloudFile (ours_path, cloud);
  std::remove (pcl_path.c_str());
  ASSERT_EQ (pcl::io::savePCDFileBinary (pcl_path, cloud), 0);
  pcl::PCLPointCloud2 ours, reference;
  Eigen::Vector4f ours_origin, reference_origin;
  Eigen::Quaternionf ours_orientation, reference_orientation;
  int version = 0;
  ASSERT_EQ (
      pcl::PCDReader().read (ours_path, ours, ours_origin, ours_orientation, version),
      0);
  ASSERT_EQ (pcl::PCDReader().read (
                 pcl_path, reference, reference_origin, reference_orientation, version),
             0);
  expectSameCloud (ours, reference);
  EXPECT_EQ (ours_origin, reference_origin);
  EXPECT_EQ (ours_orientation.coeffs(), reference_orientation.coeffs());
  expectSameCloud (readOurs (ours_path), reference);
}

TEST (PCDData, WritesWhatPCLsBinaryWriterWrites)
{
  std::mt19937 random (11);
  std::uniform_real_distribution<float> unit (-1.0f, 1.0f);
  for (const std::uint32_t width : {1u, 7u, 300u}) {
    SCOPED_TRACE ("width " + std::to_string (width));
    pcl::PointCloud<pcl::PointXYZRGBL> labelled;
    pcl::PointCloud<pcl::PointXYZL> holes;
    pcl::PointCloud<pcl::PointNormal> normals;
    for (std::uint32_t i = 0; i < width * 2; ++i) {
      pcl::PointXYZRGBL point;
      point.getVector3fMap() =
          Eigen::Vector3f (unit (random), unit (random), unit (random));
      point.rgba = static_cast<std::uint32_t> (random());
      point.label = static_cast<std::uint32_t> (random() % 50);
      if (i % 13 == 5)
        point.x = std::numeric_limits<float>::quiet_NaN();
      labelled.push_back (point);
      pcl::PointXYZL hole;
      hole.getVector3fMap() = point.getVector3fMap();
      hole.label = point.label;
      holes.push_back (hole);
      pcl::PointNormal normal;
      normal.getVector3fMap() = point.getVector3fMap();
      normal.getNormalVector3fMap() = Eigen::Vector3f (0.0f, 0.6f, 0.8f);
      normal.curvature = unit (random);
      normals.push_back (normal);
    }
    labelled.width = holes.width = normals.width = width; // organized: 2 rows
    labelled.height = holes.height = normals.height = 2;
    labelled.is_dense = holes.is_dense = normals.is_dense = false;
    labelled.sensor_origin_ = Eigen::Vector4f (0.5f, -1.25f, 2.0f, 0.0f);
    labelled.sensor_orientation_ = Eigen::Quaternionf (0.5f, 0.5f, -0.5f, 0.5f);
    expectWrittenAsPCLWrites (labelled);
    expectWrittenAsPCLWrites (holes);
    expectWrittenAsPCLWrites (normals);
  }
}

TEST (PCDData, RefusesASCIIValuesOutsideTheirType)
{
  using pcl::tda::test::pcdHeader;
  const std::string floats = pcdHeader ("x y z", "4 4 4", "F F F", 1, "ascii");
  const std::string integers = pcdHeader ("x y z", "4 4 1", "F F U", 2, "ascii");
  EXPECT_EQ (refusal (integers + "1 2 3\n4 5 255\n"), "");
  EXPECT_EQ (refusal (floats + "1e-50 nan -inf\n"), ""); // a float: 0, nan, -inf
  const std::vector<std::pair<std::string, std::string>> refused{
      {floats + "1 1e39 3\n", "point 1 of the ASCII data has '1e39' for field 'y'"},
      {integers + "1 2 3\n4 5 256\n",
       "point 2 of the ASCII data has '256' for field 'z'"},
      {integers + "1 2 -1\n4 5 6\n", "has '-1' for field 'z'"},
      {integers + "1 2 1.5\n4 5 6\n", "has '1.5' for field 'z'"},
      {integers + "1 2 nan\n4 5 6\n", "has 'nan' for field 'z'"},
  };
  for (const auto& [content, message] : refused)
    EXPECT_NE (refusal (content).find (message), std::string::npos)
        << content << "\nrefusal: " << refusal (content);
  // 64-bit integers beyond a double's 53 bits are read exactly (PCL's reader rounds
  // them, or reads 2^64 - 1 as 0).
  const std::string path = temporaryPath ("wide.pcd");
  pcl::tda::test::writeFile (
      path,
      pcdHeader ("x y z a b", "4 4 4 8 8", "F F F I U", 1, "ascii") +
          "0 0 0 -9223372036854775807 18446744073709551615\n");
  const pcl::PCLPointCloud2 cloud = readOurs (path);
  std::int64_t a;
  std::uint64_t b;
  std::memcpy (&a, &cloud.data[12], sizeof (a));
  std::memcpy (&b, &cloud.data[20], sizeof (b));
  EXPECT_EQ (a, -9223372036854775807LL);
  EXPECT_EQ (b, 18446744073709551615ULL);
}

// Every ASCII float and double is the value strtof and strtod read (the correctly
// rounded one): random decimals of 1 to 20 digits and exponents from -50 to 15, with
// the spellings the fast reader leaves to them (a leading '+', hexadecimal, out of
// range: underflow to 0) and signed nan and inf.
TEST (PCDData, ASCIIValuesAreThoseOfStrtofAndStrtod)
{
  std::mt19937 random (43);
  std::uniform_int_distribution<int> digit (0, 9), digits (1, 20), exponent (-50, 15);
  std::vector<std::string> words{
      "+1.5", "0x1p1", "-0x1.8p-3", "1e-50", "-1e-320", "nan", "-nan", "inf", "-inf"};
  while (words.size() < 3000) {
    std::string word = random() % 2 ? "-" : "";
    const int length = digits (random), point = static_cast<int> (random() % 22);
    for (int i = 0; i < length; ++i)
      word += (i == point ? "." : "") + std::to_string (digit (random));
    if (random() % 2)
      word += "e" + std::to_string (exponent (random));
    words.push_back (word);
  }
  std::string lines;
  for (const std::string& word : words)
    lines += "0 0 " + word + " " + word + "\n";
  const std::string path = temporaryPath ("decimals.pcd");
  pcl::tda::test::writeFile (
      path,
      pcl::tda::test::pcdHeader (
          "x y z d", "4 4 4 8", "F F F F", words.size(), "ascii") +
          lines);
  const pcl::PCLPointCloud2 cloud = readOurs (path);
  ASSERT_EQ (cloud.width, words.size());
  for (std::size_t i = 0; i < words.size(); ++i) {
    float as_float;
    double as_double;
    std::memcpy (&as_float, &cloud.data[i * cloud.point_step + 8], sizeof (as_float));
    std::memcpy (
        &as_double, &cloud.data[i * cloud.point_step + 12], sizeof (as_double));
    const float expected_float = std::strtof (words[i].c_str(), nullptr);
    const double expected_double = std::strtod (words[i].c_str(), nullptr);
    EXPECT_EQ (std::memcmp (&as_float, &expected_float, sizeof (as_float)), 0)
        << words[i] << ": " << as_float << " vs " << expected_float;
    EXPECT_EQ (std::memcmp (&as_double, &expected_double, sizeof (as_double)), 0)
        << words[i] << ": " << as_double << " vs " << expected_double;
  }
}

TEST (PCDData, DecompressesWhatPCLsCompressorWrites)
{
  std::mt19937_64 random (3);
  for (int trial = 0; trial < 200; ++trial) {
    // Runs of repeats (back references, overlapping ones) between random bytes.
    std::vector<std::uint8_t> original;
    const std::size_t size = 1 + random() % 5000;
    while (original.size() < size) {
      if (random() % 2 == 0 || original.empty())
        original.push_back (static_cast<std::uint8_t> (random() % 4));
      else {
        const std::size_t distance =
            1 + random() % std::min<std::size_t> (original.size(), 9000);
        const std::size_t length = 1 + random() % 300;
        for (std::size_t i = 0; i < length; ++i)
          original.push_back (original[original.size() - distance]);
      }
    }
    original.resize (size);
    std::vector<char> compressed (size * 2 + 16);
    const unsigned packed =
        pcl::lzfCompress (original.data(),
                          static_cast<unsigned> (size),
                          compressed.data(),
                          static_cast<unsigned> (compressed.size()));
    ASSERT_GT (packed, 0u) << trial;
    std::vector<std::uint8_t> decompressed (size);
    const auto* in = reinterpret_cast<const std::uint8_t*> (compressed.data());
    ASSERT_TRUE (lzfDecompress (in, packed, decompressed.data(), size)) << trial;
    EXPECT_EQ (decompressed, original) << trial;
    // One byte more or less than the data decompresses to is refused.
    std::vector<std::uint8_t> other (size + 1);
    EXPECT_FALSE (lzfDecompress (in, packed, other.data(), size + 1)) << trial;
    EXPECT_FALSE (lzfDecompress (in, packed, other.data(), size - 1)) << trial;
  }
}

TEST (PCDData, RefusesCorruptLZFData)
{
  std::vector<std::uint8_t> out (16);
  // A literal run of 3 bytes, then "copy 4 bytes from 2 back": abcbcbc.
  const std::vector<std::uint8_t> good{2, 'a', 'b', 'c', (2 << 5) | 0, 1};
  ASSERT_TRUE (lzfDecompress (good.data(), good.size(), out.data(), 7));
  EXPECT_EQ (std::string (out.begin(), out.begin() + 7), "abcbcbc");
  const std::vector<std::vector<std::uint8_t>> corrupt{
      {5, 'a', 'b'},                       // the literal run goes past the input
      {2, 'a', 'b', 'c', (2 << 5)},        // the back reference has no distance byte
      {2, 'a', 'b', 'c', (2 << 5) | 0, 3}, // it reaches before the output
      {(7 << 5)},                          // a long back reference with no length byte
  };
  for (const auto& data : corrupt)
    EXPECT_FALSE (lzfDecompress (data.data(), data.size(), out.data(), 7));
}
