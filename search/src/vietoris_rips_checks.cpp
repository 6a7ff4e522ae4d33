#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/system_memory.h>
#include <pcl/tda/search/vietoris_rips_checks.h>

#include <cmath>

namespace pcl {
namespace tda {

MemoryBudget
vietorisRipsMemoryBudget (std::size_t limit, int max_dimension)
{
  return {limit,
          VIETORIS_RIPS_BYTES_PER_EDGE,
          max_dimension == 2 ? VIETORIS_RIPS_BYTES_PER_TRIANGLE : 0};
}

bool
checkVietorisRipsSettings (const std::string& class_name,
                           double radius,
                           int max_dimension)
{
  if (!(radius > 0.0) || !std::isfinite (radius)) {
    PCL_ERROR ("[pcl::tda::%s::compute] The radius must be positive and finite, not "
               "%g.\n",
               class_name.c_str(),
               radius);
    return false;
  }
  if (max_dimension != 1 && max_dimension != 2) {
    PCL_ERROR (
        "[pcl::tda::%s::compute] The maximum dimension must be 1 or 2, not %d.\n",
        class_name.c_str(),
        max_dimension);
    return false;
  }
  return true;
}

bool
complexFitsMemory (const std::string& class_name,
                   double radius,
                   int max_dimension,
                   const MemoryBudget& budget,
                   const ComplexSize& size)
{
  const bool ids_fit = size.edges < INVALID_SIMPLEX && size.triangles < INVALID_SIMPLEX;
  if (budget.fits (size.edges, size.triangles) && ids_fit)
    return true;
  const char* about = size.exact ? "" : "about ";
  std::string sizes = about + std::to_string (std::llround (size.edges)) + " edges";
  if (max_dimension == 2 && size.triangles > 0.0)
    sizes += std::string (" and ") + about +
             std::to_string (std::llround (size.triangles)) + " triangles";
  if (!size.exact)
    sizes += " (estimated from a sample)";
  if (!budget.fits (size.edges, size.triangles))
    PCL_ERROR ("[pcl::tda::%s::compute] The complex of radius %g would have %s, "
               "%s%s, over the memory limit of %s. Use a smaller radius, a voxel grid, "
               "or a larger limit (setMemoryLimit()).\n",
               class_name.c_str(),
               radius,
               sizes.c_str(),
               about,
               formatBytes (budget.bytes (size.edges, size.triangles)).c_str(),
               formatBytes (static_cast<double> (budget.limit)).c_str());
  else
    PCL_ERROR ("[pcl::tda::%s::compute] The complex of radius %g would have %s: more "
               "than 2^32 - 1 simplices of one dimension. Use a smaller radius or a "
               "voxel grid.\n",
               class_name.c_str(),
               radius,
               sizes.c_str());
  return false;
}

} // namespace tda
} // namespace pcl
