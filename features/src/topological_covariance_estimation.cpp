#include <pcl/impl/instantiate.hpp>
#include <pcl/tda/common/point_types.h>
#include <pcl/tda/features/topological_covariance_estimation.h>
#include <pcl/point_types.h>

#ifndef PCL_NO_PRECOMPILE
#include <pcl/tda/features/impl/topological_covariance_estimation.hpp>

PCL_INSTANTIATE_PRODUCT (TopologicalCovarianceEstimation,
                         (PCL_TDA_XYZ_POINT_TYPES)((pcl::Normal) (pcl::PointNormal) (
                             pcl::PointXYZRGBNormal)) ((pcl::tda::CovarianceSignature)))
#endif // PCL_NO_PRECOMPILE
