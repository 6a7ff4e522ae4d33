#include <pcl/impl/instantiate.hpp>
#include <pcl/tda/common/point_types.h>
#include <pcl/tda/features/stpp_estimation.h>
#include <pcl/point_types.h>

#ifndef PCL_NO_PRECOMPILE
#include <pcl/tda/features/impl/stpp_estimation.hpp>

PCL_INSTANTIATE_PRODUCT (STPPEstimation,
                         (PCL_TDA_XYZ_POINT_TYPES)((pcl::tda::STPPSignature)))
#endif // PCL_NO_PRECOMPILE
