#pragma once

#include <pcl/tda/apps/pcd_file_check.h>
#include <pcl/PCLPointCloud2.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <istream>
#include <ostream>

namespace pcl {
namespace tda {

/** \brief Reads the points of the PCD file held by \a file, whose header
 * readPCDLayout() has checked into \a layout, without PCL's io library (which loads
 * VTK and makes a tool take 20 ms more to start).
 *
 * Binary data is read as it is; binary_compressed data is decompressed (LZF) and put
 * back from one field after the other to one point after the other, as PCL's writer
 * stores it; ASCII values are read as strtod reads them (nan and inf included) and
 * converted to their field's type: floats rounded, integers only when they are whole
 * and in the type's range. \a cloud gets the layout's fields, width and height, the
 * data, and is_dense when no floating-point value is NaN or infinite.
 * \throws pcl::IOException saying which point and value is wrong, or that the
 * compressed data is corrupt */
void
readPCDData (std::istream& file, const PCDLayout& layout, pcl::PCLPointCloud2& cloud);

/** \brief Writes \a cloud to \a out as a binary PCD file, as PCL's binary writer of
 * point types does, without PCL's io library: the named fields packed one after the
 * other (the padding of the point type left out), the viewpoint \a origin and
 * \a orientation.
 * \return whether the whole file was written */
bool
writePCDBinary (std::ostream& out,
                const pcl::PCLPointCloud2& cloud,
                const Eigen::Vector4f& origin,
                const Eigen::Quaternionf& orientation);

/** \brief Decompresses the \a size bytes of LZF data at \a in into exactly
 * \a out_size bytes at \a out.
 * \return false when the data is corrupt or does not decompress to \a out_size bytes */
bool
lzfDecompress (const std::uint8_t* in,
               std::size_t size,
               std::uint8_t* out,
               std::size_t out_size);

} // namespace tda
} // namespace pcl
