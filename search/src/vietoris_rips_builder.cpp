#include <pcl/impl/instantiate.hpp>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#ifndef PCL_NO_PRECOMPILE
#include <pcl/tda/search/impl/vietoris_rips_builder.hpp>

PCL_INSTANTIATE (
    VietorisRipsBuilder,
    (pcl::PointXYZ) (pcl::PointXYZI) (pcl::PointXYZRGB) (pcl::PointXYZRGBA) (
        pcl::PointNormal) (pcl::PointXYZRGBNormal) (pcl::PointXYZRGBL))
#endif // PCL_NO_PRECOMPILE
