#include <pcl/impl/instantiate.hpp>
#include <pcl/tda/segmentation/persistent_region_growing_rgb.h>
#include <pcl/point_types.h>

#ifndef PCL_NO_PRECOMPILE
#include <pcl/tda/segmentation/impl/persistent_region_growing_rgb.hpp>

// The coloured point types, with pcl::Normal or pcl::PointNormal normals.
PCL_INSTANTIATE_PRODUCT (
    PersistentRegionGrowingRGB,
    ((pcl::PointXYZRGB) (pcl::PointXYZRGBA) (pcl::PointXYZRGBNormal) (
        pcl::PointXYZRGBL)) ((pcl::Normal) (pcl::PointNormal) (pcl::PointXYZRGBNormal)))
#endif // PCL_NO_PRECOMPILE
