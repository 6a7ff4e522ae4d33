#pragma once

/** \brief The point types every PCL-TDA class template is compiled for (with
 * PCL_INSTANTIATE); other types work header-only with PCL_NO_PRECOMPILE. One list,
 * so that every module offers the same types. */
#define PCL_TDA_XYZ_POINT_TYPES                                                        \
  (pcl::PointXYZ) (pcl::PointXYZI) (pcl::PointXYZRGB) (pcl::PointXYZRGBA) (            \
      pcl::PointNormal) (pcl::PointXYZRGBNormal) (pcl::PointXYZRGBL)
