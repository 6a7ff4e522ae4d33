#include <pcl/impl/instantiate.hpp>
#include <pcl/tda/common/point_types.h>
#include <pcl/tda/surface/hole_filling.h>
#include <pcl/point_types.h>

#ifndef PCL_NO_PRECOMPILE
#include <pcl/tda/surface/impl/hole_filling.hpp>

// The point types of the library, and labelled points (a filled labelled cloud
// keeps its labels: a new point takes its nearest rim point's).
PCL_INSTANTIATE (HoleFilling, PCL_TDA_XYZ_POINT_TYPES (pcl::PointXYZL))
#endif // PCL_NO_PRECOMPILE
