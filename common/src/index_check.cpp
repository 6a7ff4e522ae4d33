#include <pcl/console/print.h>
#include <pcl/tda/common/index_check.h>

#include <vector>

namespace pcl {
namespace tda {

bool
indicesAreValid (const std::string& where,
                 std::size_t cloud_size,
                 const pcl::Indices& indices)
{
  std::vector<bool> seen (cloud_size, false);
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const pcl::index_t index = indices[i];
    if (index < 0 || static_cast<std::size_t> (index) >= cloud_size) {
      PCL_ERROR ("[pcl::tda::%s] Index %lld (at position %zu of the indices) "
                 "is not a point of the input cloud of %zu points.\n",
                 where.c_str(),
                 static_cast<long long> (index),
                 i,
                 cloud_size);
      return false;
    }
    if (seen[index]) {
      PCL_ERROR ("[pcl::tda::%s] Index %lld appears twice in the indices (at "
                 "position %zu again): each point may be indexed once.\n",
                 where.c_str(),
                 static_cast<long long> (index),
                 i);
      return false;
    }
    seen[index] = true;
  }
  return true;
}

} // namespace tda
} // namespace pcl
