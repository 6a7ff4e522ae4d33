#pragma once

#include <pcl/PCLPointCloud2.h>

#include <cstdint>
#include <istream>

namespace pcl {
namespace tda {

/** \brief How the points of a PCD file are stored after its header. */
enum class PCDData { ASCII, BINARY, BINARY_COMPRESSED };

/** \brief The layout of a PCD file, read from its header and checked against the
 * file's size. */
struct PCDLayout {
  /** \brief The fields (names, offsets, types, counts), width, height, point_step
   * and row_step; no data. */
  pcl::PCLPointCloud2 header;
  /** \brief The storage of the points. */
  PCDData data = PCDData::ASCII;
  /** \brief The number of bytes before the points. */
  std::uint64_t data_offset = 0;
  /** \brief binary_compressed only: the bytes of LZF data after the two sizes at
   * data_offset. */
  std::uint64_t compressed_size = 0;
};

/** \brief At most this many points in a PCD file: PCL's index type is 32-bit. */
constexpr std::uint64_t MAX_PCD_POINTS = 2147483647;

/** \brief At most this many bytes of points (width x height x point size): PCL's
 * reader counts them in 32 bits. */
constexpr std::uint64_t MAX_PCD_DATA_BYTES = 4294967295;

/** \brief Reads the header of the PCD file held by \a file, of \a file_size bytes,
 * and checks it strictly before any reader allocates for its points: the lines in
 * PCD v0.7 order (VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, VIEWPOINT,
 * POINTS, DATA; comments anywhere), each at most once, with whole numbers; sizes
 * and types PCL knows; counts of at least 1; WIDTH x HEIGHT = POINTS (a missing
 * WIDTH is POINTS, a missing HEIGHT 1, as PCL reads old files); no line after DATA
 * that PCL's reader would take for the header; and the data against the size of the
 * file: binary data WIDTH x HEIGHT points (then only zeros, the padding of PCL's
 * writer), compressed data at least the
 * compressed size its first 4 bytes give, decompressing to exactly that many points
 * (and at most what LZF can expand it to), ASCII data one line of numbers per point
 * with as many numbers as the fields have values. Leaves \a file at an unspecified
 * position.
 * \throws pcl::IOException saying what is wrong with the file */
PCDLayout
readPCDLayout (std::istream& file, std::uint64_t file_size);

} // namespace tda
} // namespace pcl
