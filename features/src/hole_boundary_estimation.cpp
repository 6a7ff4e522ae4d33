#include <pcl/impl/instantiate.hpp>
#include <pcl/tda/common/point_types.h>
#include <pcl/tda/features/hole_boundary_estimation.h>
#include <pcl/point_types.h>

#ifndef PCL_NO_PRECOMPILE
#include <pcl/tda/features/impl/hole_boundary_estimation.hpp>

PCL_INSTANTIATE_PRODUCT (HoleBoundaryEstimation,
                         (PCL_TDA_XYZ_POINT_TYPES)((pcl::Boundary)))
#endif // PCL_NO_PRECOMPILE
