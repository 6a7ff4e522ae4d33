#pragma once

#include <pcl/types.h>

#include <cstddef>
#include <string>

namespace pcl {
namespace tda {

/** \brief Whether every index of \a indices names a point of a cloud of \a cloud_size
 * points, and none twice. Otherwise false, after a PCL_ERROR "[pcl::tda::<where>] ..."
 * (\a where: the class and its method, "Class::compute") naming the first index that
 * is negative,
 * past the end of the cloud or repeated. PCL's classes take indices on trust (an index
 * past the end reads past the cloud, a repeated one counts its point twice); the
 * classes of this library check them when they run, and refuse. Linear in the sizes.
 */
bool
indicesAreValid (const std::string& where,
                 std::size_t cloud_size,
                 const pcl::Indices& indices);

} // namespace tda
} // namespace pcl
